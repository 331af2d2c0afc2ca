/*
 * svg.c - the benchmark's plots, written directly as SVG (no plotting
 * package).  The speed-against-error plot: log axes, one labelled point
 * per method and precision, and the Pareto front -- the methods no other
 * method beats on both speed and error -- drawn as a staircase; panels are
 * stacked one above the other.  And lines on log axes (svg_lines).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "bench.h"

/* on[i]: no other point has both x no larger and y no smaller (one of them
 * strictly): the Pareto front of "small x, large y". */
static void pareto_front(const PlotPoint *pts, int n, bool *on)
{
    for (int i = 0; i < n; i++) {
        on[i] = true;
        for (int j = 0; j < n; j++) {
            bool no_worse = pts[j].x <= pts[i].x && pts[j].y >= pts[i].y;
            bool better = pts[j].x < pts[i].x || pts[j].y > pts[i].y;
            if (j != i && no_worse && better) {
                on[i] = false;
                break;
            }
        }
    }
}

/* ---- geometry ---------------------------------------------------------------- */

enum { WIDTH = 980, HEADER = 96, PANEL_H = 560, LEFT = 90, RIGHT = 30, PANEL_TOP = 40,
       PANEL_BOTTOM = 64, MAXP = 64 };
#define FONT_W 6.6          /* average width of a 12px sans-serif character */
#define X_FLOOR 1e-18       /* an error of 0 is drawn here                  */

typedef struct {
    double lo, hi;          /* decades: 10^lo .. 10^hi */
    double p0, p1;          /* pixels */
} Axis;

static double axis_pos(const Axis *a, double v)
{
    return a->p0 + (a->p1 - a->p0) * (log10(v) - a->lo) / (a->hi - a->lo);
}

/* The range of the values (those at or below floor_v count as it), in
 * log10, widened to whole decades or, with fine set, to 1, 2, 3 or 5 times
 * a power of ten. */
static void axis_range(Axis *a, const double *v, int n, double floor_v, bool fine)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < n; i++) {
        double x = log10(v[i] > floor_v ? v[i] : floor_v);
        lo = x < lo ? x : lo;
        hi = x > hi ? x : hi;
    }
    if (!(lo <= hi)) {
        lo = 0;
        hi = 1;
    }
    lo -= 0.08;
    hi += 0.08;
    if (!fine) {
        a->lo = floor(lo);
        a->hi = ceil(hi);
        return;
    }
    const double steps[] = { 0, log10(2.0), log10(3.0), log10(5.0), 1 };   /* 1 2 3 5 10 */
    double dlo = floor(lo), dhi = floor(hi);
    int k = 4;
    while (k > 0 && dlo + steps[k] > lo)
        k--;
    a->lo = dlo + steps[k];
    k = 0;
    while (k < 4 && dhi + steps[k] < hi)
        k++;
    a->hi = dhi + steps[k];
}

typedef struct {
    double x0, y0, x1, y1;
} Box;

static bool overlaps(Box a, Box b)
{
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

static void xml_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '&')
            fputs("&amp;", f);
        else if (*s == '<')
            fputs("&lt;", f);
        else if (*s == '>')
            fputs("&gt;", f);
        else
            fputc(*s, f);
    }
}

static const char *group_color[] = { "#1f5fbf", "#d9730d", "#2a9d55" };
static const char *group_name[] = { "double", "float", "mixed: float filter, double solve" };

static void marker(FILE *f, int group, double x, double y)
{
    const char *c = group_color[group];
    if (group == 0)
        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5.5\" fill=\"%s\"/>\n", x, y, c);
    else if (group == 1)
        fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"10\" height=\"10\" fill=\"%s\"/>\n",
                x - 5, y - 5, c);
    else
        fprintf(f, "<path d=\"M%.1f %.1f l6.5 6.5 l-6.5 6.5 l-6.5 -6.5 z\" fill=\"%s\"/>\n",
                x, y - 6.5, c);
}

/* 1, 2, 3 or 5 times a power of ten, as a tick label. */
static void tick_label(char *buf, size_t len, int k, int e)
{
    if (e >= 0 && e <= 4)
        snprintf(buf, len, "%.0f", k * pow(10, e));
    else if (k == 1)
        snprintf(buf, len, "1e%d", e);
    else
        snprintf(buf, len, "%de%d", k, e);
}

/* ---- one panel ------------------------------------------------------------------ */

/* The grid, the ticks and their labels, the frame and the axes' labels
 * of a panel on axes ax and ay. */
