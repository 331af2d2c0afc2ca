/*
 * fig_view.c - the figures of the camera: Part 1 (the view frustum from the
 * side, and the image plane face on), Part 2 (the image plane's pixel grid
 * around the pixel) and Part 3b's camera rays (the eye, the pixel and the
 * two directions).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "fig_draw.h"
#include "figures.h"
#include "fig_ray.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- Part 1 --------------------------------------------------------------------- */

/* The legend at y: the expected pair c->want[0], [1] in want_fmt, the
 * code's got[0], [1] and then got_note in got_fmt, or no answer. */
static void pair_legend(Markup *m, double y, const Case *c, const double *got, const char *want_fmt,
                        const char *got_fmt, const char *got_note)
{
    char b1[40], b2[40], wt[120], gt[160];
    snprintf(wt, sizeof wt, want_fmt, fig_num(b1, sizeof b1, c->want[0], 8), fig_num(b2, sizeof b2, c->want[1], 8));
    if (!got)
        snprintf(gt, sizeof gt, "your code: no answer");
    else
        snprintf(gt, sizeof gt, got_fmt, fig_num(b1, sizeof b1, got[0], 8), fig_num(b2, sizeof b2, got[1], 8),
                 got_note);
    fig_legend(m, 12, y, wt, gt);
}

