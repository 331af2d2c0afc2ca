/*
 * cases.c - tests in memory, and the text format of the test files.
 *
 *     # comment
 *     test 1 plane core 1                  part, kind, group (core|hard), weight
 *                                          (above 0, at most 1e6)
 *     name Part 1: the worked example      the rest of the line
 *     note what the test is about          (optional)
 *     background r g b                     (color and image tests)
 *     sphere cx cy cz R r g b              (color and image tests, repeated)
 *     nx 32                                (image tests: the image's width, 1 to 16384)
 *     triangle ax ay az bx by bz cx cy cz  (mesh tests, repeated)
 *     case IN... | WANT... | TOL... | ALT... | FLAGS   (FLAGS 0, or 1: CASE_EITHER_HIT)
 *     hint OUT... | what the mistake is
 *     end
 *
 * Numbers are written in the shortest decimal form that reads back as the
 * same double, so they survive the round trip exactly.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "grader.h"
#include "decimal.h"
#include "../../labs/kit/numtext.h"
#include "../../labs/kit/savefile.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *kind_names[NKINDS] = { "plane", "pixel", "sphere", "camera", "color", "image",
                                          "planehit", "triangle", "mesh" };
static const int kind_in[NKINDS] = { 3, 7, 10, 6, 6, 3, 12, 15, 6 };
static const int kind_out[NKINDS] = { 2, 3, 2, 6, 3, 3, 2, 2, 2 };

int kind_nin(Kind kind) { return kind_in[kind]; }
int kind_nout(Kind kind) { return kind_out[kind]; }
const char *kind_name(Kind kind) { return kind_names[kind]; }

bool kind_is_hit(Kind kind)
{
    return kind == KIND_SPHERE || kind == KIND_PLANEHIT || kind == KIND_TRIANGLE || kind == KIND_MESH;
}

static const char *labels[NPARTS] = { "1", "2", "3a", "3b", "4", "5" };
static const char *titles[NPARTS] = {
    "Part 1: the image plane's size",
    "Part 2: pixel coordinates",
    "Part 3a: ray/sphere intersection",
    "Part 3b: camera rays and colours",
    "Part 4: ray/plane intersection",
    "Part 5: ray/triangle intersection",
};

const char *part_label(int part) { return labels[part]; }
const char *part_title(int part) { return titles[part]; }

PointsText points_text(double points)
{
    PointsText p;
    if (!(fabs(points) < 1e15)) {           /* not a count of points: as it is */
        snprintf(p.s, sizeof p.s, "%g", points);
        return p;
    }
    snprintf(p.s, sizeof p.s, "%.2f", points);
    size_t n = strlen(p.s);                 /* "%.2f" always writes a point */
    while (p.s[n - 1] == '0')
        p.s[--n] = '\0';
    if (p.s[n - 1] == '.')
        p.s[--n] = '\0';
    if (strcmp(p.s, "-0") == 0)
        snprintf(p.s, sizeof p.s, "0");
    return p;
}

void appendf(char **s, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    size_t old = *s ? strlen(*s) : 0;
    char *t = n >= 0 ? realloc(*s, old + (size_t)n + 1) : NULL;
    if (!t)
        return;
    va_start(ap, fmt);
    vsnprintf(t + old, (size_t)n + 1, fmt, ap);
    va_end(ap);
    *s = t;
}

FILE *save_open(SaveStream *s, const char *path, char *err, size_t errlen)
{
    *s = (SaveStream){ 0 };
    s->f = open_memstream(&s->data, &s->len);
    if (!s->f)
        snprintf(err, errlen, "%s: out of memory", path);
    return s->f;
}

int save_close(SaveStream *s, const char *path, unsigned mode, char *err, size_t errlen)
{
    bool failed = ferror(s->f) != 0;
    failed = fclose(s->f) != 0 || failed;
    int status = -1;
    if (failed)
        snprintf(err, errlen, "%s: out of memory", path);
    else
        status = kit_save_file_mode(path, s->data, s->len, mode, err, errlen);
    free(s->data);
    return status;
}

