/*
 * fig_ray.c - see fig_ray.h: the side view of a ray, with circles (the
 * spheres' great circles) or a line (a plane edge on), the expected and the
 * returned hit, and, where the scale demands it, a zoomed-in window.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "fig_ray.h"
#include "fig_draw.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define FW    760.0           /* the figure's width                    */
#define TOP   30.0            /* the windows' top                      */
#define WH    250.0           /* the windows' height                   */
#define FH    (TOP + WH + 56) /* the figure's height                   */

double ray_norm(const double v[3])
{
    double big = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(big > 0) || isinf(big))
        return big;
    double x = v[0] / big, y = v[1] / big, z = v[2] / big;
    return big * sqrt(x * x + y * y + z * z);
}

double ray_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double ray_frame_sphere(const double e[3], const double r[3], const double c[3], double *a,
                        double *b, double *dist)
{
    double rl = ray_norm(r), m[3], u[3], p[3];
    *a = *b = *dist = 0;
    if (!(rl > 0) || !isfinite(rl))
        return 0;
    for (int k = 0; k < 3; k++) {
        u[k] = r[k] / rl;
        m[k] = c[k] - e[k];
    }
    double along = ray_dot(m, u);
    for (int k = 0; k < 3; k++)
        p[k] = m[k] - along * u[k];
    *a = along;
    *b = ray_norm(p);
    *dist = ray_norm(m);
    return rl;
}

bool ray_sphere_t(const double e[3], const double r[3], const double c[3], double R, double *t)
{
    double a, b, dist;
    double rl = ray_frame_sphere(e, r, c, &a, &b, &dist);
    if (!(rl > 0) || !(b <= R))
        return false;
    double half = sqrt((R - b) * (R + b));    /* half the chord the ray cuts */
    double near = a - half, far = a + half;
    double pick = near > 0 ? near : far;
    if (!(pick > 0))
        return false;
    *t = pick / rl;
    return isfinite(*t);
}

/* ---- framing ------------------------------------------------------------------ */

typedef struct {
    double x0, y0, x1, y1;
    bool any;
} Box;

/* Grows bx to hold (x, y); a point not finite is left out. */
static void box_add(Box *bx, double x, double y)
{
    if (!isfinite(x) || !isfinite(y))
        return;
    if (!bx->any) {
        bx->x0 = bx->x1 = x;
        bx->y0 = bx->y1 = y;
        bx->any = true;
        return;
    }
    bx->x0 = fmin(bx->x0, x), bx->x1 = fmax(bx->x1, x);
    bx->y0 = fmin(bx->y0, y), bx->y1 = fmax(bx->y1, y);
}

/* A figure as ray_figure lays it out: what its steps share. */
typedef struct {
    const RayFig *f;           /* the figure, with heights stretched (line_stretch) */
    double stretch;            /* by how much (1: not at all)                       */
    double aw, ag;             /* a of the expected and of the returned hit, or NaN */
    bool got_drawable;         /* the returned hit is near enough to be drawn       */
    bool both;                 /* both hits are drawn, and apart                    */
    const RayCircle *tc;       /* the circle the hits are about, or NULL            */
    double fa, fb;             /* the plane's foot (ray_figure), or 0, 0            */
    Box bx;                    /* what the main window shows                        */
    int nwin;                  /* the windows: the main one, then zoomed-in ones    */
    FigView win[3];
    const char *why[3];        /* why each zoomed-in window is there                */
    int digits;                /* of the t in the labels                            */
} RayLayout;

/* The normal's arrow, drawn from (px, py): len pixels along the normal,
 * (ux, uy) in pixels (y down), to (*tx, *ty); its label "normal n" past
 * the tip, on the side the arrow points to, from *lx0 to *lx1 with its
 * baseline at *ly. */