void fig_plane(Markup *m, const Test *t, const Case *c, const double *got)
{
    (void)t;
    double fov = c->in[0], aspect = c->in[1], d = c->in[2];
    double ww = c->want[0], hw = c->want[1];
    /* a returned size is drawn if it is a finite number > 0 */
    bool wg_ok = got && got[0] > 0 && isfinite(got[0]), hg_ok = got && got[1] > 0 && isfinite(got[1]);
    double wg = wg_ok ? got[0] : 0, hg = hg_ok ? got[1] : 0;
    char b1[40], b2[40];
    fig_begin(m, 760, 336, "the view frustum from the side, and the image plane face on");
    svg_text(m, 10, 19, "start", 14, COL_TEXT, true, "From the side: the eye and the image plane");
    svg_text(m, 470, 19, "start", 14, COL_TEXT, true, "The image plane, face on");

    /* the side view: the eye at the left, looking right (down -z) */
    double hmax = fmax(hw, hg_ok && hg <= 50 * hw ? hg : 0);
    FigView v;
    fig_fit(&v, -d * 0.12, -hmax / 2, d * 1.18, hmax / 2, 0.08, 10, 30, 440, 250);
    fig_window(m, &v, "#fbfbfb");
    double ex = fig_px(&v, 0), ey = fig_py(&v, 0);
    double reach = d * 1.18, half = tan(fov / 2 * PI / 180);
    fig_segment(m, &v, 0, 0, reach, 0, "#999999", 1, "4 4");               /* the axis */
    if (isfinite(half) && half > 0) {
        fig_segment(m, &v, 0, 0, reach, reach * half, "#444444", 1.2, NULL);
        fig_segment(m, &v, 0, 0, reach, -reach * half, "#444444", 1.2, NULL);
    }
    double px = fig_px(&v, d);
    svg_line(m, px - 2, fig_py(&v, hw / 2), px - 2, fig_py(&v, -hw / 2), COL_WANT, 4, NULL);
    if (hg_ok)
        svg_line(m, px + 4, fig_py(&v, hg / 2), px + 4, fig_py(&v, -hg / 2), COL_GOT, 3, "6 3");
    svg_circle(m, ex, ey, 4, "#222222", "none", 0);
    fig_window_end(m, &v, false);
    svg_text(m, ex - 6, ey + 4, "end", 13, COL_TEXT, true, "eye");
    svg_text(m, 16, 274, "start", 12, COL_TEXT, false, "fov = %s\xC2\xB0 (the angle between the "
             "lines), d = %s", fig_num(b1, sizeof b1, fov, 8), fig_num(b2, sizeof b2, d, 6));
    double top = fig_py(&v, hw / 2);
    svg_text(m, fmin(px + 10, 440), fmax(top + 12, 46), "start", 12, COL_WANT, true, "expected h");
    if (hg_ok)
        svg_text(m, fmin(px + 10, 440), fmin(fig_py(&v, -hg / 2) - 2, 274), "start", 12, COL_GOT, true,
                 "your h");
    if (hmax * v.s < 4 || d * v.s < 4)
        svg_text(m, 16, 46, "start", 11, COL_NOTE, false, "%s is too small to see%s at this scale",
                 hmax * v.s < 4 ? "the plane" : "d", hmax * v.s < 4 ? "" : " beside h");
    if (hg_ok && hg != hw && fabs(hg - hw) * v.s < 2)
        svg_text(m, 16, 60, "start", 11, COL_NOTE, false, "the two h differ by %s of h: drawn side by "
                 "side to show both", fig_num(b1, sizeof b1, fabs(hg - hw) / hw, 2));

    /* face on: the expected and the returned rectangle, centred */
    double big = fmax(fmax(ww, hw), fmax(wg_ok && wg <= 50 * ww ? wg : 0, hg_ok && hg <= 50 * hw ? hg : 0));
    FigView f;
    fig_fit(&f, -big / 2, -big / 2, big / 2, big / 2, 0.1, 470, 30, 280, 250);
    fig_window(m, &f, "#fbfbfb");
    fig_segment(m, &f, -big, 0, big, 0, COL_GRID, 1, NULL);
    fig_segment(m, &f, 0, -big, 0, big, COL_GRID, 1, NULL);
    /* a side too short to see is drawn 2 pixels long */
    svg_rect(m, fig_px(&f, 0) - fmax(ww * f.s, 2) / 2, fig_py(&f, 0) - fmax(hw * f.s, 2) / 2,
             fmax(ww * f.s, 2), fmax(hw * f.s, 2), "#dbe6f6", COL_WANT, 3);
    if (ww * f.s > 30 && hw * f.s > 30) {
        svg_text(m, fig_px(&f, 0), fig_py(&f, -hw / 2) - 6, "middle", 12, COL_WANT, true, "w");
        svg_text(m, fig_px(&f, ww / 2) - 8, fig_py(&f, 0) + 4, "end", 12, COL_WANT, true, "h");
    }
    if (wg_ok && hg_ok)
        svg_rect(m, fig_px(&f, 0) - fmax(wg * f.s, 2) / 2, fig_py(&f, 0) - fmax(hg * f.s, 2) / 2,
                 fmax(wg * f.s, 2), fmax(hg * f.s, 2), "none", COL_GOT, 2.5);
    fig_window_end(m, &f, false);
    svg_text(m, 476, 276, "start", 11, COL_NOTE, false, "aspect = nx / ny = %s: w = aspect x h",
             fig_num(b1, sizeof b1, aspect, 6));
    if (hw * f.s < 2 || ww * f.s < 2)
        svg_text(m, 476, 46, "start", 11, COL_NOTE, false, "too thin to see: drawn as a line");

    pair_legend(m, 306, c, got, "expected: w = %s, h = %s", "your code: w = %s, h = %s%s",
                wg_ok && hg_ok ? "" : " (not a size > 0: not drawn)");
    svg_text(m, 12, 328, "start", 11, COL_NOTE, false, "Drawn to scale: h = 2 d tan(fov / 2) is the "
             "plane's height; the lines from the eye are the edges of the field of view.");
    fig_end(m);
}

/* ---- Part 2 --------------------------------------------------------------------- */

/* A Part 2 case on the image plane, and where the two points are on it. */
typedef struct {
    int i, j, nx, ny;           /* the pixel, of nx x ny                     */
    double w, h;                /* the plane's size                          */
    double pw, ph;              /* a pixel's size on the plane               */
    double xw, yw, xg, yg;      /* the expected and the returned point (0, 0
                                   when there is none)                       */
    double Xw, Yw, Xg, Yg;      /* the same in pixels: columns from the left,
                                   rows from the top                         */
    bool have;                  /* a returned point, finite                  */
    bool whole;                 /* it is so far off the figure shows the whole
                                   plane                                     */
    bool far;                   /* it is too far off to draw                 */
} PixelCase;

