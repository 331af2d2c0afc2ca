/*
 * linkcheck_main.c - `linkcheck LOG FILE...`: after make render failed to
 * link the stage files FILE... into the renderer, says in the lab's words
 * what the linker's message LOG means, where the files confirm it:
 *
 *   - a function defined in two stage files: make render links them into
 *     one program, where a function is defined once (the grader builds each
 *     file alone and does not mind).  A helper: make each one static.  A
 *     function of the contract: it belongs in its own stage file only.
 *   - a function defined in one stage file, which the linker says is
 *     defined twice: the kit's renderer has a function of that name.
 *   - a function of the contract that its stage file does not define (a
 *     name changed, or a typo).
 *   - a helper called in one stage file and defined in another, out of the
 *     caller's reach (static, most likely).
 *
 * It only advises: the linker's own message stays above.  Exit status 0
 * unless it was called wrongly (2).
 */
#include "build.h"
#include "linkmsg.h"
#include "kit/savefile.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_FILES = 16, MAX_NAMES = 4 };

/* Whether path is the stage file named stage (its last component is
 * stage followed by ".c"). */
static int is_stage(const char *path, const char *stage)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t n = strlen(stage);
    return strncmp(base, stage, n) == 0 && strcmp(base + n, ".c") == 0;
}

/* The files of files[0 .. n-1] whose text defines name, as "a and b" (or
 * "a, b and c") in out; returns how many. */
static int definers(char *const *texts, char *const *files, int n, const char *name, int *which,
                    char *out, size_t outlen)
{
    int count = 0;
    out[0] = '\0';
    for (int k = 0; k < n; k++)
        if (texts[k] && linkmsg_defines(texts[k], name))
            which[count++] = k;
    for (int k = 0; k < count; k++) {
        size_t used = strlen(out);
        snprintf(out + used, outlen - used, "%s%s", k == 0 ? "" : k == count - 1 ? " and " : ", ",
                 files[which[k]]);
    }
    return count;
}

static void explain_duplicate(char *const *texts, char *const *files, int n, const char *name)
{
    int which[MAX_FILES];
    char list[2048];
    int count = definers(texts, files, n, name, which, list, sizeof list);
    const char *stage = linkmsg_stage_of(name);
    if (count >= 2 && stage) {
        char others[2048] = "";
        for (int k = 0, m = 0; k < count; k++) {
            if (is_stage(files[which[k]], stage))
                continue;
            size_t used = strlen(others);
            snprintf(others + used, sizeof others - used, "%s%s", m++ ? " and " : "", files[which[k]]);
        }
        fprintf(stderr, "make render: %s is defined in %s.\n"
                        "  It belongs in %s.c only (labs/raytracer.h): remove it from %s.\n",
                name, list, stage, others);
    } else if (count >= 2) {
        fprintf(stderr, "make render: %s is defined in %s.\n"
                        "  make render links your stage files into one program, where a function may\n"
                        "  be defined only once; the grader builds each file alone and does not see\n"
                        "  this. Keep each a helper of its own file: write static in front of each\n"
                        "  definition of %s.\n", name, list, name);
    } else if (count == 1 && !stage) {
        fprintf(stderr, "make render: %s, in %s,\n"
                        "  has the name of a function of the kit's renderer. Write static in front\n"
                        "  of its definition, so that it stays a helper of that file, or give it\n"
                        "  another name.\n", name, list);
    }
}

static void explain_undefined(char *const *texts, char *const *files, int n, const char *name)
{
    int which[MAX_FILES];
    char list[2048];
    int count = definers(texts, files, n, name, which, list, sizeof list);
    const char *stage = linkmsg_stage_of(name);
    if (stage && count == 0) {
        for (int k = 0; k < n; k++)
            if (texts[k] && is_stage(files[k], stage)) {
                char defined[8 * LINKMSG_NAME_MAX + 64];
                linkmsg_definitions_list(texts[k], defined, sizeof defined);
                fprintf(stderr, "make render: %s defines no function %s, which the renderer\n"
                                "  calls by the name labs/raytracer.h declares. The functions it defines: %s.\n",
                        files[k], name, defined);
            }
    } else if (!stage && count >= 1) {
        fprintf(stderr, "make render: %s is defined in %s, and another file calls it, which the\n"
                        "  linker cannot let it do (a static function stays in its own file). Each\n"
                        "  stage file is graded alone: define %s in each file that calls it, static\n"
                        "  in each.\n", name, list, name);
    }
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc - 2 > MAX_FILES) {
        fprintf(stderr, "usage: linkcheck LOG FILE... (at most %d files)\n", MAX_FILES);
        return 2;
    }
    size_t n = 0;
    char *log = kit_load_file(argv[1], BUILD_SOURCE_MAX, &n);
    if (!log)
        return 0;                       /* the linker has said what it could */
    int nfiles = argc - 2;
    char *texts[MAX_FILES];
    for (int k = 0; k < nfiles; k++)
        texts[k] = kit_load_file(argv[k + 2], BUILD_SOURCE_MAX, &n);
    char names[MAX_NAMES][LINKMSG_NAME_MAX];
    int nduplicate = linkmsg_duplicate(log, names, MAX_NAMES);
    for (int k = 0; k < nduplicate; k++)
        explain_duplicate(texts, argv + 2, nfiles, names[k]);
    int nundefined = linkmsg_undefined(log, names, MAX_NAMES);
    for (int k = 0; k < nundefined; k++)
        explain_undefined(texts, argv + 2, nfiles, names[k]);
    for (int k = 0; k < nfiles; k++)
        free(texts[k]);
    free(log);
    return 0;
}