enum { NORMAL_LABEL_W = 56, NORMAL_LEN = 38, NORMAL_LEN_MIN = 16 };
static void normal_arrow(double px, double py, double ux, double uy, double len, double *tx, double *ty,
                         double *lx0, double *lx1, double *ly)
{
    *tx = px + len * ux;
    *ty = py + len * uy;
    double qx = px + (len + 6) * ux;
    *lx0 = ux >= 0 ? qx + 4 : qx - 4 - NORMAL_LABEL_W;
    *lx1 = *lx0 + NORMAL_LABEL_W;
    *ly = py + (len + 6) * uy + 4;
}

/* The normal drawn from (px, py), also where no point of the plane's line
 * has room for it (normal_anchor: a plane along the window's edge, its
 * normal pointing out): the arrow shortened until its tip is inside the
 * window (to NORMAL_LEN_MIN pixels at the least), and its label, if it
 * does not fit past the tip, beside it, on the side with room.  (At a
 * point normal_anchor chose, both fit as they are.) */
static void normal_squeeze(const FigView *v, double px, double py, double ux, double uy, double *tx, double *ty,
                           double *lx0, double *lx1, double *ly)
{
    double x0 = v->px0 + 4, x1 = v->px0 + v->pw - 4, y0 = v->py0 + 4, y1 = v->py0 + v->ph - 4;
    double len = NORMAL_LEN;
    while (len > NORMAL_LEN_MIN && (px + len * ux < x0 || px + len * ux > x1 || py + len * uy < y0 ||
                                    py + len * uy > y1))
        len -= 2;
    normal_arrow(px, py, ux, uy, len, tx, ty, lx0, lx1, ly);
    if (*lx0 >= x0 && *lx1 <= x1 && *ly - 10 >= y0 && *ly <= y1)
        return;
    *lx0 = *tx + 6 + NORMAL_LABEL_W <= x1 ? *tx + 6 : *tx - 6 - NORMAL_LABEL_W;
    *lx1 = *lx0 + NORMAL_LABEL_W;
    *ly = fmin(fmax(*ty + 4, y0 + 10), y1);
}

/* Where on the plane's line (foot (fa, fb), direction (da, db)) the normal
 * is drawn: a point whose arrow and label fit inside the window v, at
 * least 50 pixels off the ray's line (y0) where the line allows, and of
 * those the nearest the foot.  (At the foot itself the arrow may leave the
 * window, or lie along the ray, hidden under it, when the normal is the
 * ray's direction.)  False when no point fits. */
static bool normal_anchor(const FigView *v, const RayFig *f, double fa, double fb, double da, double db,
                          double y0, double *ax, double *ay)
{
    double n = hypot(f->line_A, f->line_B), ux = f->line_A / n, uy = -f->line_B / n;
    double S = hypot(v->pw, v->ph) / v->s;
    double sc = (v->cx - fa) * da + (v->cy - fb) * db;      /* nearest the window's centre */
    double x0 = v->px0 + 6, x1 = v->px0 + v->pw - 6, y0w = v->py0 + 6, y1w = v->py0 + v->ph - 6;
    double best = -INFINITY;
    for (int k = 0; k <= 32; k++) {
        double sk = sc + S * (k / 32.0 - 0.5), a = fa + sk * da, b = fb + sk * db;
        double px = fig_px(v, a), py = fig_py(v, b), tx, ty, lx0, lx1, ly;
        normal_arrow(px, py, ux, uy, NORMAL_LEN, &tx, &ty, &lx0, &lx1, &ly);
        bool fits = px > x0 && px < x1 && py > y0w && py < y1w && tx > x0 && tx < x1 && ty > y0w &&
                    ty < y1w && lx0 > x0 && lx1 < x1 && ly - 10 > y0w && ly < y1w;
        double off = fmin(fmin(fabs(py - y0), fabs(ty - y0)), 50);
        double score = off * 1000 - fabs(sk) * v->s;
        if (fits && score > best) {
            best = score;
            *ax = a;
            *ay = b;
        }
    }
    return best > -INFINITY;
}

/* ---- drawing ------------------------------------------------------------------ */

/* Draws what window k shows: the circles or the line, the ray (marked in
 * t in the main window), e, and the hits that fall inside it. */
