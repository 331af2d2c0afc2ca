/*
 * report_class.c - the class at a glance (report_class.h): the run's
 * submissions, what the page counts over them (the causes, the tests most
 * failed), and OUT/causes.csv.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "build.h"
#include "jail.h"
#include "csv.h"
#include "sandbox.h"
#include "kit/savefile.h"

#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

ClassRun *class_begin(const char *out, const char *previous)
{
    ClassRun *run = calloc(1, sizeof *run);
    char err[256] = "out of memory";
    if (!run || build_tempdir(run->records, sizeof run->records, err, sizeof err) != 0) {
        fprintf(stderr, "grade: no class page: %s\n", err);
        free(run);
        return NULL;
    }
    snprintf(run->out, sizeof run->out, "%s", out);
    snprintf(run->previous, sizeof run->previous, "%s", previous ? previous : "");
    if (previous) {
        char path[PATH_MAX + 16];
        size_t len;
        snprintf(path, sizeof path, "%s/gradebook.csv", previous);
        run->previous_csv = kit_load_file(path, 64u << 20, &len);
    }
    run->start = sandbox_now();
    return run;
}

const char *class_record_path(const ClassRun *run, int k, char *buf, size_t n)
{
    snprintf(buf, n, "%s/%d", run->records, k);
    return buf;
}

void class_add(ClassRun *run, int k, const char *name, const double *values, int status,
               bool no_stage_file)
{
    if (!run || k != run->n)
        return;
    ClassSub *grown = realloc(run->subs, (size_t)(k + 1) * sizeof *grown);
    if (!grown)
        return;
    run->subs = grown;
    char *copy = strdup(name);
    if (!copy)
        return;
    ClassSub *s = &run->subs[run->n++];
    *s = (ClassSub){ .name = copy, .status = status, .no_stage_file = no_stage_file,
                     .summary = values != NULL };
    if (values) {
        memcpy(s->core, values, sizeof s->core);
        s->hard = values[NPARTS];
        s->total = values[NPARTS + 1];
    }
}

/* ---- the causes ------------------------------------------------------------- */

static int by_count(const void *a, const void *b)
{
    const ClassCauseRow *x = a, *y = b;
    if (x->part != y->part)
        return x->part - y->part;
    if (x->count != y->count)
        return y->count - x->count;
    return strcmp(x->key, y->key);
}

/* The row of (part, key), added when new; NULL when memory runs out. */
static ClassCauseRow *cause_row(ClassView *v, int part, const char *key, int nsubs)
{
    for (int r = 0; r < v->ncauses; r++)
        if (v->causes[r].part == part && strcmp(v->causes[r].key, key) == 0)
            return &v->causes[r];
    ClassCauseRow *grown = realloc(v->causes, (size_t)(v->ncauses + 1) * sizeof *grown);
    int *subs = malloc((size_t)nsubs * sizeof *subs);
    if (!grown || !subs) {
        if (grown)
            v->causes = grown;
        free(subs);
        return NULL;
    }
    v->causes = grown;
    v->causes[v->ncauses] = (ClassCauseRow){ .part = part, .key = key, .subs = subs };
    return &v->causes[v->ncauses++];
}

/* The wording of row's cause that most of its submissions read (the first
 * such, in the gradebook's order). */
static const char *common_text(const ClassView *v, const ClassCauseRow *row)
{
    const char *best = "";
    int most = 0;
    for (int i = 0; i < row->count; i++) {
        const char *text = "";
        const ClassPart *cp = &v->run->subs[row->subs[i]].part[row->part];
        for (int c = 0; c < cp->ncauses; c++)
            if (strcmp(cp->causes[c].key, row->key) == 0)
                text = cp->causes[c].text;
        int same = 0;
        for (int j = 0; j < row->count; j++) {
            const ClassPart *o = &v->run->subs[row->subs[j]].part[row->part];
            for (int c = 0; c < o->ncauses; c++)
                same += strcmp(o->causes[c].key, row->key) == 0 && strcmp(o->causes[c].text, text) == 0;
        }
        if (same > most) {
            most = same;
            best = text;
        }
    }
    return best;
}

