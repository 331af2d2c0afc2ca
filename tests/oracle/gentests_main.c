/*
 * gentests - writes the public tests, with their expected values and hints,
 * as tests/public/part1.tests ... part5.tests (`make public-tests`).
 * The files are committed and shipped in the student kit, whose grader has
 * no oracle; `make test` checks that they match what this program writes.
 *
 *     gentests DIR
 */
#include "testgen.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: gentests DIR\n");
        return 2;
    }
    TestList all = { 0 };
    testgen_public(&all);
    for (int p = 0; p < NPARTS; p++) {
        TestList one = { 0 };
        for (int k = 0; k < all.n; k++)
            if (all.tests[k].part == p) {
                if (one.n == one.cap) {
                    one.cap = one.cap ? 2 * one.cap : 16;
                    one.tests = realloc(one.tests, (size_t)one.cap * sizeof *one.tests);
                }
                one.tests[one.n++] = all.tests[k];      /* shares the cases */
            }
        char path[4096], err[512], header[512];
        snprintf(path, sizeof path, "%s/part%s.tests", argv[1], part_label(p));
        snprintf(header, sizeof header,
                 "# The public tests of Part %s, with expected values from the oracle\n"
                 "# (double-double), and for Parts 4 and 5 the outputs of known mistakes, for hints.\n"
                 "# Written by `make public-tests` (tests/oracle/gentests_main.c): do not edit.\n",
                 part_label(p));
        if (tests_write(&one, path, header, err, sizeof err) != 0) {
            fprintf(stderr, "gentests: %s\n", err);
            return 1;
        }
        free(one.tests);
    }
    testlist_free(&all);
    return 0;
}