static void draw_content(Markup *m, const RayLayout *lay, int k, bool want_in, bool got_in)
{
    const FigView *v = &lay->win[k];
    const RayFig *f = lay->f;
    double aw = lay->aw, ag = lay->ag;
    bool main = k == 0;
    double left = v->cx - v->pw / 2 / v->s, right = v->cx + v->pw / 2 / v->s;
    /* the objects first, the ray and the marks over them */
    for (int q = 0; q < f->ncircles; q++) {
        const RayCircle *c = &f->circles[q];
        fig_circle(m, v, c->a, c->b, c->R, c->fill, 0.45, "#333333", q == f->target ? 1.6 : 1);
        /* the centre, and the label above the circle */
        if (c->R * v->s > 6 && fig_inside(v, c->a, c->b))
            svg_circle(m, fig_px(v, c->a), fig_py(v, c->b), 2, "#333333", "none", 0);
        if (c->label[0] && c->R * v->s > 3 && c->R * v->s < 400) {
            double lx = fig_px(v, c->a), ly = fig_py(v, c->b) - c->R * v->s - 5;
            if (lx > v->px0 + 8 && lx < v->px0 + v->pw - 8 && ly > v->py0 + 12)
                svg_text(m, lx, ly, "middle", 12, COL_TEXT, true, "%s", c->label);
            else if (fig_inside(v, c->a, c->b))
                svg_text(m, fig_px(v, c->a) + 5, fig_py(v, c->b) - 4, "start", 12, COL_TEXT, true,
                         "%s", c->label);
        }
    }
    if (f->has_line) {
        double fa = lay->fa, fb = lay->fb, n = hypot(f->line_A, f->line_B);
        double da = f->line_B / n, db = -f->line_A / n, far = 4 * (right - left) + fabs(fa - v->cx)
                                                              + fabs(fb - v->cy);
        fig_segment(m, v, fa - far * da, fb - far * db, fa + far * da, fb + far * db, "#333333", 3, NULL);
        double anchor_a = fa, anchor_b = fb;
        bool room = main && normal_anchor(v, f, fa, fb, da, db, fig_py(v, 0), &anchor_a, &anchor_b);
        if (room || (main && fig_inside(v, fa, fb))) {
            double px = fig_px(v, anchor_a), py = fig_py(v, anchor_b), tx, ty, lx0, lx1, ly;
            normal_squeeze(v, px, py, f->line_A / n, -f->line_B / n, &tx, &ty, &lx0, &lx1, &ly);
            svg_arrow(m, px, py, tx, ty, "#333333", 1.4, NULL);
            svg_text(m, lx0, ly, "start", 12, COL_TEXT, false, "normal n");
        }
    }
    /* the ray: behind e dashed, ahead solid, an arrowhead at the edge */
    double y0 = fig_py(v, 0);
    if (left < 0)
        fig_segment(m, v, left - 1 / v->s, 0, fmin(0, right), 0, "#999999", 1.2, "5 4");
    if (right > 0) {
        double x0 = fig_px(v, fmax(0, left - 1 / v->s)), x1 = v->px0 + v->pw - 2;
        svg_arrow(m, x0, y0, x1, y0, "#222222", 1.6, NULL);
    }
    if (fig_inside(v, 0, 0)) {
        svg_circle(m, fig_px(v, 0), y0, 3.5, "#222222", "none", 0);
        if (main)
            svg_text(m, fig_px(v, 0) - 6, y0 - 8, "end", 13, COL_TEXT, true, "e");
    }
    /* t along the ray */
    if (main && f->rlen > 0 && right > 0) {
        double a0 = fmax(0, left);
        double step = fig_step((right - a0) / f->rlen, (int)fmax(1, (right - a0) * v->s / 115));
        char buf[40];
        for (double t = ceil(a0 / f->rlen / step) * step; t * f->rlen <= right; t += step) {
            if (t == 0 || !(step > 0))
                continue;
            double px = fig_px(v, t * f->rlen);
            svg_line(m, px, y0 - 4, px, y0 + 4, "#222222", 1, NULL);
            bool crowded = (want_in && fabs(px - fig_px(v, aw)) < 30) || (got_in && fabs(px - fig_px(v, ag)) < 30);
            fig_num(buf, sizeof buf, t, 4);
            double half = 3.0 * (double)(strlen(buf) + 4);    /* "t = " and the number, at 11 px */
            bool cut = px - half < v->px0 + 2 || px + half > v->px0 + v->pw - 2;   /* by the frame */
            if (!crowded && !cut)
                svg_text(m, px, y0 + 16, "middle", 11, COL_NOTE, false, "t = %s", buf);
            if (t / step > 40)
                break;
        }
    }
    if (want_in)
        svg_mark_want(m, fig_px(v, aw), y0);
    if (got_in)
        svg_mark_got(m, fig_px(v, ag), y0);
}

