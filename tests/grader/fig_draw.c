/*
 * fig_draw.c - see fig_draw.h: what every figure shares (windows, clipped
 * lines, circles and polygons, numbers, the legend).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "fig_draw.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void fig_fit(FigView *v, double x0, double y0, double x1, double y1, double pad,
             double px0, double py0, double pw, double ph)
{
    double w = x1 - x0, h = y1 - y0;
    if (!(w > 0) && !(h > 0))
        w = h = 1;
    if (!(w > 0))
        w = h * 1e-3;
    if (!(h > 0))
        h = w * 1e-3;
    v->cx = x0 / 2 + x1 / 2;
    v->cy = y0 / 2 + y1 / 2;
    v->s = fmin(pw / (w * (1 + 2 * pad)), ph / (h * (1 + 2 * pad)));
    if (!(v->s > 0) || isinf(v->s))
        v->s = 1;
    v->px0 = px0;
    v->py0 = py0;
    v->pw = pw;
    v->ph = ph;
}

double fig_px(const FigView *v, double x)
{
    return v->px0 + v->pw / 2 + (x - v->cx) * v->s;
}

double fig_py(const FigView *v, double y)
{
    return v->py0 + v->ph / 2 - (y - v->cy) * v->s;
}

bool fig_inside(const FigView *v, double x, double y)
{
    double px = fig_px(v, x), py = fig_py(v, y);
    return px >= v->px0 && px <= v->px0 + v->pw && py >= v->py0 && py <= v->py0 + v->ph;
}

void fig_segment(Markup *m, const FigView *v, double x1, double y1, double x2, double y2,
                 const char *color, double width, const char *dash)
{
    /* Liang-Barsky, in pixels relative to the window (a little larger). */
    double ax = (x1 - v->cx) * v->s, ay = -(y1 - v->cy) * v->s;
    double dx = (x2 - x1) * v->s, dy = -(y2 - y1) * v->s;
    if (!isfinite(ax) || !isfinite(ay) || !isfinite(dx) || !isfinite(dy))
        return;
    double hw = v->pw / 2 + 4, hh = v->ph / 2 + 4, t0 = 0, t1 = 1;
    double p[4] = { -dx, dx, -dy, dy }, q[4] = { ax + hw, hw - ax, ay + hh, hh - ay };
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return;
        } else {
            double r = q[k] / p[k];
            if (p[k] < 0 && r > t0)
                t0 = r;
            if (p[k] > 0 && r < t1)
                t1 = r;
        }
    }
    if (t0 > t1)
        return;
    double ox = v->px0 + v->pw / 2, oy = v->py0 + v->ph / 2;
    svg_line(m, ox + ax + t0 * dx, oy + ay + t0 * dy, ox + ax + t1 * dx, oy + ay + t1 * dy, color,
             width, dash);
}

/* Sutherland-Hodgman: keeps the part of the polygon (x, y)[n] on the side
 * of the line where sign * (coord[axis] - edge) >= 0; returns its size. */
static int clip_side(const double *x, const double *y, int n, int axis, double edge, double sign,
                     double *ox, double *oy)
{
    int m = 0;
    for (int k = 0; k < n; k++) {
        int l = (k + 1) % n;
        double ck = sign * ((axis ? y[k] : x[k]) - edge), cl = sign * ((axis ? y[l] : x[l]) - edge);
        if (ck >= 0) {
            ox[m] = x[k], oy[m] = y[k], m++;
        }
        if ((ck >= 0) != (cl >= 0)) {
            double f = ck / (ck - cl);
            ox[m] = x[k] + f * (x[l] - x[k]), oy[m] = y[k] + f * (y[l] - y[k]), m++;
        }
    }
    return m;
}