static void draw_axes(FILE *f, const Axis *ax, const Axis *ay, const char *xlabel, const char *ylabel)
{
    bool dense_x = ax->hi - ax->lo > 8;      /* label every other decade */
    /* grid: decades darker; 2 and 5 between them on the throughput axis */
    fprintf(f, "<g stroke=\"#e6e6e6\">\n");
    for (int e = (int)ax->lo; e <= (int)ax->hi; e++) {
        double x = axis_pos(ax, pow(10, e));
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#cfcfcf\"/>\n",
                x, ay->p1, x, ay->p0);
    }
    for (int e = (int)floor(ay->lo); e <= (int)ay->hi; e++)
        for (int k = 1; k <= 9; k++) {
            double v = k * pow(10, e);
            if (log10(v) > ay->hi + 1e-9 || log10(v) < ay->lo - 1e-9)
                continue;
            double y = axis_pos(ay, v);
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"%s/>\n", ax->p0, y,
                    ax->p1, y, k == 1 ? " stroke=\"#cfcfcf\"" : "");
        }
    fprintf(f, "</g>\n<g fill=\"#333\">\n");
    for (int e = (int)ax->lo; e <= (int)ax->hi; e++) {
        if (dense_x && (e - (int)ax->lo) % 2 != 0)
            continue;
        char buf[32];
        tick_label(buf, sizeof buf, 1, e);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n",
                axis_pos(ax, pow(10, e)), ay->p0 + 18, buf);
    }
    for (int e = (int)floor(ay->lo); e <= (int)ay->hi; e++)
        for (int k = 1; k <= 5; k += (k < 3 ? 1 : 2)) {           /* 1, 2, 3, 5 */
            double v = k * pow(10, e);
            if (log10(v) > ay->hi + 1e-9 || log10(v) < ay->lo - 1e-9)
                continue;
            char buf[32];
            tick_label(buf, sizeof buf, k, e);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n", ax->p0 - 8,
                    axis_pos(ay, v) + 4, buf);
        }
    fprintf(f, "</g>\n");
    fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
               "stroke=\"#888\"/>\n", ax->p0, ay->p1, ax->p1 - ax->p0, ay->p0 - ay->p1);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"13\">",
            (ax->p0 + ax->p1) / 2, ay->p0 + 42);
    xml_text(f, xlabel);
    fprintf(f, "</text>\n<text transform=\"translate(24 %.1f) rotate(-90)\" "
               "text-anchor=\"middle\" font-size=\"13\">", (ay->p0 + ay->p1) / 2);
    xml_text(f, ylabel);
    fprintf(f, "</text>\n");
}

/* The Pareto front (on[i]: point i is on it) of the n points at (px, py),
 * errors xs: a dashed staircase through its points, by error, from the
 * axes' corner. */
static void draw_front(FILE *f, const bool *on, const double *xs, const double *px, const double *py, int n,
                       const Axis *ax, const Axis *ay)
{
    int order[MAXP], nf = 0;
    for (int i = 0; i < n; i++)
        if (on[i])
            order[nf++] = i;
    for (int a = 1; a < nf; a++)
        for (int b = a; b > 0 && xs[order[b]] < xs[order[b - 1]]; b--) {
            int tmp = order[b];
            order[b] = order[b - 1];
            order[b - 1] = tmp;
        }
    if (nf > 0) {
        fprintf(f, "<path fill=\"none\" stroke=\"#555\" stroke-width=\"1.5\" "
                   "stroke-dasharray=\"6 4\" d=\"M%.1f %.1f", ax->p0, py[order[0]]);
        for (int a = 0; a < nf; a++) {
            if (a > 0)
                fprintf(f, " V%.1f", py[order[a]]);
            fprintf(f, " H%.1f", px[order[a]]);
        }
        fprintf(f, " V%.1f\"/>\n", ay->p0);
    }
}

/* Where the label of the point at (px, py), w wide, goes: the first of the
 * places around the point inside the axes that overlaps none of the
 * nplaced boxes placed, or failing that the first or fourth place inside,
 * or failing that right of the point.  Its box; its text starts at (*tx,
 * *ty). */