/* How many times heights off the ray are stretched to draw a plane that
 * the ray meets far away at a grazing angle: 1 when the plane's height
 * above e, C / B, is at least 1/20 of the distance along the ray to the
 * expected hit (else the ray is drawn on the plane, and the hit looks like
 * a point of it); else 1, 2 or 5 times a power of ten, the largest that
 * makes the height at most 1/3 of that distance. */
static double line_stretch(const RayFig *f)
{
    if (!f->has_line || !f->want_hit || !(f->line_B != 0))
        return 1;
    double along = fabs(f->want_t * f->rlen), h = fabs(f->line_C / f->line_B);
    if (!(h > 0) || !(h < along / 20) || !isfinite(along))
        return 1;
    double x = along / 3 / h, k = pow(10, floor(log10(x)));
    k *= x >= 5 * k ? 5 : x >= 2 * k ? 2 : 1;
    return isfinite(k) ? k : 1;      /* at least 5: x is more than 20 / 3 */
}

/* ---- the figure ---------------------------------------------------------------- */

/* How far the interesting things are from e: the expected hit, the
 * circles' nearest points and the plane's foot (or else the circles'
 * radii, or 1); and the returned hit, when it is near enough to draw
 * (ly->got_drawable says whether). */
static double ray_reach(RayLayout *ly)
{
    const RayFig *f = ly->f;
    double L = isfinite(ly->aw) ? fabs(ly->aw) : 0;
    for (int k = 0; k < f->ncircles; k++) {
        const RayCircle *c = &f->circles[k];
        double d = hypot(c->a, c->b);
        L = fmax(L, d > c->R ? d - c->R : 0);
    }
    if (f->has_line)
        L = fmax(L, hypot(ly->fa, ly->fb));
    if (!(L > 0))
        for (int k = 0; k < f->ncircles; k++)
            L = fmax(L, f->circles[k].R);
    if (!(L > 0))
        L = 1;
    ly->got_drawable = isfinite(ly->ag) && fabs(ly->ag) <= 50 * L;
    if (ly->got_drawable)
        L = fmax(L, fabs(ly->ag));
    return L;
}

/* The world box of the main window (ly->bx), for things within about L
 * of e: e, the hits, the circles (of one far larger, the part near e and
 * where it crosses the axis), the plane's foot with room for its normal,
 * some of the ray ahead of e, and a little room above and below the axis. */