int part_from_label(const char *label)
{
    for (int p = 0; p < NPARTS; p++)
        if (strcmp(label, labels[p]) == 0)
            return p;
    return -1;
}

static void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n);
    if (!q) {
        fprintf(stderr, "grade: out of memory\n");
        exit(2);
    }
    return q;
}

Test *testlist_add(TestList *list, int part, Kind kind, const char *name)
{
    if (list->n == list->cap) {
        list->cap = list->cap ? 2 * list->cap : 32;
        list->tests = xrealloc(list->tests, (size_t)list->cap * sizeof *list->tests);
    }
    Test *t = &list->tests[list->n++];
    memset(t, 0, sizeof *t);
    t->part = part;
    t->kind = kind;
    t->weight = 1;
    snprintf(t->name, sizeof t->name, "%s", name);
    return t;
}

Case *test_add_case(Test *test)
{
    if (test->ncases == test->cap) {
        test->cap = test->cap ? 2 * test->cap : 16;
        test->cases = xrealloc(test->cases, (size_t)test->cap * sizeof *test->cases);
    }
    Case *c = &test->cases[test->ncases++];
    memset(c, 0, sizeof *c);
    return c;
}

Hint *case_add_hint(Case *c)
{
    c->hints = xrealloc(c->hints, (size_t)(c->nhints + 1) * sizeof *c->hints);
    Hint *h = &c->hints[c->nhints++];
    memset(h, 0, sizeof *h);
    return h;
}

void test_add_sphere(Test *test, const double c[3], double R, const double color[3])
{
    test->spheres = xrealloc(test->spheres, (size_t)(test->nspheres + 1) * sizeof *test->spheres);
    TestSphere *s = &test->spheres[test->nspheres++];
    memcpy(s->c, c, sizeof s->c);
    s->R = R;
    memcpy(s->color, color, sizeof s->color);
}

void test_add_triangle(Test *test, const double v[9])
{
    test->triangles = xrealloc(test->triangles, (size_t)(test->ntriangles + 1) * sizeof *test->triangles);
    memcpy(test->triangles[test->ntriangles++].v, v, 9 * sizeof *v);
}

static void test_free(Test *t)
{
    for (int c = 0; c < t->ncases; c++)
        free(t->cases[c].hints);
    free(t->cases);
    free(t->spheres);
    free(t->triangles);
}

void testlist_free(TestList *list)
{
    for (int k = 0; k < list->n; k++)
        test_free(&list->tests[k]);
    free(list->tests);
    memset(list, 0, sizeof *list);
}

void testlist_drop_hard(TestList *list, const bool drop[NPARTS])
{
    int kept = 0;
    for (int k = 0; k < list->n; k++) {
        Test *t = &list->tests[k];
        if (t->hard && drop[t->part])
            test_free(t);
        else
            list->tests[kept++] = *t;
    }
    list->n = kept;
}

/* ---- writing ------------------------------------------------------------ */

static void put_number(FILE *f, double v)
{
    char buf[40];
    fprintf(f, " %s", kit_shortest_double(buf, sizeof buf, v));
}

static void put_numbers(FILE *f, const double *v, int n)
{
    for (int k = 0; k < n; k++)
        put_number(f, v[k]);
}