/* Every cause of every record, with the submissions that have it. */
static void count_causes(ClassView *v)
{
    const ClassRun *run = v->run;
    for (int s = 0; s < run->n; s++)
        for (int p = 0; p < NPARTS; p++)
            for (int c = 0; c < run->subs[s].part[p].ncauses; c++) {
                ClassCauseRow *row = cause_row(v, p, run->subs[s].part[p].causes[c].key, run->n);
                if (row && (row->count == 0 || row->subs[row->count - 1] != s))
                    row->subs[row->count++] = s;
            }
    for (int r = 0; r < v->ncauses; r++)
        v->causes[r].text = common_text(v, &v->causes[r]);
    if (v->ncauses > 1)
        qsort(v->causes, (size_t)v->ncauses, sizeof *v->causes, by_count);
}

/* ---- the tests most failed ---------------------------------------------------- */

/* Whether two answers are the same: the same case, the same numbers to
 * the bit. */
static bool same_answer(const ClassFail *x, const ClassFail *y)
{
    return x->c == y->c && x->nout == y->nout &&
           memcmp(x->got, y->got, (size_t)x->nout * sizeof x->got[0]) == 0;
}

typedef struct {
    int sub;
    const ClassFail *f;
} Wrong;

/* Row's distinct wrong answers and the most common one (of two as common,
 * the one given first in the gradebook's order), from its n answers wrong,
 * in the gradebook's order. */
static void common_answer(ClassTestRow *row, const Wrong *wrong, int n)
{
    int best = 0, most = 0;
    for (int i = 0; i < n; i++) {
        int same = 0, first = i;
        for (int j = n - 1; j >= 0; j--)
            if (same_answer(wrong[i].f, wrong[j].f)) {
                same++;
                first = j;
            }
        row->answers += first == i;
        if (same > most) {
            most = same;
            best = i;
        }
    }
    if (most == 0 || !(row->common_subs = malloc((size_t)most * sizeof *row->common_subs)))
        return;
    row->common = wrong[best].f;
    for (int j = 0; j < n; j++)
        if (same_answer(wrong[best].f, wrong[j].f))
            row->common_subs[row->ncommon++] = wrong[j].sub;
}

static double fail_rate(const ClassTestRow *r)
{
    return r->built > 0 ? (double)r->failed / r->built : 0;
}

static int by_failures(const void *a, const void *b)
{
    const ClassTestRow *x = a, *y = b;
    if (x->failed != y->failed)
        return y->failed - x->failed;
    double rx = fail_rate(x), ry = fail_rate(y);
    if (rx != ry)
        return rx > ry ? -1 : 1;
    return x->test - y->test;
}

/* Each test's failures among the submissions whose file of its part
 * built; the most failed kept, with their most common wrong answers. */
static void count_tests(ClassView *v)
{
    const ClassRun *run = v->run;
    int n = v->tests->n, built[NPARTS] = { 0 };
    ClassTestRow *rows = calloc((size_t)n, sizeof *rows);
    Wrong *wrong = malloc(((size_t)run->n + 1) * sizeof *wrong);
    if (!rows || !wrong) {
        free(rows);
        free(wrong);
        return;
    }
    for (int s = 0; s < run->n; s++)
        for (int p = 0; p < NPARTS; p++)
            built[p] += run->subs[s].record && run->subs[s].part[p].built;
    for (int k = 0; k < n; k++) {
        rows[k].test = k;
        rows[k].built = built[v->tests->tests[k].part];
    }
    for (int s = 0; s < run->n; s++)
        for (int i = 0; i < run->subs[s].nfails; i++) {
            const ClassFail *f = &run->subs[s].fails[i];
            if (f->test < n && run->subs[s].part[v->tests->tests[f->test].part].built)
                rows[f->test].failed++;
        }
    qsort(rows, (size_t)n, sizeof *rows, by_failures);
    int keep = 0;
    while (keep < n && keep < CLASS_MAX_TESTS && rows[keep].failed > 0)
        keep++;
    for (int r = 0; r < keep; r++) {
        int nwrong = 0;
        for (int s = 0; s < run->n; s++)
            for (int i = 0; i < run->subs[s].nfails; i++) {
                const ClassFail *f = &run->subs[s].fails[i];
                if (f->test == rows[r].test && f->c >= 0 && f->nout > 0 &&
                    run->subs[s].part[v->tests->tests[f->test].part].built)
                    wrong[nwrong++] = (Wrong){ s, f };
            }
        common_answer(&rows[r], wrong, nwrong);
    }
    free(wrong);
    v->worst = rows;
    v->nworst = keep;
}

/* ---- the files ------------------------------------------------------------------ */

/* The names of row's submissions, as causes.csv lists them: separated by
 * a space, each name's spaces and percent signs written %20 and %25. */