static void ray_main_box(RayLayout *ly, double L)
{
    const RayFig *f = ly->f;
    Box *bx = &ly->bx;
    box_add(bx, 0, 0);
    if (isfinite(ly->aw))
        box_add(bx, ly->aw, 0);
    if (ly->got_drawable)
        box_add(bx, ly->ag, 0);
    for (int k = 0; k < f->ncircles; k++) {
        const RayCircle *c = &f->circles[k];
        double d = hypot(c->a, c->b);
        if (c->R <= 3 * L) {
            box_add(bx, c->a - c->R, c->b - c->R);
            box_add(bx, c->a + c->R, c->b + c->R);
        } else if (d > 0) {
            box_add(bx, c->a * (1 - c->R / d), c->b * (1 - c->R / d));
            if (c->b <= c->R) {
                double half = sqrt((c->R - c->b) * (c->R + c->b));
                if (fabs(c->a - half) <= 3 * L)
                    box_add(bx, c->a - half, 0);
                if (fabs(c->a + half) <= 3 * L)
                    box_add(bx, c->a + half, 0);
            }
        }
    }
    if (f->has_line) {
        box_add(bx, ly->fa, ly->fb);
        /* and room for the normal's arrow and label on the side it points
         * to (past the window's edge, a normal along the ray is not seen) */
        double n = hypot(f->line_A, f->line_B), room = 0.2 * fmax(bx->x1 - bx->x0, bx->y1 - bx->y0);
        box_add(bx, ly->fa + room * f->line_A / n, ly->fb + room * f->line_B / n);
    }
    /* keep some of the ray ahead of e in view */
    if (bx->x1 < 0.25 * (bx->x1 - bx->x0))
        box_add(bx, 0.25 * (bx->x1 - bx->x0), 0);
    /* keep a little room above and below the axis */
    double span = fmax(bx->x1 - bx->x0, bx->y1 - bx->y0);
    box_add(bx, bx->x0, -0.06 * span);
    box_add(bx, bx->x0, 0.06 * span);
}

/* The next reason to zoom in from a window of s pixels per unit, with the
 * world box (zb) the closer window shows; NULL when none is left.  Each
 * reason is given once: used[] holds those given (the sphere too small,
 * the ray grazing it, the two hits too close, e and the plane too close). */
static const char *zoom_reason(const RayLayout *ly, double s, bool used[4], Box *zb)
{
    const RayCircle *tc = ly->tc;
    double aw = ly->aw, ag = ly->ag;
    if (tc && !used[0] && tc->R * s < 6) {
        used[0] = true;
        box_add(zb, tc->a - tc->R, tc->b - tc->R);
        box_add(zb, tc->a + tc->R, tc->b + tc->R);
        box_add(zb, tc->a, 0);
        if (isfinite(aw) && fabs(aw - tc->a) < 6 * tc->R)
            box_add(zb, aw, 0);
        if (ly->got_drawable && fabs(ag - tc->a) < 6 * tc->R)
            box_add(zb, ag, 0);
        return "the sphere";
    }
    if (tc && !used[1] && fabs(tc->b - tc->R) < 0.05 * tc->R && fabs(tc->b - tc->R) * s < 4) {
        used[1] = true;
        /* the gap between the ray and the edge, as wide again on each
         * side; an exact tangent has none: close enough to see it touch */
        double g = tc->b != tc->R ? fabs(tc->b - tc->R) : 0.02 * tc->R;
        box_add(zb, tc->a - 8 * g, -5 * g);
        box_add(zb, tc->a + 8 * g, 5 * g);
        return "where the ray grazes the sphere";
    }
    if (ly->both && !used[2] && fabs(aw - ag) * s < 10) {
        used[2] = true;
        double d = fabs(aw - ag), mid = aw / 2 + ag / 2;
        box_add(zb, mid - 2.5 * d, -1.2 * d);
        box_add(zb, mid + 2.5 * d, 1.2 * d);
        return "the two hits";
    }
    double g = hypot(ly->fa, ly->fb);
    if (ly->f->has_line && !used[3] && isfinite(aw) && g * s < 6 && g > 0) {
        used[3] = true;
        box_add(zb, -2 * g, -2 * g);
        box_add(zb, fmax(2 * g, 1.2 * aw), 2 * g);
        return "e and the plane";
    }
    return NULL;
}

/* Zoomed-in windows after the main one (at most two, each closer than the
 * last), while what matters is too small at the scale so far. */
static void zoom_in(RayLayout *ly)
{
    bool used[4] = { false, false, false, false };
    ly->nwin = 1;
    while (ly->nwin < 3) {
        double s = ly->win[ly->nwin - 1].s;
        Box zb = { 0, 0, 0, 0, false };
        const char *what = zoom_reason(ly, s, used, &zb);
        if (!what || !zb.any)
            break;
        FigView z;
        fig_fit(&z, zb.x0, zb.y0, zb.x1, zb.y1, 0.12, 0, TOP, 220, WH);
        if (!(z.s > 4 * s))
            continue;               /* no closer than now: try the next reason */
        ly->why[ly->nwin] = what;
        ly->win[ly->nwin++] = z;
    }
}