static Box place_label(double px, double py, double w, const Axis *ax, const Axis *ay, const Box *placed,
                       int nplaced, double *tx, double *ty)
{
    static const double dx[] = { 12, 12, 12, -12, -12, -12, 0, 0, 12, -12, 12, -12, 30, -30 };
    static const double dy[] = { 4, -9, 17, 4, -9, 17, -13, 25, -22, -22, 30, 30, 4, 4 };
    Box best = { 0, 0, 0, 0 };
    *tx = 0, *ty = 0;
    for (size_t c = 0; c < sizeof dx / sizeof dx[0]; c++) {
        double x0 = dx[c] > 0 ? px + dx[c] : dx[c] < 0 ? px + dx[c] - w : px - w / 2;
        Box b = { x0, py + dy[c] - 12, x0 + w, py + dy[c] + 4 };
        bool inside = b.x0 >= ax->p0 && b.x1 <= ax->p1 && b.y0 >= ay->p1 && b.y1 <= ay->p0;
        bool ok = inside;
        for (int k = 0; ok && k < nplaced; k++)
            ok = !overlaps(b, placed[k]);
        if (ok || (c == 0 && inside) || (c == 3 && best.x1 == 0 && inside)) {
            best = b;
            *tx = x0;
            *ty = py + dy[c];
            if (ok)
                break;
        }
    }
    if (best.x1 == 0) {            /* nowhere inside: right of the point */
        *tx = px + 12;
        *ty = py + 4;
        Box b = { *tx, *ty - 11, *tx + w, *ty + 3 };
        best = b;
    }
    return best;
}

/* The n points (at most MAXP) of a panel, its texts p and ylabel. */
static void draw_panel(FILE *f, const PlotPoint *pts, int n, const PlotPanel *p,
                       const char *ylabel, double top)
{
    double xs[MAXP], ys[MAXP];
    for (int i = 0; i < n; i++) {
        xs[i] = pts[i].x;
        ys[i] = pts[i].y;
    }
    Axis ax = { 0, 0, LEFT, WIDTH - RIGHT };
    Axis ay = { 0, 0, top + PANEL_H - PANEL_BOTTOM, top + PANEL_TOP };
    axis_range(&ax, xs, n, X_FLOOR, false);
    axis_range(&ay, ys, n, 1e-3, true);
    fprintf(f, "<text x=\"%d\" y=\"%.1f\" font-size=\"15\" font-weight=\"bold\">", LEFT, top + 24);
    xml_text(f, p->title);
    fprintf(f, "</text>\n");
    draw_axes(f, &ax, &ay, p->xlabel, ylabel);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"#888\" font-style=\"italic\">"
               "better: up and to the left</text>\n", ax.p0 + 8, ay.p1 + 16);

    bool on[MAXP];
    pareto_front(pts, n, on);
    double px[MAXP], py[MAXP];
    for (int i = 0; i < n; i++) {
        px[i] = axis_pos(&ax, xs[i] > X_FLOOR ? xs[i] : X_FLOOR);
        py[i] = axis_pos(&ay, ys[i]);
    }
    draw_front(f, on, xs, px, py, n, &ax, &ay);

    /* points, then labels where they collide with nothing placed yet */
    Box placed[2 * MAXP];
    int nplaced = 0;
    for (int i = 0; i < n; i++) {
        Box b = { px[i] - 7, py[i] - 7, px[i] + 7, py[i] + 7 };
        placed[nplaced++] = b;
        if (on[i])
            fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"10\" fill=\"none\" stroke=\"#555\"/>\n",
                    px[i], py[i]);
        marker(f, pts[i].group, px[i], py[i]);
    }
    for (int i = 0; i < n; i++) {
        double w = FONT_W * (double)strlen(pts[i].label), tx, ty;
        Box best = place_label(px[i], py[i], w, &ax, &ay, placed, nplaced, &tx, &ty);
        placed[nplaced++] = best;
        /* a label not beside its point gets a thin line to it */
        double cx = px[i] < best.x0 ? best.x0 : px[i] > best.x1 ? best.x1 : px[i];
        double cy = py[i] < best.y0 ? best.y0 : py[i] > best.y1 ? best.y1 : py[i];
        if (hypot(cx - px[i], cy - py[i]) > 16)
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
                       "stroke-width=\"0.7\"/>\n", px[i], py[i], cx, cy,
                    group_color[pts[i].group]);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\">", tx, ty,
                group_color[pts[i].group]);
        xml_text(f, pts[i].label);
        fprintf(f, "</text>\n");
    }
}

/* Opens dir/name (outfile.c) and writes the document's start, its title and
 * subtitle, for a picture height pixels high.  Returns the file, or NULL
 * with err. */
static FILE *svg_begin(const char *dir, const char *name, int height, const char *title,
                       const char *subtitle, char *err, size_t errlen)
{
    FILE *f = out_open(dir, name, err, errlen);
    if (!f)
        return NULL;
    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "viewBox=\"0 0 %d %d\" font-family=\"Helvetica, Arial, sans-serif\" "
               "font-size=\"12\">\n", WIDTH, height, WIDTH, height);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(f, "<text x=\"%d\" y=\"28\" font-size=\"19\" font-weight=\"bold\">", LEFT);
    xml_text(f, title);
    fprintf(f, "</text>\n<text x=\"%d\" y=\"50\" fill=\"#555\">", LEFT);
    xml_text(f, subtitle);
    fprintf(f, "</text>\n");
    return f;
}

