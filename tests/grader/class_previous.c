/*
 * class_previous.c - what changed since a previous run (PREVIOUS=dir, a
 * previous grade-all's OUT): its gradebook.csv read back, each submission's
 * points then and now, and the submissions whose score changed (a regrade
 * after changing tests/weights.conf or the tests), largest change first.
 * A submission is the same one when its folder has the same name.  The
 * gradebook is read as it was when the run began (report_class.c), so that
 * the previous run's OUT may be this one's.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "csv.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A row of the previous gradebook: the name, then each part's points, the
 * hard cases' and the total (NAN where the run had none). */
typedef struct {
    char *name;
    double v[NPARTS + 2];
} Before;

/* The column of a gradebook's header field: a part, NPARTS for "hard",
 * NPARTS + 1 for "total", -1 for any other. */
static int column_of(const char *field)
{
    if (strcmp(field, "hard") == 0)
        return NPARTS;
    if (strcmp(field, "total") == 0)
        return NPARTS + 1;
    return strncmp(field, "part", 4) == 0 ? part_from_label(field + 4) : -1;
}

/* The fields of the line at *p, the first max of them into field (the
 * others freed); *p moves to the next line.  Returns how many it had, or
 * -1 when memory ran out. */
static int read_line(const char **p, char **field, int max)
{
    int end = 0, n = 0;
    while (!end) {
        char *f = csv_read_field(p, &end);
        if (!f) {
            for (int k = 0; k < n && k < max; k++)
                free(field[k]);
            return -1;
        }
        if (n < max)
            field[n] = f;
        else
            free(f);
        n++;
    }
    *p += **p == '\r';
    *p += **p == '\n';
    return n;
}

/* The rows of the previous gradebook, text; -1 when it is not one.  Each
 * field of its header is a column (column_of). */
static int read_before(const char *text, Before **rows, int *n)
{
    const char *p = text;
    char *field[64];
    int column[64], ncolumns = text ? read_line(&p, field, 64) : -1;
    ncolumns = ncolumns < 64 ? ncolumns : 64;
    for (int k = 0; k < ncolumns; k++) {
        column[k] = column_of(field[k]);
        free(field[k]);
    }
    if (ncolumns < 2 || column[0] != -1)
        return -1;
    *rows = NULL;
    *n = 0;
    while (*p) {
        Before *grown = realloc(*rows, (size_t)(*n + 1) * sizeof *grown);
        if (grown)
            *rows = grown;
        int nfields = grown ? read_line(&p, field, 64) : -1;
        if (nfields < 0)
            break;
        Before *row = &(*rows)[(*n)++];
        row->name = field[0];
        for (int c = 0; c < NPARTS + 2; c++)
            row->v[c] = NAN;
        for (int k = 1; k < nfields && k < 64; k++) {
            char *end;
            double x = strtod(field[k], &end);
            if (k < ncolumns && column[k] >= 0 && end != field[k] && !*end)
                row->v[column[k]] = x;
            free(field[k]);
        }
    }
    return 0;
}

/* The change of a submission: after's total less before's (an unknown
 * one counts as the largest, so that it comes first). */
static double change_of(const ClassChange *c)
{
    double d = c->after[NPARTS + 1] - c->before[NPARTS + 1];
    return isnan(d) ? INFINITY : fabs(d);
}

static int by_change(const void *a, const void *b)
{
    const ClassChange *x = a, *y = b;
    double dx = change_of(x), dy = change_of(y);
    if (dx != dy)
        return dx > dy ? -1 : 1;
    return x->sub - y->sub;
}

/* Whether points then and now differ: one of them none (NAN), or more
 * than rounding apart. */
static bool changed(double then, double now)
{
    return isnan(then) != isnan(now) || (!isnan(then) && fabs(now - then) > 1e-9);
}

/* Submission s's points now, as its gradebook row has them. */
static void now_of(const ClassView *v, int s, double *after)
{
    const ClassSub *sub = &v->run->subs[s];
    for (int c = 0; c < NPARTS + 2; c++)
        after[c] = NAN;
    if (!sub->summary)
        return;
    for (int p = 0; p < NPARTS; p++)
        after[p] = v->cfg->parts[p] ? sub->core[p] : NAN;
    after[NPARTS] = sub->hard;
    after[NPARTS + 1] = sub->total;
}

/* Compares the run's submissions with the previous rows. */
static void compare(ClassView *v, Before *rows, int n)
{
    ClassPrevious *pr = &v->previous;
    const ClassRun *run = v->run;
    char *seen = calloc((size_t)n + 1, 1);
    pr->changes = calloc((size_t)run->n + 1, sizeof *pr->changes);
    pr->gone = calloc((size_t)n + 1, sizeof *pr->gone);
    for (int s = 0; seen && pr->changes && s < run->n; s++) {
        int b = 0;
        while (b < n && strcmp(rows[b].name, run->subs[s].name) != 0)
            b++;
        if (b == n) {
            pr->nnew++;
            continue;
        }
        seen[b] = 1;
        pr->compared++;
        ClassChange *c = &pr->changes[pr->nchanges];
        c->sub = s;
        memcpy(c->before, rows[b].v, sizeof c->before);
        now_of(v, s, c->after);
        pr->nchanges += changed(c->before[NPARTS + 1], c->after[NPARTS + 1]);
    }
    for (int b = 0; seen && pr->gone && b < n; b++)
        if (!seen[b])
            pr->gone[pr->ngone++] = rows[b].name, rows[b].name = NULL;
    free(seen);
    if (pr->nchanges > 1)
        qsort(pr->changes, (size_t)pr->nchanges, sizeof *pr->changes, by_change);
}