static PixelCase pixel_case(const Case *c, const double *got)
{
    bool have = got && isfinite(got[0]) && isfinite(got[1]);
    PixelCase pc = { .i = (int)c->in[0], .j = (int)c->in[1], .nx = (int)c->in[2], .ny = (int)c->in[3],
                     .w = c->in[4], .h = c->in[5], .xw = c->want[0], .yw = c->want[1],
                     .xg = have ? got[0] : 0, .yg = have ? got[1] : 0, .have = have };
    pc.pw = pc.w / pc.nx;
    pc.ph = pc.h / pc.ny;
    pc.Xw = (pc.xw + pc.w / 2) / pc.pw, pc.Yw = (pc.h / 2 - pc.yw) / pc.ph;
    pc.Xg = (pc.xg + pc.w / 2) / pc.pw, pc.Yg = (pc.h / 2 - pc.yg) / pc.ph;
    double dX = fabs(pc.Xg - pc.Xw), dY = fabs(pc.Yg - pc.Yw);
    pc.whole = have && fmax(dX, dY) > 24;       /* the offset is large: the whole plane */
    pc.far = have && dX + dY > 60.0 * (pc.nx + pc.ny);
    return pc;
}

/* The figure's view of the plane (its x and y): the whole plane and both
 * points, or the pixels around the expected one (and the returned one,
 * where it is near). */
static void fit_pixel_view(FigView *v, const PixelCase *pc)
{
    double w = pc->w, h = pc->h, pw = pc->pw, ph = pc->ph;
    double xw = pc->xw, yw = pc->yw, xg = pc->xg, yg = pc->yg;
    double x0, y0, x1, y1;
    if (pc->whole && !pc->far) {
        x0 = fmin(-w / 2, fmin(xw, xg)), x1 = fmax(w / 2, fmax(xw, xg));
        y0 = fmin(-h / 2, fmin(yw, yg)), y1 = fmax(h / 2, fmax(yw, yg));
    } else {
        double ci = pc->i + 0.5, cj = pc->j + 0.5;
        double X0 = ci - 2.5, X1 = ci + 2.5, Y0 = cj - 2, Y1 = cj + 2;
        if (pc->have && !pc->far) {
            double Xg = pc->Xg, Yg = pc->Yg;
            X0 = fmin(X0, Xg - 1), X1 = fmax(X1, Xg + 1), Y0 = fmin(Y0, Yg - 1), Y1 = fmax(Y1, Yg + 1);
        }
        x0 = -w / 2 + X0 * pw, x1 = -w / 2 + X1 * pw;
        y0 = h / 2 - Y1 * ph, y1 = h / 2 - Y0 * ph;
    }
    fig_fit(v, x0, y0, x1, y1, 0.05, 10, 30, 740, 250);
}

/* The pixel grid's lines in view: columns ia to ib and rows ja to jb, a
 * line drawn every every-th column and every every_j-th row. */
typedef struct {
    int ia, ib, ja, jb;
    int every, every_j;
} GridLines;

/* Draws the plane, the pixel, the grid's lines and the plane's axes in v. */
static GridLines draw_pixel_grid(Markup *m, const FigView *v, const PixelCase *pc)
{
    int i = pc->i, j = pc->j, nx = pc->nx, ny = pc->ny;
    double w = pc->w, h = pc->h, pw = pc->pw, ph = pc->ph;
    GridLines g;
    svg_rect(m, fig_px(v, -w / 2), fig_py(v, h / 2), w * v->s, h * v->s, "#f3f3f3", "none", 0);
    svg_rect(m, fig_px(v, -w / 2 + i * pw), fig_py(v, h / 2 - j * ph), pw * v->s, ph * v->s, "#fff1b8",
             "none", 0);
    double vx0 = v->cx - v->pw / 2 / v->s, vx1 = v->cx + v->pw / 2 / v->s;
    double vy0 = v->cy - v->ph / 2 / v->s, vy1 = v->cy + v->ph / 2 / v->s;
    g.ia = (int)fmax(0, floor((vx0 + w / 2) / pw)), g.ib = (int)fmin(nx, ceil((vx1 + w / 2) / pw));
    g.ja = (int)fmax(0, floor((h / 2 - vy1) / ph)), g.jb = (int)fmin(ny, ceil((h / 2 - vy0) / ph));
    /* every line, or every 2nd, 4th ... where they would crowd (each way on its own) */
    g.every = 1, g.every_j = 1;
    while ((g.ib - g.ia) / g.every > 48)
        g.every *= 2;
    while ((g.jb - g.ja) / g.every_j > 48)
        g.every_j *= 2;
    for (int k = g.ia - g.ia % g.every; k <= g.ib; k += g.every)
        fig_segment(m, v, -w / 2 + k * pw, fmax(-h / 2, vy0), -w / 2 + k * pw, fmin(h / 2, vy1),
                    k == 0 || k == nx ? "#555555" : COL_GRID, k == 0 || k == nx ? 2 : 1, NULL);
    for (int k = g.ja - g.ja % g.every_j; k <= g.jb; k += g.every_j)
        fig_segment(m, v, fmax(-w / 2, vx0), h / 2 - k * ph, fmin(w / 2, vx1), h / 2 - k * ph,
                    k == 0 || k == ny ? "#555555" : COL_GRID, k == 0 || k == ny ? 2 : 1, NULL);
    /* the plane's axes (x = 0, y = 0) */
    fig_segment(m, v, 0, vy0, 0, vy1, "#9a9a9a", 1, "3 3");
    fig_segment(m, v, vx0, 0, vx1, 0, "#9a9a9a", 1, "3 3");
    return g;
}