/* Ends the document and closes f into dir/name.  Returns 0, or -1 with err. */
static int svg_end(FILE *f, const char *dir, const char *name, char *err, size_t errlen)
{
    fprintf(f, "</svg>\n");
    return out_close(f, dir, name, err, errlen);
}

int svg_plot(const char *dir, const char *name, const char *title, const char *subtitle,
             const MethodPoint *pts, int n, const PlotPanel panels[2], const char *ylabel,
             char *err, size_t errlen)
{
    FILE *f = svg_begin(dir, name, HEADER + 2 * PANEL_H, title, subtitle, err, errlen);
    if (!f)
        return -1;
    /* each panel's points, their group their precision; and the legend,
     * once, under the title: the groups that have points */
    char labels[MAXP][METHOD_LABEL];
    PlotPoint pp[2][MAXP];
    bool present[3] = { false, false, false };
    n = n < MAXP ? n : MAXP;
    for (int i = 0; i < n; i++) {
        const char *label = method_cells(labels[i], pts[i].name, pts[i].precision, " ");
        for (int k = 0; k < 2; k++)
            pp[k][i] = (PlotPoint){ label, pts[i].x[k], pts[i].y, (int)pts[i].precision };
        present[pts[i].precision] = true;
    }
    double lx = LEFT, ly = 76;
    for (int g = 0; g < 3; g++) {
        if (!present[g])
            continue;
        marker(f, g, lx + 6, ly - 4);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">%s</text>\n", lx + 18, ly, group_name[g]);
        lx += 30 + FONT_W * (double)strlen(group_name[g]);
    }
    fprintf(f, "<path d=\"M%.1f %.1f h26\" stroke=\"#555\" stroke-width=\"1.5\" "
               "stroke-dasharray=\"6 4\"/>\n", lx, ly - 4);
    fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"7\" fill=\"none\" stroke=\"#555\"/>\n",
            lx + 13, ly - 4);
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">Pareto front: nothing is both faster and more "
               "accurate</text>\n", lx + 34, ly);
    for (int k = 0; k < 2; k++)
        draw_panel(f, pp[k], n, &panels[k], ylabel, HEADER + k * PANEL_H);
    return svg_end(f, dir, name, err, errlen);
}

int svg_lines(const char *dir, const char *name, const char *title, const char *subtitle,
              const char *xlabel, const char *ylabel, const PlotSeries *series, int nseries,
              char *err, size_t errlen)
{
    FILE *f = svg_begin(dir, name, HEADER + PANEL_H, title, subtitle, err, errlen);
    if (!f)
        return -1;
    double xs[MAXP] = { 0 }, ys[MAXP] = { 0 };
    int n = 0;
    for (int s = 0; s < nseries; s++)
        for (int i = 0; i < series[s].n && n < MAXP; i++, n++) {
            xs[n] = series[s].pts[i].x;
            ys[n] = series[s].pts[i].y;
        }
    Axis ax = { 0, 0, LEFT, WIDTH - RIGHT };
    Axis ay = { 0, 0, HEADER + PANEL_H - PANEL_BOTTOM, HEADER + 16 };
    axis_range(&ax, xs, n, X_FLOOR, false);
    axis_range(&ay, ys, n, 1e-6, true);
    draw_axes(f, &ax, &ay, xlabel, ylabel);
    double lx = LEFT;
    for (int s = 0; s < nseries; s++) {
        const PlotPoint *pts = series[s].pts;
        const char *color = group_color[pts[0].group];
        marker(f, pts[0].group, lx + 6, 72);
        fprintf(f, "<text x=\"%.1f\" y=\"76\">", lx + 18);
        xml_text(f, series[s].label);
        fprintf(f, "</text>\n");
        lx += 40 + FONT_W * (double)strlen(series[s].label);
        fprintf(f, "<path fill=\"none\" stroke=\"%s\" stroke-width=\"2\" d=\"", color);
        for (int i = 0; i < series[s].n; i++)
            fprintf(f, "%s%.1f %.1f", i ? " L" : "M", axis_pos(&ax, pts[i].x),
                    axis_pos(&ay, pts[i].y > 1e-6 ? pts[i].y : 1e-6));
        fprintf(f, "\"/>\n");
        for (int i = 0; i < series[s].n; i++)
            marker(f, pts[i].group, axis_pos(&ax, pts[i].x),
                   axis_pos(&ay, pts[i].y > 1e-6 ? pts[i].y : 1e-6));
    }
    return svg_end(f, dir, name, err, errlen);
}
