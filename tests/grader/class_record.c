/*
 * class_record.c - a submission's record for the class page: what its
 * grading found, written by the grading child (class_record_write) and
 * read back by grade --all (class_record_read).  One item a line:
 *
 *     rtclass 1
 *     error TEXT                       the grading stopped without a grade: why
 *     part P BUILT REFUSED RANOUT      each graded part (P: "1" ... "5")
 *     why P TEXT                       a part that did not build: what the build said
 *     cause P KEY TEXT                 each cause the diagnosis named, its sentence
 *     fail K RAN C N G1 ... GN         each failed test: its index, whether it ran,
 *                                      the case its figure shows (-1: none) and
 *                                      the N numbers answered there (%a)
 *     end
 *
 * TEXT runs to the end of the line, with "\" written "\\" and a line
 * break "\n".  A record without its "end" line is not whole.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "report.h"
#include "kit/savefile.h"

#include <stdlib.h>
#include <string.h>

#define RECORD_MAX (64u << 20)

static void put_text(FILE *f, const char *s)
{
    for (; s && *s; s++) {
        if (*s == '\\')
            fputs("\\\\", f);
        else if (*s == '\n')
            fputs("\\n", f);
        else
            fputc(*s, f);
    }
    fputc('\n', f);
}

/* The first "- " line of text at or after s, or NULL. */
static const char *next_item(const char *s)
{
    while (s && *s && strncmp(s, "- ", 2) != 0)
        s = strchr(s, '\n') ? strchr(s, '\n') + 1 : NULL;
    return s && *s ? s : NULL;
}

/* Part p's causes: the i-th key of g->causes[p] with the i-th "- " line
 * of its diagnosis, the sentence the student read: the core failures'
 * causes first, then those of the hard cases alone (diagnose.h). */
static void put_causes(FILE *f, const Grade *g, int p)
{
    const char *keys = g->causes[p];
    const char *core = next_item(g->diagnosis[p]), *hard = next_item(g->diagnosis_hard[p]);
    while (keys && *keys) {
        size_t n = strcspn(keys, " ");
        const char **at = core ? &core : &hard;
        const char *line = *at ? *at + 2 : "";
        size_t len = strcspn(line, "\n");
        fprintf(f, "cause %s %.*s %.*s\n", part_label(p), (int)n, keys, (int)len, line);
        if (*at)
            *at = next_item(line + len);
        keys += n;
        keys += *keys == ' ';
    }
}

static void put_part(FILE *f, const Grade *g, int p, double timeout)
{
    int ranout = 0;
    for (int k = 0; k < g->tests->n; k++) {
        const TestResult *r = &g->results[k];
        ranout += g->tests->tests[k].part == p && r->ran && !r->passed && r->seconds >= timeout;
    }
    fprintf(f, "part %s %d %d %d\n", part_label(p), g->built[p], g->build_refused[p], ranout);
    if (!g->built[p]) {
        fprintf(f, "why %s ", part_label(p));
        put_text(f, g->build_messages[p] ? g->build_messages[p] : "");
    }
    put_causes(f, g, p);
}

int class_record_write(const char *path, const Grade *g, double timeout, char *err, size_t errlen)
{
    SaveStream out;
    FILE *f = save_open(&out, path, err, errlen);
    if (!f)
        return -1;
    fprintf(f, "rtclass 1\n");
    for (int p = 0; p < NPARTS; p++)
        if (g->graded[p])
            put_part(f, g, p, timeout);
    for (int k = 0; k < g->tests->n; k++) {
        const Test *t = &g->tests->tests[k];
        const TestResult *r = &g->results[k];
        if (!g->graded[t->part] || r->passed)
            continue;
        const double *got = NULL;
        int c = report_figure_case(t, r, &got);
        int n = got ? kind_nout(t->kind) : 0;
        fprintf(f, "fail %d %d %d %d", k, r->ran, c, n);
        for (int q = 0; q < n; q++)
            fprintf(f, " %a", got[q]);
        fputc('\n', f);
    }
    fprintf(f, "end\n");
    return save_close(&out, path, 0666, err, errlen);
}

void class_record_write_error(const char *path, const char *msg)
{
    SaveStream out;
    char err[PATH_MAX + 128];
    FILE *f = save_open(&out, path, err, sizeof err);
    if (!f)
        return;                     /* the class page says the status alone */
    fprintf(f, "rtclass 1\nerror ");
    put_text(f, msg);
    fprintf(f, "end\n");
    save_close(&out, path, 0666, err, sizeof err);
}