/* The column and row numbers along the window's edges, where there is room. */
static void number_grid(Markup *m, const FigView *v, const PixelCase *pc, const GridLines *g)
{
    double w = pc->w, h = pc->h, pw = pc->pw, ph = pc->ph;
    if (!pc->whole || g->every <= 4)
        for (int k = g->ia; k < g->ib; k += g->every) {
            double px = fig_px(v, -w / 2 + (k + 0.5) * pw);
            if (px > v->px0 + 10 && px < v->px0 + v->pw - 10 && pw * g->every * v->s > 24)
                svg_text(m, px, 44, "middle", 11, k == pc->i ? COL_TEXT : COL_NOTE, k == pc->i, "i=%d", k);
        }
    for (int k = g->ja; k < g->jb; k += g->every_j) {
        double py = fig_py(v, h / 2 - (k + 0.5) * ph);
        if (py > v->py0 + 20 && py < v->py0 + v->ph - 6 && ph * g->every_j * v->s > 16)
            svg_text(m, v->px0 + 4, py + 4, "start", 11, k == pc->j ? COL_TEXT : COL_NOTE, k == pc->j,
                     "j=%d", k);
    }
}

/* The line that says how far, in pixel widths and heights, the returned
 * point is from the expected centre. */
static void offset_caption(Markup *m, const FigView *v, const PixelCase *pc)
{
    char b1[40], b2[40], how[200] = "";
    double dx = (pc->Xg - pc->Xw), dy = (pc->Yg - pc->Yw);
    if (dx != 0)
        snprintf(how, sizeof how, "%s pixel width%s to the %s", fig_num(b1, sizeof b1, fabs(dx), 3),
                 fabs(dx) == 1 ? "" : "s", dx < 0 ? "left" : "right");
    if (dy != 0)
        snprintf(how + strlen(how), sizeof how - strlen(how), "%s%s pixel height%s %s",
                 dx != 0 ? " and " : "", fig_num(b2, sizeof b2, fabs(dy), 3), fabs(dy) == 1 ? "" : "s",
                 dy < 0 ? "above" : "below");
    if (dx == 0 && dy == 0)
        svg_text(m, 12, 298, "start", 12, COL_TEXT, false, "your x and y are right");
    else
        svg_text(m, 12, 298, "start", 12, COL_TEXT, false, "your point is %s the expected centre%s",
                 how, pc->far ? " (far off the figure)" : hypot(dx * pc->pw, dy * pc->ph) * v->s < 3
                 ? " (too close to draw apart)" : "");
}

