/*
 * lookalike_main.c - `lookalike FILE...`: after make render failed to
 * compile a stage file, names what in it is not C's though it looks so
 * (lookalike.h), or says that it is saved as UTF-16.  It only advises: its
 * exit status is 0 unless it was called wrongly (2).
 */
#include "build.h"
#include "lookalike.h"
#include "kit/savefile.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: lookalike FILE...\n");
        return 2;
    }
    for (int k = 1; k < argc; k++) {
        size_t n = 0;
        char *text = kit_load_file(argv[k], BUILD_SOURCE_MAX, &n);
        if (!text)
            continue;                   /* the compiler has said why */
        char lines[1200];
        if (lookalike_utf16(text, n))
            fprintf(stderr, "%s " LOOKALIKE_UTF16 "\n", argv[k]);
        else if (lookalike_explain(text, n, argv[k], lines, sizeof lines) > 0)
            fprintf(stderr, LOOKALIKE_INTRO "\n%s", lines);
        free(text);
    }
    return 0;
}