/* ---- reading it back ------------------------------------------------------ */

/* The text at s, to the end of its line, unescaped: a fresh string. */
static char *get_text(const char *s)
{
    size_t n = strcspn(s, "\n");
    char *out = malloc(n + 1), *o = out;
    if (!out)
        return NULL;
    for (size_t k = 0; k < n; k++) {
        if (s[k] == '\\' && k + 1 < n) {
            k++;
            *o++ = s[k] == 'n' ? '\n' : s[k];
        } else {
            *o++ = s[k];
        }
    }
    *o = '\0';
    return out;
}

static bool read_fail(ClassSub *s, const char *line)
{
    ClassFail fl = { 0 };
    int ran = 0, used = 0;
    if (sscanf(line, "%d %d %d %d%n", &fl.test, &ran, &fl.c, &fl.nout, &used) != 4 || fl.test < 0 ||
        fl.nout < 0 || fl.nout > CASE_MAX_OUT)
        return false;
    fl.ran = ran;
    line += used;
    for (int q = 0; q < fl.nout; q++) {
        char *end;
        fl.got[q] = strtod(line, &end);
        if (end == line)
            return false;
        line = end;
    }
    ClassFail *grown = realloc(s->fails, (size_t)(s->nfails + 1) * sizeof *grown);
    if (!grown)
        return false;
    s->fails = grown;
    s->fails[s->nfails++] = fl;
    return true;
}

static bool read_cause(ClassPart *cp, const char *line)
{
    size_t n = strcspn(line, " \n");
    if (n == 0 || n >= sizeof cp->causes->key)
        return false;
    ClassCause *grown = realloc(cp->causes, (size_t)(cp->ncauses + 1) * sizeof *grown);
    if (!grown)
        return false;
    cp->causes = grown;
    ClassCause *c = &cp->causes[cp->ncauses];
    memcpy(c->key, line, n);
    c->key[n] = '\0';
    c->text = get_text(line + n + (line[n] == ' '));
    if (!c->text)
        return false;
    cp->ncauses++;
    return true;
}

/* One line of the record; false when it is not one the format has. */
static bool read_line(ClassSub *s, const char *line)
{
    char label[8];
    int b, r, t, at = 0;
    if (strncmp(line, "fail ", 5) == 0)
        return read_fail(s, line + 5);
    if (strncmp(line, "error ", 6) == 0 && !s->error)
        return (s->error = get_text(line + 6)) != NULL;
    /* The others name a part: "WORD P REST". */
    int p = sscanf(line, "%*[a-z] %7[^ \n]%n", label, &at) == 1 ? part_from_label(label) : -1;
    if (p < 0)
        return false;
    const char *rest = line + at + (line[at] == ' ');
    ClassPart *cp = &s->part[p];
    if (strncmp(line, "part ", 5) == 0 && !cp->graded &&
        sscanf(rest, "%d %d %d", &b, &r, &t) == 3) {
        *cp = (ClassPart){ .graded = true, .built = b, .refused = r, .ranout = t };
        return true;
    }
    if (strncmp(line, "why ", 4) == 0 && !cp->why)
        return (cp->why = get_text(rest)) != NULL;
    if (strncmp(line, "cause ", 6) == 0)
        return read_cause(cp, rest);
    return false;
}

bool class_record_read(const char *path, ClassSub *s)
{
    size_t len = 0;
    char *text = kit_load_file(path, RECORD_MAX, &len);
    if (!text || strncmp(text, "rtclass 1\n", 10) != 0) {
        free(text);
        return false;
    }
    bool whole = false;
    for (const char *line = text + 10; *line && !whole;) {
        if (strncmp(line, "end\n", 4) == 0)
            whole = true;
        else if (!read_line(s, line))
            break;
        const char *nl = strchr(line, '\n');
        line = nl ? nl + 1 : line + strlen(line);
    }
    free(text);
    return whole;
}

void class_sub_free(ClassSub *s)
{
    for (int p = 0; p < NPARTS; p++) {
        for (int c = 0; c < s->part[p].ncauses; c++)
            free(s->part[p].causes[c].text);
        free(s->part[p].causes);
        free(s->part[p].why);
    }
    free(s->fails);
    free(s->error);
    free(s->name);
    memset(s, 0, sizeof *s);
}