/* Lays the windows out side by side: the main one keeps its left edge. */
static void lay_out_windows(RayLayout *ly)
{
    static const double widths[3][3] = { { 740, 0, 0 }, { 470, 260, 0 }, { 300, 210, 210 } };
    const FigView main = ly->win[0];
    const Box *bx = &ly->bx;
    double x = 10;
    for (int k = 0; k < ly->nwin; k++) {
        double w = widths[ly->nwin - 1][k];
        FigView *v = &ly->win[k];
        if (k == 0) {
            /* its left edge kept, unless that would push the far end of
             * what it shows past the right: then what it shows, centred
             * (a main window fitted to its height starts well left of
             * what it shows) */
            double left = main.cx - main.pw / 2 / main.s;
            v->pw = w;
            v->s = fmin(main.s, w / fmax((bx->x1 - bx->x0) * 1.12, 1e-300));
            double seen = w / v->s;
            if (left + seen < bx->x1 + 0.06 * (bx->x1 - bx->x0))
                left = (bx->x0 + bx->x1) / 2 - seen / 2;
            v->cx = left + w / 2 / v->s;
        } else {
            double cx = v->cx, cy = v->cy, sw = v->pw / v->s, sh = v->ph / v->s;
            fig_fit(v, cx - sw / 2, cy - sh / 2, cx + sw / 2, cy + sh / 2, 0, x, TOP, w, WH);
        }
        v->px0 = x;
        x += w + 10;
    }
}

/* Enough digits that the expected and the returned t read apart. */
static int ray_digits(const RayFig *f)
{
    char buf[64], buf2[64];
    int digits = 6;
    while (digits < 17 && f->want_hit && f->got_known && f->got_hit && f->want_t != f->got_t
           && strcmp(fig_num(buf, sizeof buf, f->want_t, digits), fig_num(buf2, sizeof buf2, f->got_t, digits)) == 0)
        digits++;
    return digits;
}

/* A hit's label in window k (the returned one's if got, else the expected
 * one's), outside the clipping so that none is cut: expected above the
 * axis, returned below, over the hit but inside the window's frame; with
 * its t in the main window. */
static void hit_label(Markup *m, const RayLayout *ly, int k, bool got)
{
    const FigView *v = &ly->win[k];
    char buf[64], text[64];
    if (k == 0)
        snprintf(text, sizeof text, "%s t = %s", got ? "your" : "expected",
                 fig_num(buf, sizeof buf, got ? ly->f->got_t : ly->f->want_t, ly->digits));
    else
        snprintf(text, sizeof text, "%s", got ? "yours" : "expected");
    double lo = v->px0 + 4, hi = v->px0 + v->pw - 4, w = 6.6 * (double)strlen(text);
    double px = fmin(fmax(fig_px(v, got ? ly->ag : ly->aw), lo + w / 2), hi - w / 2);
    svg_text(m, px, fig_py(v, 0) + (got ? 34 : -14), "middle", 12, got ? COL_GOT : COL_WANT, true, "%s",
             text);
}

/* The words in window k's corners: of a zoomed-in window, how far it
 * zooms, why, and how wide it is (or how far apart the hits are, or the
 * ray from the sphere's edge); of the main window, how far heights are
 * stretched, if they are. */
