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
    double along = m[0] * u[0] + m[1] * u[1] + m[2] * u[2];
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

/* Where the plane's line comes nearest e: (A, B) C / (A^2 + B^2). */
static void line_foot(const RayFig *f, double *fa, double *fb)
{
    double n = hypot(f->line_A, f->line_B);
    double A = f->line_A / n, B = f->line_B / n, C = f->line_C / n;
    *fa = A * C;
    *fb = B * C;
}

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

/* The normal drawn where no point of the plane's line has room for it
 * (normal_anchor: a plane along the window's edge, its normal pointing
 * out): the arrow shortened until its tip is inside the window (to
 * NORMAL_LEN_MIN pixels at the least), and its label, if it does not fit
 * past the tip, beside it, on the side with room. */
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

/* Draws what the window v shows: the circles or the line, the ray (marked
 * in t in the main window), e, and the hits that fall inside it. */
static void draw_content(Markup *m, const FigView *v, const RayFig *f, double aw, double ag,
                         bool want_in, bool got_in, bool main)
{
    double left = v->cx - v->pw / 2 / v->s, right = v->cx + v->pw / 2 / v->s;
    /* the objects first, the ray and the marks over them */
    for (int k = 0; k < f->ncircles; k++) {
        const RayCircle *c = &f->circles[k];
        fig_circle(m, v, c->a, c->b, c->R, c->fill, 0.45, "#333333", k == f->target ? 1.6 : 1);
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
        double fa, fb, n = hypot(f->line_A, f->line_B);
        line_foot(f, &fa, &fb);
        double da = f->line_B / n, db = -f->line_A / n, far = 4 * (right - left) + fabs(fa - v->cx)
                                                              + fabs(fb - v->cy);
        fig_segment(m, v, fa - far * da, fb - far * db, fa + far * da, fb + far * db, "#333333", 3, NULL);
        double na = fa, nb = fb;
        bool room = main && normal_anchor(v, f, fa, fb, da, db, fig_py(v, 0), &na, &nb);
        if (room || (main && fig_inside(v, fa, fb))) {
            double px = fig_px(v, na), py = fig_py(v, nb), tx, ty, lx0, lx1, ly;
            if (room)
                normal_arrow(px, py, f->line_A / n, -f->line_B / n, NORMAL_LEN, &tx, &ty, &lx0, &lx1, &ly);
            else
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

void ray_figure(Markup *m, const RayFig *given)
{
    char buf[64], buf2[64];
    /* a grazing plane is drawn with heights stretched: b becomes k b, so
     * the line A a + B b = C becomes A a + (B / k) b = C */
    const double stretch = line_stretch(given);
    RayFig stretched;
    const RayFig *f = given;
    if (stretch > 1) {
        stretched = *given;
        stretched.line_B = given->line_B / stretch;
        f = &stretched;
    }
    double aw = f->want_hit ? f->want_t * f->rlen : NAN;
    double ag = f->got_known && f->got_hit ? f->got_t * f->rlen : NAN;
    const RayCircle *tc = f->target >= 0 && f->target < f->ncircles ? &f->circles[f->target] : NULL;

    /* How far the interesting things are from e. */
    double L = isfinite(aw) ? fabs(aw) : 0;
    for (int k = 0; k < f->ncircles; k++) {
        const RayCircle *c = &f->circles[k];
        double d = hypot(c->a, c->b);
        L = fmax(L, d > c->R ? d - c->R : 0);
    }
    double fa = 0, fb = 0;
    if (f->has_line) {
        line_foot(f, &fa, &fb);
        L = fmax(L, hypot(fa, fb));
    }
    if (!(L > 0))
        for (int k = 0; k < f->ncircles; k++)
            L = fmax(L, f->circles[k].R);
    if (!(L > 0))
        L = 1;
    bool got_drawable = isfinite(ag) && fabs(ag) <= 50 * L;
    if (got_drawable)
        L = fmax(L, fabs(ag));

    Box bx = { 0, 0, 0, 0, false };
    box_add(&bx, 0, 0);
    if (isfinite(aw))
        box_add(&bx, aw, 0);
    if (got_drawable)
        box_add(&bx, ag, 0);
    for (int k = 0; k < f->ncircles; k++) {
        const RayCircle *c = &f->circles[k];
        double d = hypot(c->a, c->b);
        if (c->R <= 3 * L) {
            box_add(&bx, c->a - c->R, c->b - c->R);
            box_add(&bx, c->a + c->R, c->b + c->R);
        } else if (d > 0) {
            box_add(&bx, c->a * (1 - c->R / d), c->b * (1 - c->R / d));
            if (c->b <= c->R) {
                double half = sqrt((c->R - c->b) * (c->R + c->b));
                if (fabs(c->a - half) <= 3 * L)
                    box_add(&bx, c->a - half, 0);
                if (fabs(c->a + half) <= 3 * L)
                    box_add(&bx, c->a + half, 0);
            }
        }
    }
    if (f->has_line) {
        box_add(&bx, fa, fb);
        /* and room for the normal's arrow and label on the side it points
         * to (past the window's edge, a normal along the ray is not seen) */
        double n = hypot(f->line_A, f->line_B), room = 0.2 * fmax(bx.x1 - bx.x0, bx.y1 - bx.y0);
        box_add(&bx, fa + room * f->line_A / n, fb + room * f->line_B / n);
    }
    /* keep some of the ray ahead of e in view, and a little room above
     * and below the axis */
    if (bx.x1 < 0.25 * (bx.x1 - bx.x0))
        box_add(&bx, 0.25 * (bx.x1 - bx.x0), 0);
    /* keep a little room above and below the axis */
    double span = fmax(bx.x1 - bx.x0, bx.y1 - bx.y0);
    box_add(&bx, bx.x0, -0.06 * span);
    box_add(&bx, bx.x0, 0.06 * span);

    FigView main;
    fig_fit(&main, bx.x0, bx.y0, bx.x1, bx.y1, 0.06, 10, TOP, 740, WH);

    /* Zoomed-in windows (at most two, each closer than the last), while
     * what matters is too small at the scale so far. */
    FigView win[3];
    const char *why[3] = { NULL, NULL, NULL };
    int nwin = 1;
    win[0] = main;
    bool both = isfinite(aw) && got_drawable && aw != ag;
    bool used_small = false, used_close = false, used_graze = false, used_line = false;
    while (nwin < 3) {
        double s = win[nwin - 1].s;
        Box zb = { 0, 0, 0, 0, false };
        const char *what = NULL;
        if (tc && !used_small && tc->R * s < 6) {
            what = "the sphere";
            used_small = true;
            box_add(&zb, tc->a - tc->R, tc->b - tc->R);
            box_add(&zb, tc->a + tc->R, tc->b + tc->R);
            box_add(&zb, tc->a, 0);
            if (isfinite(aw) && fabs(aw - tc->a) < 6 * tc->R)
                box_add(&zb, aw, 0);
            if (got_drawable && fabs(ag - tc->a) < 6 * tc->R)
                box_add(&zb, ag, 0);
        } else if (tc && !used_graze && fabs(tc->b - tc->R) < 0.05 * tc->R
                   && fabs(tc->b - tc->R) * s < 4) {
            what = "where the ray grazes the sphere";
            used_graze = true;
            /* the gap between the ray and the edge, as wide again on each
             * side; an exact tangent has none: close enough to see it touch */
            double g = tc->b != tc->R ? fabs(tc->b - tc->R) : 0.02 * tc->R;
            box_add(&zb, tc->a - 8 * g, -5 * g);
            box_add(&zb, tc->a + 8 * g, 5 * g);
        } else if (both && !used_close && fabs(aw - ag) * s < 10) {
            what = "the two hits";
            used_close = true;
            double d = fabs(aw - ag), mid = aw / 2 + ag / 2;
            box_add(&zb, mid - 2.5 * d, -1.2 * d);
            box_add(&zb, mid + 2.5 * d, 1.2 * d);
        } else if (f->has_line && !used_line && isfinite(aw) && hypot(fa, fb) * s < 6
                   && hypot(fa, fb) > 0) {
            what = "e and the plane";
            used_line = true;
            double g = hypot(fa, fb);
            box_add(&zb, -2 * g, -2 * g);
            box_add(&zb, fmax(2 * g, 1.2 * aw), 2 * g);
        }
        if (!what || !zb.any)
            break;
        FigView z;
        fig_fit(&z, zb.x0, zb.y0, zb.x1, zb.y1, 0.12, 0, TOP, 220, WH);
        if (!(z.s > 4 * s))
            continue;               /* no closer than now: try the next reason */
        why[nwin] = what;
        win[nwin++] = z;
    }
    /* Lay the windows out side by side: the main one keeps its left edge. */
    static const double widths[3][3] = { { 740, 0, 0 }, { 470, 260, 0 }, { 300, 210, 210 } };
    double x = 10;
    for (int k = 0; k < nwin; k++) {
        double w = widths[nwin - 1][k];
        if (k == 0) {
            /* its left edge kept, unless that would push the far end of
             * what it shows past the right: then what it shows, centred
             * (a main window fitted to its height starts well left of
             * what it shows) */
            double left = main.cx - main.pw / 2 / main.s;
            win[0].pw = w;
            win[0].s = fmin(main.s, w / fmax((bx.x1 - bx.x0) * 1.12, 1e-300));
            double seen = w / win[0].s;
            if (left + seen < bx.x1 + 0.06 * (bx.x1 - bx.x0))
                left = (bx.x0 + bx.x1) / 2 - seen / 2;
            win[0].cx = left + w / 2 / win[0].s;
        } else {
            FigView z = win[k];
            double cx = z.cx, cy = z.cy, sw = z.pw / z.s, sh = z.ph / z.s;
            fig_fit(&win[k], cx - sw / 2, cy - sh / 2, cx + sw / 2, cy + sh / 2, 0, x, TOP, w, WH);
        }
        win[k].px0 = x;
        x += w + 10;
    }
    main = win[0];

    fig_begin(m, FW, FH + (f->note ? 16 : 0), f->title ? f->title : "the ray");
    svg_text(m, 10, 19, "start", 14, COL_TEXT, true, "%s", f->title ? f->title : "");
    /* enough digits that the expected and the returned t read apart */
    int digits = 6;
    while (digits < 17 && f->want_hit && f->got_known && f->got_hit && f->want_t != f->got_t
           && strcmp(fig_num(buf, sizeof buf, f->want_t, digits), fig_num(buf2, sizeof buf2, f->got_t, digits)) == 0)
        digits++;
    bool got_shown = false;
    for (int k = 0; k < nwin; k++) {
        const FigView *v = &win[k];
        bool want_in = isfinite(aw) && fig_inside(v, aw, 0);
        bool got_in = got_drawable && fig_inside(v, ag, 0);
        got_shown = got_shown || got_in;
        const char *frame_col = k ? "#7a4fbf" : "#bbbbbb";
        fig_window(m, v, k ? "#f8f5fd" : "#fbfbfb");
        draw_content(m, v, f, aw, ag, want_in, got_in, k == 0);
        if (k + 1 < nwin) {
            /* where the next window is, in this one */
            const FigView *z = &win[k + 1];
            double x0 = fig_px(v, z->cx - z->pw / 2 / z->s), x1 = fig_px(v, z->cx + z->pw / 2 / z->s);
            double ya = fig_py(v, z->cy + z->ph / 2 / z->s), yb = fig_py(v, z->cy - z->ph / 2 / z->s);
            double cxp = (x0 + x1) / 2, cyp = (ya + yb) / 2, rw = fmax(x1 - x0, 10), rh = fmax(yb - ya, 10);
            svg_rect(m, cxp - rw / 2, cyp - rh / 2, rw, rh, "none", "#7a4fbf", 1.4);
        }
        fig_window_end(m);
        svg_rect(m, v->px0, v->py0, v->pw, v->ph, "none", frame_col, k ? 1.4 : 1);
        /* labels of the hits, outside the clipping so that none is cut:
         * expected above the axis, returned below */
        double y0 = fig_py(v, 0), lo = v->px0 + 4, hi = v->px0 + v->pw - 4;
        bool apart = !(want_in && got_in) || fabs(fig_px(v, aw) - fig_px(v, ag)) > 4;
        if (want_in) {
            if (k == 0)
                snprintf(buf2, sizeof buf2, "expected t = %s", fig_num(buf, sizeof buf, f->want_t, digits));
            else
                snprintf(buf2, sizeof buf2, "expected");
            double w = 6.6 * (double)strlen(buf2), px = fmin(fmax(fig_px(v, aw), lo + w / 2), hi - w / 2);
            svg_text(m, px, y0 - 14, "middle", 12, COL_WANT, true, "%s", buf2);
        }
        if (got_in && (apart || k == 0)) {
            if (k == 0)
                snprintf(buf2, sizeof buf2, "your t = %s", fig_num(buf, sizeof buf, f->got_t, digits));
            else
                snprintf(buf2, sizeof buf2, "yours");
            double w = 6.6 * (double)strlen(buf2), px = fmin(fmax(fig_px(v, ag), lo + w / 2), hi - w / 2);
            svg_text(m, px, y0 + 34, "middle", 12, COL_GOT, true, "%s", buf2);
        }
        if (k > 0) {
            svg_text(m, v->px0 + 6, v->py0 + 16, "start", 12, "#7a4fbf", true, "zoomed in %s times:",
                     fig_times(buf, sizeof buf, v->s / main.s));
            svg_text(m, v->px0 + 6, v->py0 + 30, "start", 12, "#7a4fbf", true, "%s", why[k]);
            char note[120];
            snprintf(note, sizeof note, "this window is %s wide", fig_num(buf2, sizeof buf2, v->pw / v->s, 2));
            if (both && fabs(aw - ag) * v->s < 3 && k == nwin - 1)
                snprintf(note, sizeof note, "the two hits are %s apart", fig_num(buf, sizeof buf, fabs(aw - ag), 2));
            if (strcmp(why[k], "where the ray grazes the sphere") == 0 && tc) {
                if (tc->b == tc->R)
                    snprintf(note, sizeof note, "the ray touches the edge: it passes exactly on it");
                else
                    snprintf(note, sizeof note, "the ray passes %s %s the edge",
                             fig_num(buf, sizeof buf, fabs(tc->b - tc->R), 2),
                             tc->b < tc->R ? "inside" : "outside");
            }
            svg_text(m, v->px0 + 6, v->py0 + v->ph - 8, "start", 11, COL_NOTE, false, "%s", note);
        } else if (stretch > 1) {
            /* on the side of the ray away from the plane at e */
            bool below = f->line_C / f->line_B < 0;
            svg_text(m, v->px0 + 6, below ? v->py0 + 16 : v->py0 + v->ph - 8, "start", 12, "#7a4fbf", true,
                     "heights off the ray stretched %s times", fig_times(buf, sizeof buf, stretch));
        }
    }
    /* a returned hit off the figure, or at a t that is not a number */
    if (f->got_known && f->got_hit && !got_shown && isnan(f->got_t)) {
        svg_text(m, main.px0 + main.pw - 6, fig_py(&main, 0) + 34, "end", 12, COL_GOT, true,
                 "your t = NaN: no point of the ray");
    } else if (f->got_known && f->got_hit && !got_shown) {
        bool ahead = !(ag < 0) && !(f->got_t < 0);
        double y0 = fig_py(&main, 0);
        double xe = ahead ? main.px0 + main.pw - 6 : main.px0 + 6;
        svg_text(m, xe, y0 + 34, ahead ? "end" : "start", 12, COL_GOT, true, "%syour t = %s: off "
                 "the figure%s", ahead ? "" : "\xE2\x86\x90 ", fig_num(buf, sizeof buf, f->got_t, 6),
                 ahead ? " \xE2\x86\x92" : "");
    }

    /* the legend */
    char wt[120], gt[120];
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
    fig_end(m);
}
