/*
 * fig_flat.c - the figures of flat things: Part 4 (a plane, seen edge on in
 * the plane of the ray and the plane's normal) and Part 5 (a triangle, or a
 * closed mesh, seen along the ray: the vertices projected on the plane
 * square to the ray, where the ray is a point, so that a ray through an
 * edge shows as a point on that edge).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "fig_draw.h"
#include "figures.h"
#include "fig_ray.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* u = v / |v|; false when v is zero or not finite. */
static bool unit3(const double *v, double *u)
{
    double n = ray_norm(v);
    if (!(n > 0) || !isfinite(n))
        return false;
    for (int k = 0; k < 3; k++)
        u[k] = v[k] / n;
    return true;
}

/* Two unit vectors p, q square to the unit vector u and to each other,
 * the way an eye looking along u sees them: p to its right, q up (p x q =
 * -u, so a picture drawn with p right and q up is not a mirror image),
 * and q as near the world's +y as u allows (the lab's camera looks down
 * -z with +y up, so a camera ray's picture is upright as in the render). */
static void square_to(const double *u, double *p, double *q)
{
    double up[3] = { 0, 1, 0 };
    if (fabs(u[1]) > 0.9)               /* looking up (down), the head tilted back (forward) */
        up[1] = 0, up[2] = u[1] > 0 ? 1 : -1;
    double along = ray_dot(up, u);
    for (int k = 0; k < 3; k++)
        q[k] = up[k] - along * u[k];
    unit3(q, q);
    p[0] = u[1] * q[2] - u[2] * q[1];   /* p = u x q */
    p[1] = u[2] * q[0] - u[0] * q[2];
    p[2] = u[0] * q[1] - u[1] * q[0];
}

/* The legend at y: the expected answer (a hit's followed by "(or a miss)"
 * where either is right) and the code's. */
static void answer_legend(Markup *m, double y, const Case *c, const double *got)
{
    char b[40], wt[120], gt[120];
    if (c->want[0] != 0)
        snprintf(wt, sizeof wt, "expected: a hit at t = %s%s", fig_num(b, sizeof b, c->want[1], 10),
                 c->flags & CASE_EITHER_HIT ? " (or a miss)" : "");
    else
        snprintf(wt, sizeof wt, "expected: a miss");
    if (!got)
        snprintf(gt, sizeof gt, "your code: no answer");
    else if (got[0] == 1)
        snprintf(gt, sizeof gt, "your code: a hit at t = %s", fig_num(b, sizeof b, got[1], 10));
    else
        snprintf(gt, sizeof gt, "your code: %s", got[0] == 0 ? "a miss" : "neither true nor false");
    fig_legend(m, 12, y, wt, gt);
}

/* A figure with no drawing: the input itself makes the answer a miss. */
static void plain_figure(Markup *m, const char *title, const char *line1, const char *line2,
                         const Case *c, const double *got)
{
    fig_begin(m, 760, 100, title);
    svg_text(m, 12, 28, "start", 14, COL_TEXT, true, "%s", line1);
    svg_text(m, 12, 50, "start", 13, COL_TEXT, false, "%s", line2);
    answer_legend(m, 84, c, got);
    fig_end(m);
}

/* The plain figure of an input that makes the answer a miss whatever the
 * shape (what: "plane", "triangle"): a NaN among its nin numbers, or a ray
 * r with no direction.  Returns whether it drew one; if not, u is r's unit
 * vector. */
static bool plain_ray_figure(Markup *m, const Case *c, int nin, const double *r, double *u, const char *what,
                             const double *got)
{
    for (int k = 0; k < nin; k++)
        if (isnan(c->in[k])) {
            plain_figure(m, "NaN input", "A number of the input is NaN (not a number).",
                         "No point can be computed from it: the answer must be a miss.", c, got);
            return true;
        }
    if (!unit3(r, u)) {
        char line[100];
        snprintf(line, sizeof line, "A ray that goes nowhere meets no %s: the answer must be a miss.", what);
        plain_figure(m, "no direction", "The ray has no direction: r = (0, 0, 0).", line, c, got);
        return true;
    }
    return false;
}

