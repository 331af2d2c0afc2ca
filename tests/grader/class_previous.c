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

/* Compares the run's submissions with the rows of the previous gradebook,
 * text, its header first (each field a column, column_of); -1 when it is
 * not a gradebook. */
static int compare(ClassView *v, const char *text)
{
    ClassPrevious *pr = &v->previous;
    const ClassRun *run = v->run;
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
    size_t lines = 1;                   /* the most rows there can be */
    for (const char *c = p; *c; c++)
        lines += *c == '\n';
    char *seen = calloc((size_t)run->n + 1, 1);
    pr->changes = calloc((size_t)run->n + 1, sizeof *pr->changes);
    pr->gone = calloc(lines, sizeof *pr->gone);
    while (*p && seen && pr->changes && pr->gone) {
        int nfields = read_line(&p, field, 64);
        if (nfields < 0)
            break;
        /* The row's points (NAN where it has none), in the next change's
         * place; the submission of its name, the first row of a name. */
        ClassChange *c = &pr->changes[pr->nchanges];
        for (int k = 0; k < NPARTS + 2; k++)
            c->before[k] = NAN;
        for (int k = 1; k < nfields && k < 64; k++) {
            char *end;
            double x = strtod(field[k], &end);
            if (k < ncolumns && column[k] >= 0 && end != field[k] && !*end)
                c->before[column[k]] = x;
            free(field[k]);
        }
        int s = 0;
        while (s < run->n && (seen[s] || strcmp(run->subs[s].name, field[0]) != 0))
            s++;
        if (s == run->n) {
            pr->gone[pr->ngone++] = field[0];
            continue;
        }
        free(field[0]);
        seen[s] = 1;
        pr->compared++;
        c->sub = s;
        now_of(v, s, c->after);
        pr->nchanges += changed(c->before[NPARTS + 1], c->after[NPARTS + 1]);
    }
    for (int s = 0; seen && s < run->n; s++)
        pr->nnew += !seen[s];
    free(seen);
    if (pr->nchanges > 1)
        qsort(pr->changes, (size_t)pr->nchanges, sizeof *pr->changes, by_change);
    return 0;
}

void class_previous_read(ClassView *v)
{
    ClassPrevious *pr = &v->previous;
    if (!v->run->previous[0])
        return;
    if (compare(v, v->run->previous_csv) != 0)
        snprintf(pr->note, sizeof pr->note, "%s/gradebook.csv could not be read as a gradebook: nothing "
                 "was compared", v->run->previous);
    else
        pr->have = true;
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
