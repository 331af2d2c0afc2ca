/*
 * class_hist.c - the class page's scores: for each graded part and for the
 * hard cases, a histogram of the submissions' points with the median and
 * the quartiles marked, and a table of the same numbers.
 *
 * A histogram has ten bars, each a tenth of the points (0 up to the
 * maximum, that excluded), and an eleventh, green, for full points.  The
 * submissions counted are those whose grading reported its points (not a
 * grader error).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "fig_draw.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NBINS 10

/* One row of the scores: its points per submission, sorted. */
typedef struct {
    const char *title;         /* "Part 1: image plane size", "hard cases" */
    const char *id;            /* "1" ... "5", "hard"                       */
    double max;
    int n;
    double *x;
    double q1, med, q3;        /* x's quartiles and median                 */
    int full;                  /* how many of x are full points            */
} Scores;

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The q-quantile (0..1) of the n sorted values x, interpolated between
 * the two nearest ranks (the sample's (n-1) q-th value). */
static double quantile(const double *x, int n, double q)
{
    if (n <= 0)
        return 0;
    double h = (n - 1) * q;
    int lo = (int)floor(h);
    if (lo >= n - 1)
        return x[n - 1];
    return x[lo] + (h - lo) * (x[lo + 1] - x[lo]);
}

/* The points of part p (or, for p = NPARTS, the hard cases). */
static bool scores_of(const ClassView *v, int p, Scores *s)
{
    const GradeConfig *cfg = v->cfg;
    memset(s, 0, sizeof *s);
    s->title = p < NPARTS ? part_title(p) : cfg->hard_is_bonus ? "hard cases (bonus)" : "hard cases";
    s->id = p < NPARTS ? part_label(p) : "hard";
    for (int q = 0; q < NPARTS; q++)
        s->max += p == NPARTS && cfg->parts[q] ? cfg->hard[q] : 0;
    if (p < NPARTS)
        s->max = cfg->parts[p] ? cfg->core[p] : 0;
    if (s->max <= 0 || !(s->x = malloc(((size_t)v->run->n + 1) * sizeof *s->x)))
        return false;
    for (int k = 0; k < v->run->n; k++) {
        const ClassSub *sub = &v->run->subs[k];
        if (sub->summary)
            s->x[s->n++] = p < NPARTS ? sub->core[p] : sub->hard;
    }
    qsort(s->x, (size_t)s->n, sizeof *s->x, by_value);
    s->q1 = quantile(s->x, s->n, 0.25);
    s->med = quantile(s->x, s->n, 0.5);
    s->q3 = quantile(s->x, s->n, 0.75);
    for (int k = 0; k < s->n; k++)
        s->full += s->x[k] >= s->max;
    return true;
}

/* The histogram's geometry: where its bars are, left to right. */
#define HX0 34.0
#define HBAR 22.0
#define HGAP 8.0
#define HTOP 34.0
#define HPLOT 90.0

static double value_x(const Scores *s, double x)
{
    if (x >= s->max)
        return HX0 + NBINS * HBAR + HGAP + HBAR / 2;
    return HX0 + (x > 0 ? x / s->max : 0) * NBINS * HBAR;
}

/* Under the bars, a box from the first quartile to the third with a tick
 * at the median (a box plot), and the three numbers above the bars. */
static void quartile_marks(Markup *m, const Scores *s)
{
    double y = HTOP + HPLOT + 5, x1 = value_x(s, s->q1), x3 = value_x(s, s->q3), med = s->med;
    svg_line(m, HX0, y + 5, value_x(s, s->max), y + 5, COL_GRID, 1, NULL);
    svg_rect(m, x1, y, x3 - x1 > 2 ? x3 - x1 : 2, 10, "#fde2d2", COL_GOT, 1.2);
    svg_line(m, value_x(s, med), y - 2, value_x(s, med), y + 12, COL_GOT, 3, NULL);
    svg_text(m, HX0, 14, "start", 12, COL_TEXT, false, "median %s, quartiles %s and %s",
             points_text(med).s, points_text(s->q1).s, points_text(s->q3).s);
}

/* The bar of x points: NBINS for full points. */
static int bin_of(const Scores *s, double x)
{
    if (x >= s->max)
        return NBINS;
    if (!(x > 0))
        return 0;
    int b = (int)(x / s->max * NBINS);
    return b > NBINS - 1 ? NBINS - 1 : b;
}

static void histogram(Markup *m, const Scores *s)
{
    int bins[NBINS + 1] = { 0 }, most = 1;
    for (int k = 0; k < s->n; k++)
        bins[bin_of(s, s->x[k])]++;
    for (int b = 0; b <= NBINS; b++)
        most = bins[b] > most ? bins[b] : most;
    char title[200];
    snprintf(title, sizeof title, "%s: how many submissions scored how many points", s->title);
    double width = HX0 + (NBINS + 1) * HBAR + HGAP + 14, bottom = HTOP + HPLOT, labels = bottom + 30;
    fig_begin(m, width, labels + 20, title);
    for (int b = 0; b <= NBINS; b++) {
        double h = HPLOT * bins[b] / most, x = HX0 + b * HBAR + (b == NBINS ? HGAP : 0);
        if (bins[b] > 0)
            svg_rect(m, x + 1, bottom - h, HBAR - 2, h, b == NBINS ? "#1a7f37" : COL_WANT, "none", 0);
        if (bins[b] > 0)
            svg_text(m, x + HBAR / 2, bottom - h - 3, "middle", 10, COL_TEXT, false, "%d", bins[b]);
    }
    svg_line(m, HX0, bottom, HX0 + NBINS * HBAR, bottom, COL_AXIS, 1, NULL);
    svg_line(m, HX0 + NBINS * HBAR + HGAP, bottom, width - 14, bottom, COL_AXIS, 1, NULL);
    svg_text(m, HX0, labels, "middle", 11, COL_NOTE, false, "0");
    svg_text(m, HX0 + NBINS * HBAR / 2, labels, "middle", 11, COL_NOTE, false, "%s",
             points_text(s->max / 2).s);
    svg_text(m, value_x(s, s->max), labels, "middle", 11, "#1a7f37", true, "%s",
             points_text(s->max).s);
    svg_text(m, HX0 + NBINS * HBAR / 2, labels + 14, "middle", 11, COL_NOTE, false,
             "points (the green bar: full points)");
    if (s->n > 0)
        quartile_marks(m, s);
    fig_end(m);
}

/* The table's row of s, its numbers also in data- attributes for tools
 * (and the kit's tests). */
static void table_row(Markup *m, const Scores *s)
{
    mk_printf(m, "<tr data-scores=\"%s\" data-n=\"%d\" data-median=\"%.10g\" data-q1=\"%.10g\" "
                 "data-q3=\"%.10g\" data-full=\"%d\"><td>", s->id, s->n, s->med, s->q1, s->q3, s->full);
    if (s->n > 0)                       /* its histogram, drawn below */
        mk_printf(m, "<a href=\"#hist-%s\">", s->id);
    mk_text(m, s->title);
    mk_printf(m, "%s</td><td class=\"num\">%s</td>", s->n > 0 ? "</a>" : "", points_text(s->max).s);
    if (s->n == 0)
        mk_printf(m, "<td colspan=\"3\">no scores</td></tr>\n");
    else
        mk_printf(m, "<td class=\"num\">%s</td><td class=\"num\">%s to %s</td><td class=\"num\">%d "
                     "of %d</td></tr>\n", points_text(s->med).s, points_text(s->q1).s, points_text(s->q3).s,
                  s->full, s->n);
}

void class_scores(Markup *m, const ClassView *v)
{
    Scores all[NPARTS + 1];             /* x is NULL where there are none */
    int drawn = 0;
    mk_printf(m, "<h2 id=\"scores\">Scores</h2>\n<table class=\"scores\">\n<tr><th>part</th>"
                 "<th>points</th><th>median</th><th>quartiles</th><th>full points</th></tr>\n");
    for (int p = 0; p <= NPARTS; p++) {
        if (scores_of(v, p, &all[p]))
            table_row(m, &all[p]);
        drawn += all[p].x && all[p].n > 0;
    }
    mk_printf(m, "</table>\n");
    if (drawn > 0)
        mk_printf(m, "<p class=\"note\">Each histogram counts the submissions by their "
                 "points, in tenths of the part's points; the green bar is full points. Under the "
                 "bars, the orange box spans the quartiles (a quarter of the submissions scored "
                 "less than its left end, a quarter more than its right end) and its tick is the "
                 "median.</p>\n<div class=\"hists\">\n");
    for (int p = 0; p <= NPARTS; p++) {
        if (all[p].x && all[p].n > 0) {
            mk_printf(m, "<figure class=\"hist\" id=\"hist-%s\">\n", all[p].id);
            histogram(m, &all[p]);
            mk_printf(m, "<figcaption>");
            mk_text(m, all[p].title);
            mk_printf(m, "</figcaption></figure>\n");
        }
        free(all[p].x);
    }
    if (drawn > 0)
        mk_printf(m, "</div>\n");
}
