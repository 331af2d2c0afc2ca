/*
 * stagecheck_main.c - `stagecheck FILE...`: before make render compiles a
 * stage file, refuses one that the grader would not build: one it refuses
 * outright (a device, a path out of the folder: include_scan.h), or one
 * that includes a header the grader's build will not have (own_headers.h).
 * So a render that works is a file the grader can grade.  Exit status 0
 * when every file may be compiled, 1 when one may not (it says why), 2
 * when called wrongly.
 */
#include "build.h"
#include "include_scan.h"
#include "lookalike.h"
#include "own_headers.h"
#include "kit/savefile.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: stagecheck FILE...\n");
        return 2;
    }
    int status = 0;
    for (int k = 1; k < argc; k++) {
        size_t n = 0;
        char *text = kit_load_file(argv[k], BUILD_SOURCE_MAX, &n);
        if (!text || lookalike_utf16(text, n)) {
            free(text);
            continue;                   /* the compiler, then lookalike, say why */
        }
        char dir[1024], why[400], lines[1400];
        const char *slash = strrchr(argv[k], '/');
        if (!slash)
            snprintf(dir, sizeof dir, ".");
        else
            snprintf(dir, sizeof dir, "%.*s", slash == argv[k] ? 1 : (int)(slash - argv[k]), argv[k]);
        const char *dirs[] = { dir, "labs" };
        if (include_scan(text, n, dir, why, sizeof why)) {
            fprintf(stderr, "%s: refused, as the grader refuses it: %s\n", argv[k], why);
            status = 1;
        } else if (own_headers_explain(text, n, dirs, 2, argv[k], lines, sizeof lines) > 0) {
            fputs(lines, stderr);
            status = 1;
        }
        free(text);
    }
    return status;
}
