/*
 * svg.h - the benchmark's plots, drawn as SVG by hand (no plotting
 * package): speed against error on log axes, and lines on log axes.
 */
#ifndef BENCH_SVG_H
#define BENCH_SVG_H

#include <stdbool.h>
#include <stddef.h>

typedef struct {
    const char *label;      /* shown beside the point                          */
    double x;               /* error (smaller is better); 0 is drawn at 1e-18   */
    double y;               /* throughput (larger is better), > 0              */
    int group;              /* 0 double, 1 float, 2 mixed: colour and marker   */
} PlotPoint;

typedef struct {
    const PlotPoint *pts;
    int n;
    const char *title;      /* above the panel                                 */
    const char *xlabel, *ylabel;
} PlotPanel;

/* on[i]: no other point has both x no larger and y no smaller (one of them
 * strictly): the Pareto front of "small x, large y". */
void pareto_front(const PlotPoint *pts, int n, bool *on);

/* Writes the panels, one above the other, to dir/name.  Returns 0, or -1
 * with a reason in err. */
int svg_plot(const char *dir, const char *name, const char *title, const char *subtitle,
             const PlotPanel *panels, int npanels, char *err, size_t errlen);

/* A line of points, drawn in the colour and marker of its points' group. */
typedef struct {
    const PlotPoint *pts;       /* by x; their labels are not drawn */
    int n;
    const char *label;          /* in the legend */
} PlotSeries;

/* Writes one panel of lines on log axes to dir/name.  Returns 0, or -1 with
 * a reason in err. */
int svg_lines(const char *dir, const char *name, const char *title, const char *subtitle,
              const char *xlabel, const char *ylabel, const PlotSeries *series, int nseries,
              char *err, size_t errlen);

#endif