/* ---- Part 4 ----------------------------------------------------------------------- */

/* (p - e) . n / |n|, the height of e below the plane through p with normal
 * n, to a few units in its last place however small it is against |p - e|:
 * an origin 1e-12 off the plane, 80 from p, lost a hundredth of its height
 * to the rounding of p - e, and the plane was drawn 2 to 5 pixels off the
 * hit it was drawn for.  Each difference is split into its rounded value
 * and that rounding's error (TwoSum, exact), and the six products are
 * summed as if in twice the precision (Ogita, Rump and Oishi's Dot2: each
 * product's error from fma, each sum's from TwoSum). */
static double plane_height(const double *p, const double *n, const double *e)
{
    /* n scaled by a power of two (exactly) to about 1, so that no product
     * underflows; a rounded unit normal would tilt the plane about p by
     * as much as the rounding of p - e moves it */
    int ex;
    frexp(fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2]))), &ex);
    double x[6], y[6], ns[3], sum = 0, err = 0;
    for (int k = 0; k < 3; k++) {
        double d = p[k] - e[k], back = d - p[k];
        x[k] = d;
        x[k + 3] = (p[k] - (d - back)) + (-e[k] - back);
        ns[k] = y[k] = y[k + 3] = ldexp(n[k], -ex);
    }
    for (int k = 0; k < 6; k++) {
        double h = x[k] * y[k], r = fma(x[k], y[k], -h);
        double s = sum + h, bb = s - sum;
        err += ((sum - (s - bb)) + (h - bb)) + r;
        sum = s;
    }
    double height = (sum + err) / ray_norm(ns);
    if (isfinite(height))
        return height;
    double nh[3];                       /* too large for the pieces: as it comes */
    unit3(n, nh);
    return (p[0] - e[0]) * nh[0] + (p[1] - e[1]) * nh[1] + (p[2] - e[2]) * nh[2];
}

void fig_planehit(Markup *m, const Test *t, const Case *c, const double *got)
{
    (void)t;
    const double *p = c->in, *n = c->in + 3, *e = c->in + 6, *r = c->in + 9;
    double u[3], nh[3];
    if (plain_ray_figure(m, c, 12, r, u, "plane", got))
        return;
    if (!unit3(n, nh)) {
        plain_figure(m, "no normal", "The plane's normal is zero: there is no plane.",
                     "The answer must be a miss.", c, got);
        return;
    }
    /* the drawing's plane: u, and the part of the normal square to u */
    double along = ray_dot(nh, u), v[3], q[3];
    for (int k = 0; k < 3; k++)
        v[k] = nh[k] - along * u[k];
    if (!unit3(v, v))
        square_to(u, v, q);                     /* the normal is along the ray */
    RayFig f = { .title = "The plane seen edge on (the thick line), in the plane of the ray and the "
                          "plane's normal",
                 .rlen = ray_norm(r), .target = -1, .has_line = true,
                 .line_A = along, .line_B = ray_dot(nh, v), .line_C = plane_height(p, n, e) };
    ray_answers(&f, c->want, got, c->flags & CASE_EITHER_HIT ? "within rounding" : NULL);
    f.note = along < 0 ? "The ray comes at the plane from the side its normal points to (r.n < 0)."
             : along > 0 ? "The ray comes at the plane from behind, against its normal (r.n > 0)."
             : f.line_C == 0 ? "The ray is parallel to the plane (r.n = 0), and lies in it ((p - e).n = 0)."
             : "The ray is parallel to the plane (r.n = 0).";
    ray_figure(m, &f);
}

/* ---- Part 5 ----------------------------------------------------------------------- */