void fig_pixel(Markup *m, const Test *t, const Case *c, const double *got)
{
    (void)t;
    PixelCase pc = pixel_case(c, got);
    double pw = pc.pw, ph = pc.ph, d = c->in[6];
    char b1[40], b2[40];
    fig_begin(m, 760, 356, "the image plane's pixel grid with the expected and the returned pixel centre");
    svg_text(m, 10, 19, "start", 14, COL_TEXT, true, pc.whole ? "The whole image plane (%dx%d pixels), "
             "with pixel (%d, %d)" : "The image plane's pixels around pixel (i = %d, j = %d)",
             pc.whole ? pc.nx : pc.i, pc.whole ? pc.ny : pc.j, pc.i, pc.j);
    FigView v;
    fit_pixel_view(&v, &pc);
    fig_window(m, &v, "#ffffff");
    GridLines g = draw_pixel_grid(m, &v, &pc);
    double pwx = fig_px(&v, pc.xw), pwy = fig_py(&v, pc.yw);
    if (pc.have && !pc.far) {
        double pgx = fig_px(&v, pc.xg), pgy = fig_py(&v, pc.yg);
        if (hypot(pgx - pwx, pgy - pwy) > 12)
            svg_arrow(m, pwx, pwy, pgx, pgy, COL_GOT, 1.8, "5 3");
        svg_mark_got(m, pgx, pgy);
    }
    svg_mark_want(m, pwx, pwy);
    fig_window_end(m, &v, false);
    number_grid(m, &v, &pc, &g);
    if (pc.have)
        offset_caption(m, &v, &pc);
    if (pw > 4 * ph || ph > 4 * pw)
        svg_text(m, v.px0 + v.pw - 6, v.py0 + v.ph - 6, "end", 11, COL_NOTE, false,
                 "drawn to scale: these pixels are %s times %s than %s", fig_times(b1, sizeof b1,
                 pw > ph ? pw / ph : ph / pw), pw > ph ? "wider" : "taller", pw > ph ? "tall" : "wide");
    if (got && got[2] != c->want[2])
        svg_text(m, 12, 316, "start", 12, COL_GOT, true, "z: expected -d = %s, yours %s",
                 fig_num(b1, sizeof b1, -d, 8), fig_num(b2, sizeof b2, got[2], 8));
    pair_legend(m, 340, c, got, "expected centre (%s, %s)", "your point (%s, %s)%s", "");
    fig_end(m);
}

/* ---- Part 3b: camera rays -------------------------------------------------------- */

/* The drawing's plane, through the eye E: ux along the expected direction
 * dw, uy square to it, towards what the returned ray (got, or none) adds
 * across it, or any way square to ux where it adds nothing across. */
static void camera_frame(const double *E, const double *dw, const double *got, double *ux, double *uy)
{
    double across[3];
    for (int k = 0; k < 3; k++) {
        ux[k] = dw[k];
        across[k] = got ? got[3 + k] + (got[k] - E[k]) : 0;
    }
    double along = ray_dot(across, ux);
    for (int k = 0; k < 3; k++)
        uy[k] = across[k] - along * ux[k];
    double ny = ray_norm(uy);
    if (!(ny > 1e-12 * fmax(1, ray_norm(across))) || !isfinite(ny)) {
        /* nothing across: any direction square to ux */
        double a[3] = { fabs(ux[0]) < 0.9 ? 1 : 0, fabs(ux[0]) < 0.9 ? 0 : 1, 0 };
        double dd = a[0] * ux[0] + a[1] * ux[1];
        for (int k = 0; k < 3; k++)
            uy[k] = a[k] - dd * ux[k];
        ny = ray_norm(uy);
    }
    for (int k = 0; k < 3; k++)
        uy[k] /= ny;
}

/* The line at y on the returned ray: its direction's length glen, its
 * angle from the expected one (gx: its length along it), how far from the
 * eye it starts (start) and whether it points out of the drawing (off:
 * its length square to the drawing's plane). */
static void camera_caption(Markup *m, double y, double glen, double gx, double start, double off)
{
    char b1[40], b2[40], b3[20];
    double cosang = (gx * 1) / (glen > 0 ? glen : 1);
    double ang = acos(fmax(-1, fmin(1, cosang))) * 180 / PI;
    svg_text(m, 12, y, "start", 12, COL_TEXT, false, "your direction: length %s (should be 1), "
             "%s\xC2\xB0 from the expected one; your ray starts %s from the eye%s",
             fig_num(b1, sizeof b1, glen, 6), fig_num(b2, sizeof b2, ang, 3),
             fig_num(b3, sizeof b3, start, 3),
             off > 1e-6 * glen ? " (part of it points out of this drawing)" : "");
}