static void window_note(Markup *m, const RayLayout *ly, int k)
{
    const RayFig *f = ly->f;
    const FigView *v = &ly->win[k];
    const RayCircle *tc = ly->tc;
    char buf[64], buf2[64];
    if (k > 0) {
        svg_text(m, v->px0 + 6, v->py0 + 16, "start", 12, "#7a4fbf", true, "zoomed in %s times:",
                 fig_times(buf, sizeof buf, v->s / ly->win[0].s));
        svg_text(m, v->px0 + 6, v->py0 + 30, "start", 12, "#7a4fbf", true, "%s", ly->why[k]);
        char note[120];
        snprintf(note, sizeof note, "this window is %s wide", fig_num(buf2, sizeof buf2, v->pw / v->s, 2));
        if (ly->both && fabs(ly->aw - ly->ag) * v->s < 3 && k == ly->nwin - 1)
            snprintf(note, sizeof note, "the two hits are %s apart",
                     fig_num(buf, sizeof buf, fabs(ly->aw - ly->ag), 2));
        if (strcmp(ly->why[k], "where the ray grazes the sphere") == 0 && tc) {
            if (tc->b == tc->R)
                snprintf(note, sizeof note, "the ray touches the edge: it passes exactly on it");
            else
                snprintf(note, sizeof note, "the ray passes %s %s the edge",
                         fig_num(buf, sizeof buf, fabs(tc->b - tc->R), 2),
                         tc->b < tc->R ? "inside" : "outside");
        }
        svg_text(m, v->px0 + 6, v->py0 + v->ph - 8, "start", 11, COL_NOTE, false, "%s", note);
    } else if (ly->stretch > 1) {
        /* on the side of the ray away from the plane at e */
        bool below = f->line_C / f->line_B < 0;
        svg_text(m, v->px0 + 6, below ? v->py0 + 16 : v->py0 + v->ph - 8, "start", 12, "#7a4fbf", true,
                 "heights off the ray stretched %s times", fig_times(buf, sizeof buf, ly->stretch));
    }
}

/* Draws window k: its content, the frame of the next window in it, its
 * own frame, the hits' labels and its note.  Returns whether the returned
 * hit shows in it. */
static bool draw_window(Markup *m, const RayLayout *ly, int k)
{
    const FigView *v = &ly->win[k];
    bool want_in = isfinite(ly->aw) && fig_inside(v, ly->aw, 0);
    bool got_in = ly->got_drawable && fig_inside(v, ly->ag, 0);
    fig_window(m, v, k ? "#f8f5fd" : "#fbfbfb");
    draw_content(m, ly, k, want_in, got_in);
    if (k + 1 < ly->nwin) {
        /* where the next window is, in this one */
        const FigView *z = &ly->win[k + 1];
        double x0 = fig_px(v, z->cx - z->pw / 2 / z->s), x1 = fig_px(v, z->cx + z->pw / 2 / z->s);
        double ya = fig_py(v, z->cy + z->ph / 2 / z->s), yb = fig_py(v, z->cy - z->ph / 2 / z->s);
        double cxp = (x0 + x1) / 2, cyp = (ya + yb) / 2, rw = fmax(x1 - x0, 10), rh = fmax(yb - ya, 10);
        svg_rect(m, cxp - rw / 2, cyp - rh / 2, rw, rh, "none", "#7a4fbf", 1.4);
    }
    fig_window_end(m, v, k > 0);
    if (want_in)
        hit_label(m, ly, k, false);
    /* the returned one's where it is apart from the expected (always in the main window) */
    if (got_in && (k == 0 || !want_in || fabs(fig_px(v, ly->aw) - fig_px(v, ly->ag)) > 4))
        hit_label(m, ly, k, true);
    window_note(m, ly, k);
    return got_in;
}

/* A returned hit shown in no window: off the figure, or at a t that is
 * not a number. */
static void got_off_figure(Markup *m, const RayLayout *ly)
{
    const RayFig *f = ly->f;
    const FigView *main = &ly->win[0];
    char buf[64], text[120];
    bool ahead = !(ly->ag < 0) && !(f->got_t < 0);             /* and a NaN's words at the right */
    if (isnan(f->got_t))
        snprintf(text, sizeof text, "your t = NaN: no point of the ray");
    else
        snprintf(text, sizeof text, "%syour t = %s: off the figure%s", ahead ? "" : "\xE2\x86\x90 ",
                 fig_num(buf, sizeof buf, f->got_t, 6), ahead ? " \xE2\x86\x92" : "");
    svg_text(m, ahead ? main->px0 + main->pw - 6 : main->px0 + 6, fig_py(main, 0) + 34,
             ahead ? "end" : "start", 12, COL_GOT, true, "%s", text);
}