void fig_polygon(Markup *m, const FigView *v, const double *wx, const double *wy, int n,
                 const char *fill, double opacity, const char *stroke, double width)
{
    enum { MAXV = 40 };
    double x[MAXV], y[MAXV], tx[MAXV], ty[MAXV];
    if (n < 2 || n > 8)
        return;
    for (int k = 0; k < n; k++) {
        x[k] = fig_px(v, wx[k]);
        y[k] = fig_py(v, wy[k]);
        if (!isfinite(x[k]) || !isfinite(y[k]))
            return;
    }
    double lo[2] = { v->px0 - 6, v->py0 - 6 }, hi[2] = { v->px0 + v->pw + 6, v->py0 + v->ph + 6 };
    for (int axis = 0; axis < 2 && n > 0; axis++) {
        n = clip_side(x, y, n, axis, lo[axis], 1, tx, ty);
        n = clip_side(tx, ty, n, axis, hi[axis], -1, x, y);
    }
    if (n < 2)
        return;
    mk_printf(m, "<path d=\"");
    for (int k = 0; k < n; k++)
        mk_printf(m, "%s%.2f %.2f", k ? " L" : "M", x[k], y[k]);
    mk_printf(m, " Z\" fill=\"%s\"", fill);
    if (opacity < 1)
        mk_printf(m, " fill-opacity=\"%.2f\"", opacity);
    if (strcmp(stroke, "none") != 0)
        mk_printf(m, " stroke=\"%s\" stroke-width=\"%.2g\" stroke-linejoin=\"round\"", stroke, width);
    mk_printf(m, "/>\n");
}

void fig_circle(Markup *m, const FigView *v, double cx, double cy, double R, const char *fill,
                double opacity, const char *stroke, double width)
{
    if (!(R > 0) || !isfinite(R))
        return;
    double pcx = fig_px(v, cx), pcy = fig_py(v, cy), pr = R * v->s;
    char op[40] = "";
    if (opacity < 1)
        snprintf(op, sizeof op, " fill-opacity=\"%.2f\"", opacity);
    if (pr < 2e4 && fabs(pcx) < 2e4 && fabs(pcy) < 2e4) {
        mk_printf(m, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\"%s", pcx, pcy,
                  fmax(pr, 0.8), fill, op);
        if (strcmp(stroke, "none") != 0)
            mk_printf(m, " stroke=\"%s\" stroke-width=\"%.2g\"", stroke, width);
        mk_printf(m, "/>\n");
        return;
    }
    /* A huge circle: the arc near the window's centre V.  With d = c - V
     * and n the unit vector from c towards V, the point of the circle
     * nearest V is V + (R - |d|) n, and the arc around it is
     * V + (R - |d|) n + R (-2 sin^2(phi/2) n + sin(phi) t): all small
     * numbers when the window is small, however large R. */
    double dx = cx - v->cx, dy = cy - v->cy, dist = hypot(dx, dy);
    double half = hypot(v->pw, v->ph) / 2 / v->s;         /* the window's half diagonal */
    if (!(dist > 0)) {
        if (strcmp(fill, "none") != 0)
            mk_printf(m, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"%s/>\n",
                      v->px0, v->py0, v->pw, v->ph, fill, op);
        return;
    }
    if (fabs(R - dist) > 2 * half && strcmp(fill, "none") == 0)
        return;                                           /* the arc misses the window */
    double nx = -dx / dist, ny = -dy / dist, tx = -ny, ty = nx, gap = R - dist;
    double phi_max = fmin(3.14159265358979, 3 * half / R + 1e-300);
    enum { N = 96 };
    double px[N + 1], py[N + 1];
    for (int k = 0; k <= N; k++) {
        double phi = phi_max * (2.0 * k / N - 1), sh = sin(phi / 2);
        double along = gap - 2 * R * sh * sh, side = R * sin(phi);
        px[k] = fig_px(v, v->cx) + (along * nx + side * tx) * v->s;
        py[k] = fig_py(v, v->cy) - (along * ny + side * ty) * v->s;
    }
    mk_printf(m, "<path d=\"");
    for (int k = 0; k <= N; k++)
        mk_printf(m, "%s%.2f %.2f", k ? " L" : "M", mk_clamp(px[k]), mk_clamp(py[k]));
    if (strcmp(fill, "none") != 0) {
        double deep = 3 * half * v->s;                    /* inwards, towards the centre */
        mk_printf(m, " L%.2f %.2f L%.2f %.2f Z", mk_clamp(px[N] - nx * deep), mk_clamp(py[N] + ny * deep),
                  mk_clamp(px[0] - nx * deep), mk_clamp(py[0] + ny * deep));
    }
    mk_printf(m, "\" fill=\"%s\"%s", fill, op);
    if (strcmp(stroke, "none") != 0)
        mk_printf(m, " stroke=\"%s\" stroke-width=\"%.2g\"", stroke, width);
    mk_printf(m, "/>\n");
}