typedef struct {
    double x[3], y[3];          /* the vertices, projected (the ray at 0, 0) */
    double t;                   /* where the ray's line meets its plane      */
    bool crossed;               /* the ray's point is inside or on it        */
} Flat;

/* Projects the triangle v (a, b, c) seen along the ray. */
static void project(const double *v, const double *e, const double *r, const double *p,
                    const double *q, Flat *out)
{
    for (int k = 0; k < 3; k++) {
        double d[3] = { v[3 * k] - e[0], v[3 * k + 1] - e[1], v[3 * k + 2] - e[2] };
        out->x[k] = ray_dot(d, p);
        out->y[k] = ray_dot(d, q);
    }
    /* the signs of the ray's point against the three edges */
    double s[3];
    for (int k = 0; k < 3; k++) {
        int l = (k + 1) % 3;
        s[k] = out->x[k] * out->y[l] - out->y[k] * out->x[l];
    }
    out->crossed = (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
    /* t of the plane: (a - e) . N / (r . N) */
    double ab[3], ac[3], N[3], ae[3];
    for (int k = 0; k < 3; k++) {
        ab[k] = v[3 + k] - v[k];
        ac[k] = v[6 + k] - v[k];
        ae[k] = v[k] - e[k];
    }
    N[0] = ab[1] * ac[2] - ab[2] * ac[1];
    N[1] = ab[2] * ac[0] - ab[0] * ac[2];
    N[2] = ab[0] * ac[1] - ab[1] * ac[0];
    out->t = ray_dot(ae, N) / ray_dot(r, N);
}

/* The distance from the origin to the segment (x0, y0) - (x1, y1). */
static double seg_dist(double x0, double y0, double x1, double y1)
{
    double dx = x1 - x0, dy = y1 - y0, l2 = dx * dx + dy * dy;
    double s = l2 > 0 ? -(x0 * dx + y0 * dy) / l2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    return hypot(x0 + s * dx, y0 + s * dy);
}

/* Draws the projected triangles in v: those the ray goes through in yellow,
 * the others grey; a single triangle's vertices named a, b, c. */
static void draw_flats(Markup *m, const FigView *v, const Flat *fl, int nf, bool labels)
{
    static const char *const names[3] = { "a", "b", "c" };
    for (int k = 0; k < nf; k++) {
        const Flat *f = &fl[k];
        /* the fill clipped, then each edge on its own (a clipped outline
         * would draw the window's edge too) */
        fig_polygon(m, v, f->x, f->y, 3, f->crossed ? "#f2c14e" : "#c9c9c9", nf > 1 ? 0.35 : 0.6, "none", 0);
        for (int q = 0; q < 3; q++)
            fig_segment(m, v, f->x[q], f->y[q], f->x[(q + 1) % 3], f->y[(q + 1) % 3], "#333333",
                        f->crossed ? 1.6 : 1, NULL);
        if (labels && nf == 1)
            for (int q = 0; q < 3; q++)
                if (fig_inside(v, f->x[q], f->y[q])) {
                    double cx = (f->x[0] + f->x[1] + f->x[2]) / 3, cy = (f->y[0] + f->y[1] + f->y[2]) / 3;
                    double dx = fig_px(v, f->x[q]) - fig_px(v, cx), dy = fig_py(v, f->y[q]) - fig_py(v, cy);
                    double l = hypot(dx, dy) > 0 ? hypot(dx, dy) : 1;
                    svg_text(m, fig_px(v, f->x[q]) + 12 * dx / l, fig_py(v, f->y[q]) + 12 * dy / l + 4,
                             "middle", 13, COL_TEXT, true, "%s", names[q]);
                }
    }
}

/* How far the projected triangles reach: the box around every vertex and
 * the ray's point (0, 0), the ray's distance to the nearest edge, and
 * whether the ray passes exactly through a vertex. */
typedef struct {
    double x0, y0, x1, y1;
    double near;
    bool vertex;
} Extent;

static Extent flats_extent(const Flat *fl, int nf)
{
    Extent x = { 0, 0, 0, 0, INFINITY, false };
    for (int k = 0; k < nf; k++)
        for (int v = 0; v < 3; v++) {
            x.vertex = x.vertex || (fl[k].x[v] == 0 && fl[k].y[v] == 0);
            x.x0 = fmin(x.x0, fl[k].x[v]), x.x1 = fmax(x.x1, fl[k].x[v]);
            x.y0 = fmin(x.y0, fl[k].y[v]), x.y1 = fmax(x.y1, fl[k].y[v]);
            x.near = fmin(x.near, seg_dist(fl[k].x[v], fl[k].y[v], fl[k].x[(v + 1) % 3],
                                           fl[k].y[(v + 1) % 3]));
        }
    return x;
}

/* The figure's windows: w[0] the whole extent, and where the ray passes
 * close to an edge, w[1] zoomed in on the ray beside it.  Returns how
 * many (1 or 2). */
static int fit_windows(FigView w[2], const Extent *x)
{
    fig_fit(&w[0], x->x0, x->y0, x->x1, x->y1, 0.12, 10, 30, 740, 240);
    if (x->near * w[0].s < 6) {
        /* the ray passes close to an edge: look closer */
        double h = x->near > 0 ? 8 * x->near : 0.02 * fmax(x->x1 - x->x0, x->y1 - x->y0);
        FigView z;
        fig_fit(&z, -h, -h, h, h, 0, 500, 30, 250, 240);
        if (z.s > 4 * w[0].s) {
            w[1] = z;
            fig_fit(&w[0], x->x0, x->y0, x->x1, x->y1, 0.12, 10, 30, 480, 240);
            return 2;
        }
    }
    return 1;
}

/* Window k of w: the triangles, the ray's cross with the expected and the
 * returned hit on it; the zoom (k = 1) says how far it zooms and how near
 * the nearest edge is. */
static void draw_window(Markup *m, const FigView *w, int k, const Flat *fl, int nf, const Extent *x,
                        const Case *c, const double *got)
{
    char b1[40], b2[40];
    const FigView *v = &w[k];
    fig_window(m, v, k ? "#f8f5fd" : "#fbfbfb");
    draw_flats(m, v, fl, nf, k == 0);
    double ox = fig_px(v, 0), oy = fig_py(v, 0);
    svg_line(m, ox - 9, oy, ox + 9, oy, "#222222", 1.2, NULL);
    svg_line(m, ox, oy - 9, ox, oy + 9, "#222222", 1.2, NULL);
    bool want_hit = c->want[0] != 0, got_hit = got && got[0] == 1;
    if (want_hit)
        svg_mark_want(m, ox - (got_hit ? 7 : 0), oy);
    if (got_hit)
        svg_mark_got(m, ox + (want_hit ? 7 : 0), oy);
    fig_window_end(m, v, k > 0);
    if (k == 1) {
        svg_text(m, v->px0 + 6, v->py0 + 16, "start", 12, "#7a4fbf", true, "zoomed in %s times on the ray",
                 fig_times(b1, sizeof b1, v->s / w[0].s));
        if (x->near > 0)
            svg_text(m, v->px0 + 6, v->py0 + v->ph - 8, "start", 11, COL_NOTE, false,
                     "the nearest edge is %s away", fig_num(b2, sizeof b2, x->near, 2));
        else
            svg_text(m, v->px0 + 6, v->py0 + v->ph - 8, "start", 11, COL_NOTE, false,
                     "the ray passes exactly through %s", x->vertex ? "a vertex" : "an edge");
    }
}

/* The two lines below the windows, at y: what the ray's line meets, by t,
 * and (a single triangle) which side the ray comes from. */
static void triangle_caption(Markup *m, double y, const Flat *fl, int nf, bool mesh)
{
    char b1[40];
    int ncross = 0;
    for (int k = 0; k < nf; k++)
        ncross += fl[k].crossed;
    if (mesh) {
        char list[300] = "";
        for (int k = 0, shown = 0; k < nf && shown < 6; k++)
            if (fl[k].crossed) {
                size_t len = strlen(list);
                snprintf(list + len, sizeof list - len, "%s%d (t = %s)", shown ? ", " : "", k + 1,
                         fig_num(b1, sizeof b1, fl[k].t, 8));
                shown++;
            }
        svg_text(m, 12, y, "start", 12, COL_TEXT, false, "%d triangles; the ray's line crosses %s%s",
                 nf, ncross ? "triangles " : "none of them", list);
        svg_text(m, 12, y + 18, "start", 11, COL_NOTE, false, "Seen along the ray, every triangle the ray "
                 "goes through covers the cross; a ray through a shared edge lies on that edge.");
    } else {
        double tp = fl[0].t;
        svg_text(m, 12, y, "start", 12, COL_TEXT, false, "The ray's line meets the triangle's plane at "
                 "t = %s%s; the point is %s the triangle (yellow: the ray goes through it).",
                 fig_num(b1, sizeof b1, tp, 10), tp < 0 ? " (behind e: t < 0)" : "",
                 fl[0].crossed ? "inside or on the edge of" : "outside");
        /* the side the ray comes from: the winding of a, b, c as drawn
         * (as the eye sees them), whose sign is det's */
        const Flat *f = &fl[0];
        double turn = (f->x[1] - f->x[0]) * (f->y[2] - f->y[0]) - (f->y[1] - f->y[0]) * (f->x[2] - f->x[0]);
        svg_text(m, 12, y + 18, "start", 11, COL_NOTE, false, "Drawn as seen looking along the ray, %s",
                 turn > 0 ? "a, b, c run counterclockwise: the ray comes at the triangle's front (det > 0)."
                 : turn < 0 ? "a, b, c run clockwise: the ray comes at the triangle from behind (det < 0)."
                 : "the triangle is edge on (det = 0).");
    }
}

void fig_triangle(Markup *m, const Test *t, const Case *c, const double *got)
{
    bool mesh = t->kind == KIND_MESH;
    const double *e = mesh ? c->in : c->in + 9, *r = mesh ? c->in + 3 : c->in + 12;
    double u[3], p[3], q[3];
    if (plain_ray_figure(m, c, kind_nin(t->kind), r, u, "triangle", got))
        return;
    square_to(u, p, q);
    int nf = mesh ? t->ntriangles : 1;
    Flat *fl = calloc((size_t)nf + 1, sizeof *fl);
    if (!fl)
        return;
    for (int k = 0; k < nf; k++)
        project(mesh ? t->triangles[k].v : c->in, e, r, p, q, &fl[k]);
    Extent x = flats_extent(fl, nf);
    fig_begin(m, 760, 356, mesh ? "the mesh seen along the ray" : "the triangle seen along the ray");
    svg_text(m, 10, 19, "start", 14, COL_TEXT, true, "%s seen along the ray: the ray is the point %s",
             mesh ? "The mesh" : "The triangle", "in the middle of the cross");
    FigView w[2];
    int nwin = fit_windows(w, &x);
    for (int k = 0; k < nwin; k++)
        draw_window(m, w, k, fl, nf, &x, c, got);
    if (nwin == 2) {
        /* the zoom's square on the whole */
        double s = w[1].pw / w[1].s / 2;
        svg_rect(m, fig_px(&w[0], -s) - 4, fig_py(&w[0], s) - 4, fmax(2 * s * w[0].s, 0) + 8,
                 fmax(2 * s * w[0].s, 0) + 8, "none", "#7a4fbf", 1.4);
    }
    triangle_caption(m, 290, fl, nf, mesh);
    answer_legend(m, 340, c, got);
    fig_end(m);
    free(fl);
}