int tests_write(const TestList *list, const char *path, const char *header, char *err, size_t errlen)
{
    SaveStream out;
    FILE *f = save_open(&out, path, err, errlen);
    if (!f)
        return -1;
    fprintf(f, "%s", header);
    for (int k = 0; k < list->n; k++) {
        const Test *t = &list->tests[k];
        int nin = kind_in[t->kind], nout = kind_out[t->kind];
        fprintf(f, "\ntest %s %s %s %.17g\n", labels[t->part], kind_names[t->kind],
                t->hard ? "hard" : "core", t->weight);
        fprintf(f, "name %s\n", t->name);
        if (t->note[0])
            fprintf(f, "note %s\n", t->note);
        if (t->kind == KIND_COLOR || t->kind == KIND_IMAGE) {
            fprintf(f, "background");
            put_numbers(f, t->background, 3);
            fprintf(f, "\n");
            for (int s = 0; s < t->nspheres; s++) {
                fprintf(f, "sphere");
                put_numbers(f, t->spheres[s].c, 3);
                put_numbers(f, &t->spheres[s].R, 1);
                put_numbers(f, t->spheres[s].color, 3);
                fprintf(f, "\n");
            }
        }
        if (t->kind == KIND_IMAGE)
            fprintf(f, "nx %d\n", t->image_nx);
        for (int k2 = 0; k2 < t->ntriangles; k2++) {
            fprintf(f, "triangle");
            put_numbers(f, t->triangles[k2].v, 9);
            fprintf(f, "\n");
        }
        for (int c = 0; c < t->ncases; c++) {
            const Case *cs = &t->cases[c];
            fprintf(f, "case");
            put_numbers(f, cs->in, nin);
            fprintf(f, " |");
            put_numbers(f, cs->want, nout);
            fprintf(f, " |");
            put_numbers(f, cs->tol, nout);
            fprintf(f, " |");
            put_numbers(f, cs->alt, nout);
            fprintf(f, " | %u\n", cs->flags);
            for (int h = 0; h < cs->nhints; h++) {
                fprintf(f, "hint");
                put_numbers(f, cs->hints[h].out, nout);
                fprintf(f, " | %s\n", cs->hints[h].text);
            }
        }
        fprintf(f, "end\n");
    }
    return save_close(&out, path, 0666, err, errlen);
}

/* ---- reading ------------------------------------------------------------ */

/* Reads n numbers from *p, then expects '|' or the end; 0 on success. */
static int get_numbers(char **p, double *v, int n)
{
    for (int k = 0; k < n; k++) {
        char *end;
        v[k] = decimal_read(*p, &end);
        if (end == *p)
            return -1;
        *p = end;
    }
    while (**p == ' ' || **p == '\t')
        (*p)++;
    if (**p == '|') {
        (*p)++;
        return 0;
    }
    return **p == '\0' || **p == '\n' ? 0 : -1;
}

static char *rest_of_line(char *s)
{
    while (*s == ' ')
        s++;
    s[strcspn(s, "\n")] = '\0';
    return s;
}

/* Copies the rest of the line s into dst, of size n; false when it does
 * not fit (a name or hint cut short would mislead). */
static bool take_text(char *dst, size_t n, char *s)
{
    const char *text = rest_of_line(s);
    size_t len = strlen(text);
    if (len >= n)
        return false;
    memcpy(dst, text, len + 1);
    return true;
}

/* A line "test PART KIND GROUP WEIGHT": a new test in list, in *t; NULL,
 * or what is wrong. */
static const char *read_test_line(TestList *list, const char *p, bool hidden, Test **t)
{
    char part[8], kind[16], group[8];
    double weight;
    if (sscanf(p, "%7s %15s %7s %lf", part, kind, group, &weight) != 4)
        return "test needs: part kind group weight";
    int pt = part_from_label(part), kd = -1;
    for (int k = 0; k < NKINDS; k++)
        if (strcmp(kind, kind_names[k]) == 0)
            kd = k;
    if (pt < 0 || kd < 0 || (strcmp(group, "core") && strcmp(group, "hard")) ||
        !(weight > 0 && weight <= TEST_MAX_WEIGHT))
        return "bad part, kind, group or weight (more than 0, at most 1000000)";
    *t = testlist_add(list, pt, (Kind)kd, "");
    (*t)->hard = strcmp(group, "hard") == 0;
    (*t)->hidden = hidden;
    (*t)->weight = weight;
    return NULL;
}

/* A line "case IN | WANT | TOL | ALT | FLAGS" of t; NULL, or what is wrong. */
static const char *read_case_line(Test *t, char *p, Case **last)
{
    int nin = kind_in[t->kind], nout = kind_out[t->kind];
    Case *c = *last = test_add_case(t);
    double flags;
    if (get_numbers(&p, c->in, nin) || get_numbers(&p, c->want, nout) || get_numbers(&p, c->tol, nout) ||
        get_numbers(&p, c->alt, nout) || get_numbers(&p, &flags, 1))
        return "case needs: inputs | wanted | tolerances | alternatives | flags";
    if (flags != 0 && flags != CASE_EITHER_HIT)
        return "case flags must be 0, or 1 (a hit or a miss both accepted)";
    c->flags = (unsigned)flags;
    return NULL;
}