void class_previous_read(ClassView *v)
{
    ClassPrevious *pr = &v->previous;
    if (!v->run->previous[0])
        return;
    char path[PATH_MAX + 16];
    snprintf(path, sizeof path, "%s/gradebook.csv", v->run->previous);
    Before *rows = NULL;
    int n = 0;
    if (read_before(v->run->previous_csv, &rows, &n) != 0) {
        snprintf(pr->note, sizeof pr->note, "%s could not be read as a gradebook: nothing was "
                 "compared", path);
        return;
    }
    pr->have = true;
    compare(v, rows, n);
    for (int b = 0; b < n; b++)
        free(rows[b].name);
    free(rows);
}

void class_previous_free(ClassPrevious *p)
{
    for (int k = 0; k < p->ngone; k++)
        free(p->gone[k]);
    free(p->gone);
    free(p->changes);
    memset(p, 0, sizeof *p);
}

/* ---- the section ------------------------------------------------------------ */

static void points_cell(Markup *m, double x)
{
    if (isnan(x))
        mk_printf(m, "<td class=\"num\">none</td>");
    else
        mk_printf(m, "<td class=\"num\">%s</td>", points_text(x).s);
}

/* The parts whose points changed: "Part 1 0 to 20, hard cases 2.5 to 5". */
static void parts_changed(Markup *m, const ClassChange *c)
{
    int said = 0;
    for (int k = 0; k < NPARTS + 1; k++) {
        double then = c->before[k], now = c->after[k];
        if (!changed(then, now))
            continue;
        mk_printf(m, "%s%s%s ", said++ ? ", " : "", k < NPARTS ? "Part " : "hard cases",
                  k < NPARTS ? part_label(k) : "");
        mk_printf(m, "%s to %s", isnan(then) ? "none" : points_text(then).s,
                  isnan(now) ? "none" : points_text(now).s);
    }
}

static void change_row(Markup *m, const ClassView *v, const ClassChange *c)
{
    double then = c->before[NPARTS + 1], now = c->after[NPARTS + 1];
    mk_printf(m, "<tr class=\"change\" data-before=\"%.10g\" data-after=\"%.10g\"><td>", then, now);
    class_link(m, v, c->sub);
    mk_printf(m, "</td>");
    points_cell(m, then);
    points_cell(m, now);
    if (isnan(then) || isnan(now))
        mk_printf(m, "<td class=\"num\"></td><td>");
    else
        mk_printf(m, "<td class=\"num %s\">%s%s</td><td>", now > then ? "full" : "lost",
                  now > then ? "+" : "&minus;", points_text(fabs(now - then)).s);
    parts_changed(m, c);
    mk_printf(m, "</td></tr>\n");
}

void class_changes(Markup *m, const ClassView *v)
{
    const ClassPrevious *pr = &v->previous;
    if (!v->run->previous[0])
        return;
    mk_printf(m, "<h2 id=\"changes\">Since the previous run</h2>\n<p>");
    if (!pr->have) {
        mk_text(m, pr->note);
        mk_printf(m, ".</p>\n");
        return;
    }
    mk_printf(m, "Compared with <code>");
    mk_text(m, v->run->previous);
    mk_printf(m, "</code>: %d submission%s graded in both runs; ", pr->compared,
              pr->compared == 1 ? "" : "s");
    if (pr->nchanges == 0)
        mk_printf(m, "no score changed.");
    else
        mk_printf(m, "the score of %d changed.", pr->nchanges);
    if (pr->nnew)
        mk_printf(m, " %d %s new.", pr->nnew, pr->nnew == 1 ? "is" : "are");
    if (pr->ngone) {
        mk_printf(m, " %d graded then %s not here now: ", pr->ngone, pr->ngone == 1 ? "is" : "are");
        for (int k = 0; k < pr->ngone; k++) {
            mk_printf(m, "%s<code>", k ? ", " : "");
            mk_text(m, pr->gone[k]);
            mk_printf(m, "</code>");
        }
        mk_printf(m, ".");
    }
    mk_printf(m, "</p>\n");
    if (pr->nchanges == 0)
        return;
    mk_printf(m, "<table class=\"changes\">\n<tr><th>submission</th><th>then</th><th>now</th>"
                 "<th>change</th><th>where</th></tr>\n");
    for (int k = 0; k < pr->nchanges; k++)
        change_row(m, v, &pr->changes[k]);
    mk_printf(m, "</table>\n");
}