static void list_names(Markup *m, const ClassView *v, const ClassCauseRow *row)
{
    for (int i = 0; i < row->count; i++) {
        if (i)
            mk_raw(m, " ", 1);
        for (const char *c = v->run->subs[row->subs[i]].name; *c; c++) {
            if (*c == ' ' || *c == '%')
                mk_printf(m, "%%%02X", (unsigned char)*c);
            else
                mk_raw(m, c, 1);
        }
    }
    mk_raw(m, "", 1);
}

/* OUT/causes.csv: part,cause,text,count,submissions, a row per part and
 * cause, in the page's order; the text is its sentence's first line. */
static int write_causes_csv(const ClassView *v, char *err, size_t errlen)
{
    char path[PATH_MAX + 16];
    snprintf(path, sizeof path, "%s/causes.csv", v->run->out);
    SaveStream out;
    FILE *f = save_open(&out, path, err, errlen);
    if (!f)
        return -1;
    fprintf(f, "part,cause,text,count,submissions\n");
    bool ok = true;
    for (int r = 0; r < v->ncauses && ok; r++) {
        const ClassCauseRow *row = &v->causes[r];
        Markup names;
        mk_init(&names);
        list_names(&names, v, row);
        char *line = strndup(row->text, strcspn(row->text, "\n"));
        ok = line && mk_ok(&names);
        if (ok) {
            fprintf(f, "%s,%s,", part_label(row->part), row->key);
            csv_field(f, line);
            fprintf(f, ",%d,", row->count);
            csv_field(f, (const char *)names.b.data);
            fputc('\n', f);
        }
        free(line);
        mk_free(&names);
    }
    if (!ok) {
        fclose(f);
        free(out.data);
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    return save_close(&out, path, 0600, err, errlen);     /* every name in it: the owner's alone */
}

/* ---- the end of the run ------------------------------------------------------------ */

static double cpu_seconds(void)
{
    struct rusage self, children;
    getrusage(RUSAGE_SELF, &self);
    getrusage(RUSAGE_CHILDREN, &children);
    return (double)(self.ru_utime.tv_sec + self.ru_stime.tv_sec + children.ru_utime.tv_sec +
                    children.ru_stime.tv_sec) +
           1e-6 * (double)(self.ru_utime.tv_usec + self.ru_stime.tv_usec + children.ru_utime.tv_usec +
                           children.ru_stime.tv_usec);
}

static void view_free(ClassView *v)
{
    for (int r = 0; r < v->ncauses; r++)
        free(v->causes[r].subs);
    free(v->causes);
    for (int r = 0; r < v->nworst; r++)
        free(v->worst[r].common_subs);
    free(v->worst);
    class_previous_free(&v->previous);
}

int class_finish(ClassRun *run, const GradeConfig *cfg, ClassLoadTests load_tests)
{
    if (!run)
        return -1;
    ClassView v = { .run = run, .cfg = cfg, .page_start = sandbox_now() };
    v.seconds = v.page_start - run->start;
    v.cpu = cpu_seconds();
    TestList tests = { 0 };
    bool failures = false;
    for (int s = 0; s < run->n; s++) {
        char path[PATH_MAX + 32];
        class_record_path(run, s, path, sizeof path);
        run->subs[s].record = class_record_read(path, &run->subs[s]);
        failures = failures || run->subs[s].nfails > 0;
        for (int p = 0; p < NPARTS; p++)
            v.compiled += run->subs[s].part[p].graded && !run->subs[s].part[p].refused;
    }
    char err[PATH_MAX + 300];
    if (failures && load_tests(&tests, cfg, cfg->parts, err, sizeof err) == 0)
        v.tests = &tests;
    else if (failures)
        snprintf(v.tests_note, sizeof v.tests_note, "%.250s", err);
    count_causes(&v);
    if (v.tests)
        count_tests(&v);
    class_previous_read(&v);
    char page[PATH_MAX + 16];
    snprintf(page, sizeof page, "%s/index.html", run->out);
    int status = write_causes_csv(&v, err, sizeof err);
    if (status == 0)
        status = class_page_write(page, &v, err, sizeof err);
    if (status == 0)
        printf("the class at a glance: %s (for you alone: it names every student), and each part's "
               "causes in %s/causes.csv\n", page, run->out);
    else
        fprintf(stderr, "grade: the class page was not written: %s\n", err);
    view_free(&v);
    testlist_free(&tests);
    for (int s = 0; s < run->n; s++)
        class_sub_free(&run->subs[s]);
    free(run->subs);
    free(run->previous_csv);
    jail_remove_tree(run->records);
    free(run);
    return status;
}