void fig_camera(Markup *m, const Test *t, const Case *c, const double *got)
{
    (void)t;
    const double *E = c->in, *P = c->in + 3, *dw = c->want + 3;
    char b1[40];
    double ux[3], uy[3];
    camera_frame(E, dw, got, ux, uy);
    /* 2D coordinates relative to the eye: (v . ux, v . uy) */
    double rel[3], ox = 0, oy = 0, gx = 0, gy = 0, glen = 0, off = 0;
    for (int k = 0; k < 3; k++)
        rel[k] = P[k] - E[k];
    double pd = ray_norm(rel), ppx = ray_dot(rel, ux), ppy = ray_dot(rel, uy);
    bool have = got && isfinite(got[0] + got[1] + got[2] + got[3] + got[4] + got[5]);
    if (have) {
        double o[3] = { got[0] - E[0], got[1] - E[1], got[2] - E[2] };
        ox = ray_dot(o, ux), oy = ray_dot(o, uy);
        gx = ray_dot(got + 3, ux), gy = ray_dot(got + 3, uy);
        glen = ray_norm(got + 3);
        double rest = glen * glen - gx * gx - gy * gy;
        off = rest > 0 ? sqrt(rest) : 0;              /* out of the drawing's plane */
    }
    double reach = 1.3;
    if (pd <= 8)
        reach = fmax(reach, pd * 1.1);
    if (have)           /* the returned ray, from where it starts if that is near */
        reach = fmax(reach, (hypot(ox, oy) <= 8 ? hypot(ox, oy) : 0) + fmin(glen, 8) * 1.05);
    fig_begin(m, 760, 356, "the eye, the pixel and the expected and returned ray direction");
    svg_text(m, 10, 19, "start", 14, COL_TEXT, true, "The plane of the eye, the pixel and the two "
             "rays (the dashed circle has radius 1)");
    FigView v;
    fig_fit(&v, -reach, -reach * 0.55, reach, reach * 0.55, 0.04, 10, 30, 740, 260);
    fig_window(m, &v, "#fbfbfb");
    mk_printf(m, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"none\" stroke=\"#8a8a8a\" "
                 "stroke-width=\"1.2\" stroke-dasharray=\"5 4\"/>\n", fig_px(&v, 0), fig_py(&v, 0), v.s);
    fig_segment(m, &v, -reach * 3, 0, reach * 3, 0, COL_GRID, 1, NULL);
    if (fig_inside(&v, ppx, ppy)) {
        svg_rect(m, fig_px(&v, ppx) - 5, fig_py(&v, ppy) - 5, 10, 10, "#222222", "none", 0);
        svg_text(m, fig_px(&v, ppx) + 8, fig_py(&v, ppy) - 8, "start", 13, COL_TEXT, true, "pixel");
    }
    svg_arrow(m, fig_px(&v, 0), fig_py(&v, 0), fig_px(&v, 1), fig_py(&v, 0), COL_WANT, 3.5, NULL);
    if (have) {
        double sx = fig_px(&v, ox), sy = fig_py(&v, oy);
        double ex = fig_px(&v, ox + gx), ey = fig_py(&v, oy + gy);
        svg_arrow(m, sx, sy, ex, ey, COL_GOT, 2.5, "7 4");
        svg_mark_got(m, sx, sy);
    }
    svg_circle(m, fig_px(&v, 0), fig_py(&v, 0), 4.5, "#222222", "none", 0);
    svg_text(m, fig_px(&v, 0) - 8, fig_py(&v, 0) - 9, "end", 13, COL_TEXT, true, "eye");
    fig_window_end(m, &v, false);
    if (!fig_inside(&v, ppx, ppy))
        svg_text(m, v.px0 + v.pw - 8, fig_py(&v, 0) - 8, "end", 12, COL_TEXT, true,
                 "the pixel is %s away, this way \xE2\x86\x92", fig_num(b1, sizeof b1, pd, 4));
    if (have)
        camera_caption(m, 308, glen, gx, hypot(ox, oy), off);
    else if (got)
        svg_text(m, 12, 308, "start", 12, COL_GOT, false, "your ray has a number that is not finite "
                 "(NaN or infinity): not drawn");
    fig_legend(m, 12, 334, "expected: starts at the eye, unit length, towards the pixel",
               got ? "your ray: where it starts and its direction" : "your code: no answer");
    fig_end(m);
}
