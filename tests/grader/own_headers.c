/*
 * own_headers.c - headers the grader's build will not have (own_headers.h).
 */
#define _XOPEN_SOURCE 700        /* PATH_MAX, stat */
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "own_headers.h"
#include "include_scan.h"

#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

enum { SHOWN = 3 };

typedef struct {
    const char *const *dirs;
    int ndirs;
    int found;
    char names[SHOWN][256];
} Finder;

/* Whether name is a regular file in dir. */
static bool file_in(const char *dir, const char *name)
{
    char path[PATH_MAX];
    struct stat st;
    if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path)
        return false;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* The scan's judge: notes a name found in one of the folders, and never
 * refuses (the grader's own scan refuses what must not be compiled). */
static const char *note_own(const char *name, void *ctx)
{
    Finder *f = ctx;
    if (name[0] == '/' || !strcmp(name, "raytracer.h") || !strcmp(name, "vec3.h") || strlen(name) >= 256)
        return NULL;
    for (int k = 0; k < f->found && k < SHOWN; k++)
        if (!strcmp(f->names[k], name))
            return NULL;                /* named twice: said once */
    for (int d = 0; d < f->ndirs; d++)
        if (file_in(f->dirs[d], name)) {
            if (f->found < SHOWN)
                snprintf(f->names[f->found], sizeof f->names[0], "%s", name);
            f->found++;
            return NULL;
        }
    return NULL;
}

/* The line of the first directive that names name ("name" or <name>), or 0. */
static int line_of(const char *text, size_t len, const char *name)
{
    size_t m = strlen(name);
    int line = 1;
    bool directive = false, start = true;
    for (size_t k = 0; k < len; k++) {
        char c = text[k];
        if (c == '\n') {
            line++;
            start = true;
            directive = false;
            continue;
        }
        if (start && c == '#')
            directive = true;
        if (c != ' ' && c != '\t')
            start = false;
        if (directive && (c == '"' || c == '<') && k + m + 1 < len && !memcmp(text + k + 1, name, m) &&
            text[k + m + 1] == (c == '"' ? '"' : '>'))
            return line;
    }
    return 0;
}

int own_headers_explain(const char *text, size_t len, const char *const *dirs, int ndirs,
                        const char *file, char *out, size_t outlen)
{
    Finder f = { dirs, ndirs, 0, { { 0 } } };
    char why[400];
    out[0] = '\0';
    include_scan_judged(text, len, ndirs > 0 ? dirs[0] : ".", note_own, &f, why, sizeof why);
    if (f.found == 0)
        return 0;
    size_t o = 0;
    for (int k = 0; k < f.found && k < SHOWN && o < outlen; k++) {
        int line = line_of(text, len, f.names[k]);
        char where[32] = "";
        if (line > 0)
            snprintf(where, sizeof where, "%d:", line);
        int w = snprintf(out + o, outlen - o, "%s:%s #include \"%s\": the grader will not have %s\n", file,
                         where, f.names[k], f.names[k]);
        o += w > 0 ? (size_t)w : 0;
    }
    if (f.found > SHOWN && o < outlen) {
        int w = snprintf(out + o, outlen - o, "(and %d more such headers)\n", f.found - SHOWN);
        o += w > 0 ? (size_t)w : 0;
    }
    bool one = f.found == 1;
    if (o < outlen)
        snprintf(out + o, outlen - o,
                 "The grader builds each stage file alone, with only raytracer.h, vec3.h and the "
                 "system's headers beside it: put what %s %s into %s itself (make %s functions "
                 "static), and into each other stage file that uses %s.\n",
                 one ? f.names[0] : "those headers", one ? "holds" : "hold", file, one ? "its" : "their",
                 one ? "it" : "them");
    return f.found;
}