/* The legend and the notes under the windows. */
static void ray_legend(Markup *m, const RayFig *f, int digits)
{
    char buf[64], wt[120], gt[120];
    if (f->want_text)
        snprintf(wt, sizeof wt, "%s", f->want_text);
    else if (f->want_hit)
        snprintf(wt, sizeof wt, "expected: a hit at t = %s", fig_num(buf, sizeof buf, f->want_t, digits > 10 ? digits : 10));
    else
        snprintf(wt, sizeof wt, "expected: a miss");
    if (f->got_text)
        snprintf(gt, sizeof gt, "%s", f->got_text);
    else if (!f->got_known)
        snprintf(gt, sizeof gt, "your code: no answer");
    else if (f->got_hit)
        snprintf(gt, sizeof gt, "your code: a hit at t = %s", fig_num(buf, sizeof buf, f->got_t, digits > 10 ? digits : 10));
    else
        snprintf(gt, sizeof gt, "your code: a miss");
    fig_legend(m, 12, TOP + WH + 22, wt, gt);
    svg_text(m, 12, TOP + WH + 44, "start", 11, COL_NOTE, false,
             "e: where the ray starts (t = 0); the arrow: the ray e + t r, marked in t; "
             "dashed: t < 0, behind e");
    if (f->note)
        svg_text(m, 12, TOP + WH + 60, "start", 11, COL_NOTE, false, "%s", f->note);
}

void ray_answers(RayFig *f, const double want[2], const double *got, const char *either)
{
    f->want_hit = want[0] != 0;
    f->want_t = want[1];
    f->got_known = got != NULL;
    f->got_hit = got && got[0] == 1;
    f->got_t = got ? got[1] : 0;
    if (got && got[0] != 0 && got[0] != 1)
        f->got_text = "your code: neither true nor false";
    if (either) {
        snprintf(f->want_buf, sizeof f->want_buf, "expected: %s (%s: a miss is right too)",
                 f->want_hit ? "a hit" : "a miss", either);
        f->want_text = f->want_buf;
    }
}

void ray_figure(Markup *m, const RayFig *given)
{
    /* a grazing plane is drawn with heights stretched: b becomes k b, so
     * the line A a + B b = C becomes A a + (B / k) b = C */
    RayFig stretched = *given;
    RayLayout ly = { .f = &stretched, .stretch = line_stretch(given) };
    stretched.line_B = given->line_B / ly.stretch;
    const RayFig *f = ly.f;
    ly.aw = f->want_hit ? f->want_t * f->rlen : NAN;
    ly.ag = f->got_known && f->got_hit ? f->got_t * f->rlen : NAN;
    ly.tc = f->target >= 0 && f->target < f->ncircles ? &f->circles[f->target] : NULL;
    if (f->has_line) {
        /* where the plane's line comes nearest e: (A, B) C / (A^2 + B^2) */
        double n = hypot(f->line_A, f->line_B);
        ly.fa = f->line_A / n * (f->line_C / n);
        ly.fb = f->line_B / n * (f->line_C / n);
    }
    ray_main_box(&ly, ray_reach(&ly));
    fig_fit(&ly.win[0], ly.bx.x0, ly.bx.y0, ly.bx.x1, ly.bx.y1, 0.06, 10, TOP, 740, WH);
    ly.both = isfinite(ly.aw) && ly.got_drawable && ly.aw != ly.ag;
    zoom_in(&ly);
    lay_out_windows(&ly);
    ly.digits = ray_digits(f);

    fig_begin(m, FW, FH + (f->note ? 16 : 0), f->title ? f->title : "the ray");
    svg_text(m, 10, 19, "start", 14, COL_TEXT, true, "%s", f->title ? f->title : "");
    bool got_shown = false;
    for (int k = 0; k < ly.nwin; k++)
        got_shown = draw_window(m, &ly, k) || got_shown;
    if (f->got_known && f->got_hit && !got_shown)
        got_off_figure(m, &ly);
    ray_legend(m, f, ly.digits);
    fig_end(m);
}
