/*
 * fuzz_public.h - the public tests (the files of tests/public), for the fuzz
 * targets that need a real test to judge or draw (answers, figures).
 * Include after fuzz.h.
 */
#ifndef FUZZ_PUBLIC_H
#define FUZZ_PUBLIC_H

#include "../grader/grader.h"

/* Every part's public tests, read once; the kit's top directory must be
 * the working directory (as `make fuzz` runs them). */
static inline const TestList *fuzz_public_tests(void)
{
    static TestList list;
    if (!list.n) {
        char err[512];
        for (int p = 0; p < NPARTS; p++) {
            char path[64];
            snprintf(path, sizeof path, "tests/public/part%s.tests", part_label(p));
            if (tests_read(&list, path, false, err, sizeof err) != 0) {
                fprintf(stderr, "%s (run from the kit's top directory)\n", err);
                abort();
            }
        }
    }
    return &list;
}

#endif