void fig_begin(Markup *m, double width, double height, const char *title)
{
    mk_printf(m, "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"fig\" width=\"%.0f\" "
                 "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" role=\"img\" "
                 "font-family=\"Helvetica, Arial, sans-serif\">\n<title>", width, height, width, height);
    mk_text(m, title);
    mk_printf(m, "</title>\n<rect width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n", width, height);
}

void fig_end(Markup *m)
{
    mk_printf(m, "</svg>\n");
}

void fig_window(Markup *m, const FigView *v, const char *frame)
{
    mk_printf(m, "<svg x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
                 "viewBox=\"%.2f %.2f %.2f %.2f\" overflow=\"hidden\">\n",
              v->px0, v->py0, v->pw, v->ph, v->px0, v->py0, v->pw, v->ph);
    if (frame)
        svg_rect(m, v->px0, v->py0, v->pw, v->ph, frame, "none", 0);
}

void fig_window_end(Markup *m, const FigView *v, bool zoom)
{
    mk_printf(m, "</svg>\n");
    svg_rect(m, v->px0, v->py0, v->pw, v->ph, "none", zoom ? "#7a4fbf" : "#bbbbbb", zoom ? 1.4 : 1);
}

const char *fig_hex(char *buf, const double *rgb)
{
    int c[3];
    for (int k = 0; k < 3; k++) {
        double v = rgb[k];
        c[k] = !(v > 0) ? 0 : v >= 1 ? 255 : (int)lround(255 * v);
    }
    snprintf(buf, 8, "#%02x%02x%02x", c[0], c[1], c[2]);
    return buf;
}

const char *fig_num(char *buf, size_t len, double x, int digits)
{
    if (isnan(x))
        snprintf(buf, len, "NaN");
    else if (isinf(x))
        snprintf(buf, len, "%sinfinity", x < 0 ? "-" : "");
    else
        snprintf(buf, len, "%.*g", digits, x == 0 ? 0.0 : x);
    return buf;
}

const char *fig_times(char *buf, size_t len, double x)
{
    if (x < 1e5)
        snprintf(buf, len, "%.0f", x < 100 ? x : x < 1000 ? 10 * round(x / 10) : 100 * round(x / 100));
    else
        snprintf(buf, len, "%.1e", x);
    return buf;
}

double fig_step(double span, int n)
{
    if (!(span > 0) || !isfinite(span))
        return 1;
    double raw = span / n, p = pow(10, floor(log10(raw))), f = raw / p;
    return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}

void fig_legend(Markup *m, double x, double y, const char *want, const char *got)
{
    if (want) {
        svg_mark_want(m, x + 6, y - 4);
        svg_text(m, x + 18, y, "start", 13, COL_TEXT, false, "%s", want);
        x += 30 + 6.8 * (double)strlen(want);
    }
    if (got) {
        svg_mark_got(m, x + 8, y - 4);
        svg_text(m, x + 22, y, "start", 13, COL_TEXT, false, "%s", got);
    }
}