/* A line "nx N": the width of a render test's image; NULL, or what is wrong. */
static const char *read_nx_line(Test *t, const char *p)
{
    char *q;
    errno = 0;
    long nx = strtol(p, &q, 10);
    while (*q == ' ' || *q == '\t' || *q == '\r' || *q == '\n')
        q++;
    if (errno || q == p || *q || nx < 1 || nx > TEST_MAX_NX)
        return "nx needs a whole number from 1 to 16384";
    t->image_nx = (int)nx;
    return NULL;
}

/* A line inside test *t (after "test", up to "end"); NULL, or what is
 * wrong.  Sets *t to NULL at its end; *last is its latest case. */
static const char *read_body_line(Test **t, char *p, Case **last)
{
    double v[9];
    if (strncmp(p, "name ", 5) == 0)
        return take_text((*t)->name, sizeof (*t)->name, p + 5) ? NULL : "name longer than 127 bytes";
    if (strncmp(p, "note ", 5) == 0)
        return take_text((*t)->note, sizeof (*t)->note, p + 5) ? NULL : "note longer than 159 bytes";
    if (strncmp(p, "background", 10) == 0) {
        p += 10;
        return get_numbers(&p, (*t)->background, 3) ? "background needs 3 numbers" : NULL;
    }
    if (strncmp(p, "sphere", 6) == 0) {
        p += 6;
        if (get_numbers(&p, v, 7))
            return "sphere needs 7 numbers";
        test_add_sphere(*t, v, v[3], v + 4);
        return NULL;
    }
    if (strncmp(p, "triangle", 8) == 0 && (*t)->kind == KIND_MESH) {
        p += 8;
        if (get_numbers(&p, v, 9))
            return "triangle needs 9 numbers";
        test_add_triangle(*t, v);
        return NULL;
    }
    if (strncmp(p, "nx ", 3) == 0)
        return read_nx_line(*t, p + 3);
    if (strncmp(p, "case", 4) == 0)
        return read_case_line(*t, p + 4, last);
    if (strncmp(p, "hint", 4) == 0) {
        if (!*last || (*last)->nhints == CASE_MAX_HINTS)
            return "hint without a case, or too many hints";
        Hint *h = case_add_hint(*last);
        p += 4;
        if (get_numbers(&p, h->out, kind_out[(*t)->kind]))
            return "hint needs the mistake's outputs, then | and its text";
        return take_text(h->text, sizeof h->text, p) ? NULL : "hint text longer than 159 bytes";
    }
    if (strncmp(p, "end", 3) == 0) {
        if ((*t)->ncases == 0)
            return "a test without cases";
        *t = NULL;
        return NULL;
    }
    return "unknown line";
}

int tests_read(TestList *list, const char *path, bool hidden, char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    char *line = NULL;
    size_t cap = 0;
    int lineno = 0;
    Test *t = NULL;
    Case *last = NULL;
    const char *wrong = NULL;
    while (!wrong && getline(&line, &cap, f) > 0) {
        lineno++;
        char *p = line;
        while (*p == ' ')
            p++;
        if (*p == '#' || *p == '\n' || *p == '\0')
            continue;
        if (strncmp(p, "test ", 5) == 0) {
            wrong = t ? "test inside a test (missing end)" : read_test_line(list, p + 5, hidden, &t);
            last = NULL;
        } else {
            wrong = t ? read_body_line(&t, p, &last) : "expected 'test'";
        }
    }
    if (!wrong && t)
        wrong = "missing end at the end of the file";
    if (wrong)
        snprintf(err, errlen, "%s:%d: %s", path, lineno, wrong);
    free(line);
    fclose(f);
    return wrong ? -1 : 0;
}
