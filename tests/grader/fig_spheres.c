/*
 * fig_spheres.c - the figures of spheres: Part 3a (one sphere and a ray)
 * and Part 3b's colour and image tests (a scene of spheres), and the table
 * of the spheres a ray meets, by t.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "fig_draw.h"
#include "figures.h"
#include "fig_ray.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

void fig_sphere(Markup *m, const Test *t, const Case *c, const double *got)
{
    (void)t;
    const double *cen = c->in, *e = c->in + 4, *r = c->in + 7;
    double R = c->in[3];
    RayFig f = { .title = "The plane through the ray and the sphere's centre (the sphere is the circle)",
                 .ncircles = 1, .circles = { { 0, 0, R, "#c9c9c9", "c" } }, .target = 0 };
    double dist;
    f.rlen = ray_frame_sphere(e, r, cen, &f.circles[0].a, &f.circles[0].b, &dist);
    ray_answers(&f, c->want, got, c->flags & CASE_EITHER_HIT ? "the ray grazes the sphere" : NULL);
    if (!(f.rlen > 0)) {
        /* no ray to draw along: r is zero (or not a number) */
        fig_begin(m, 760, 90, "a ray with no direction");
        svg_text(m, 12, 30, "start", 14, COL_TEXT, true, "The ray has no direction: r = (%g, %g, %g)",
                 r[0], r[1], r[2]);
        svg_text(m, 12, 52, "start", 13, COL_TEXT, false,
                 "A ray that goes nowhere meets no sphere: the answer must be a miss.");
        fig_legend(m, 12, 78, f.want_hit ? "expected: a hit" : "expected: a miss",
                   !got ? "your code: no answer" : f.got_hit ? "your code: a hit" : "your code: a miss");
        fig_end(m);
        return;
    }
    ray_figure(m, &f);
}

/* ---- Part 3b: scenes -------------------------------------------------------- */

typedef struct {
    int index;                 /* in the test's list       */
    bool hit;
    double t_near, t_far;      /* where the line meets it   */
} SphereHit;

/* qsort order: spheres the line meets first, by the t the ray sees them
 * at (behind the ray last), then those it misses, by index. */
static int by_t(const void *pa, const void *pb)
{
    const SphereHit *a = pa, *b = pb;
    if (a->hit != b->hit)
        return a->hit ? -1 : 1;
    if (!a->hit)
        return a->index - b->index;
    double meet_a = a->t_far > 0 ? (a->t_near > 0 ? a->t_near : a->t_far) : INFINITY;
    double meet_b = b->t_far > 0 ? (b->t_near > 0 ? b->t_near : b->t_far) : INFINITY;
    return meet_a < meet_b ? -1 : meet_a > meet_b ? 1 : a->index - b->index;
}

/* Both roots of the ray's line and each sphere, in double (display only). */
static int sphere_hits(const Test *t, const double e[3], const double r[3], SphereHit *out)
{
    int n = 0;
    for (int k = 0; k < t->nspheres; k++) {
        const TestSphere *sp = &t->spheres[k];
        double a, b, dist, rl = ray_frame_sphere(e, r, sp->c, &a, &b, &dist);
        SphereHit h = { k, false, 0, 0 };
        if (rl > 0 && b <= sp->R) {
            double half = sqrt((sp->R - b) * (sp->R + b));
            h.hit = true;
            h.t_near = (a - half) / rl;
            h.t_far = (a + half) / rl;
        }
        out[n++] = h;
    }
    qsort(out, (size_t)n, sizeof *out, by_t);
    return n;
}

/* Which sphere's colour (or the background's) rgb is, exactly enough;
 * -1 for the background, -2 for none. */
static int colour_owner(const Test *t, const double *rgb)
{
    for (int k = 0; k <= t->nspheres; k++) {                /* the spheres, then the background */
        const double *own = k < t->nspheres ? t->spheres[k].color : t->background;
        if (fabs(rgb[0] - own[0]) < 1e-9 && fabs(rgb[1] - own[1]) < 1e-9 && fabs(rgb[2] - own[2]) < 1e-9)
            return k < t->nspheres ? k : -1;
    }
    return -2;
}

/* A small square of the colour rgb. */
static void swatch(Markup *m, const double *rgb)
{
    char hex[8];
    mk_printf(m, "<span class=\"swatch\" style=\"background:%s\"></span>", fig_hex(hex, rgb));
}

/* A colour with its swatch, its numbers and whose colour it is. */
static void owner_words(Markup *m, const Test *t, const double *rgb)
{
    int k = colour_owner(t, rgb);
    swatch(m, rgb);
    mk_printf(m, "%.3g %.3g %.3g", rgb[0], rgb[1], rgb[2]);
    if (k >= 0)
        mk_printf(m, " (sphere %d's colour)", k + 1);
    else if (k == -1)
        mk_printf(m, " (the background: no sphere hit)");
    else
        mk_printf(m, " (no sphere's colour and not the background)");
}

/* The table under a colour or image figure: the expected and the returned
 * colour, then every sphere of the scene by where the ray meets it. */
static void sphere_table(Markup *m, const Test *t, const double e[3], const double r[3],
                         const double *want, const double *got)
{
    SphereHit *h = calloc((size_t)t->nspheres + 1, sizeof *h);
    if (!h)
        return;
    int n = sphere_hits(t, e, r, h);
    mk_printf(m, "<p>Expected colour: ");
    owner_words(m, t, want);
    mk_printf(m, "<br>Your colour: ");
    if (got)
        owner_words(m, t, got);
    else
        mk_printf(m, "no answer");
    mk_printf(m, "</p>\n<table class=\"spheres\">\n<caption>The ray's spheres, nearest first "
                 "(t computed again here, in double, for you to compare)</caption>\n"
                 "<tr><th>sphere</th><th>colour</th><th>centre</th><th>radius</th>"
                 "<th>the ray's line meets it at</th><th></th></tr>\n");
    bool first = true;
    for (int k = 0; k < n && k < 40; k++) {
        const TestSphere *sp = &t->spheres[h[k].index];
        mk_printf(m, "<tr><td>%d</td><td>", h[k].index + 1);
        swatch(m, sp->color);
        mk_printf(m, "</td><td>(%.6g, %.6g, %.6g)</td><td>%.6g</td><td>", sp->c[0], sp->c[1], sp->c[2],
                  sp->R);
        const char *note = "";
        if (!h[k].hit) {
            mk_printf(m, "misses it");
        } else {
            mk_printf(m, "t = %.10g and t = %.10g", h[k].t_near, h[k].t_far);
            if (!(h[k].t_far > 0))
                note = "behind the ray's start (t &lt; 0): not seen";
            else if (first)
                note = h[k].t_near > 0 ? "<strong>the first hit: its colour is seen</strong>"
                                       : "<strong>the ray starts inside it: seen</strong>";
            else
                note = "hidden behind the first hit";
            if (h[k].t_far > 0)
                first = false;
        }
        mk_printf(m, "</td><td>%s</td></tr>\n", note);
    }
    if (n > 40)
        mk_printf(m, "<tr><td colspan=\"6\">... and %d more that the ray misses</td></tr>\n", n - 40);
    mk_printf(m, "</table>\n");
    free(h);
}

void fig_color(Markup *m, const Test *t, const Case *c, const double *got)
{
    const double *e = c->in, *r = c->in + 3;
    RayFig f = { .title = "The ray and its spheres (each turned about the ray into this plane)", .target = -1 };
    double a, b, dist;
    f.rlen = ray_frame_sphere(e, r, e, &a, &b, &dist);
    /* the spheres nearest the ray's line first, as many as fit */
    SphereHit *h = calloc((size_t)t->nspheres + 1, sizeof *h);
    int n = h ? sphere_hits(t, e, r, h) : 0;
    int want_owner = colour_owner(t, c->want), got_owner = got ? colour_owner(t, got) : -2;
    for (int k = 0; k < n && f.ncircles < RAYFIG_MAX_CIRCLES; k++) {
        const TestSphere *sp = &t->spheres[h[k].index];
        RayCircle *rc = &f.circles[f.ncircles];
        ray_frame_sphere(e, r, sp->c, &rc->a, &rc->b, &dist);
        rc->R = sp->R;
        fig_hex(rc->fill, sp->color);
        snprintf(rc->label, sizeof rc->label, "%d", h[k].index + 1);
        if (h[k].index == want_owner)
            f.target = f.ncircles;
        f.ncircles++;
    }
    const TestSphere *sp = t->spheres;
    f.want_hit = want_owner >= 0 && ray_sphere_t(e, r, sp[want_owner].c, sp[want_owner].R, &f.want_t);
    f.got_known = got != NULL;
    f.got_hit = got_owner >= 0 && ray_sphere_t(e, r, sp[got_owner].c, sp[got_owner].R, &f.got_t);
    char wt[120], gt[120];
    if (want_owner >= 0)
        snprintf(wt, sizeof wt, "expected: sphere %d's colour", want_owner + 1);
    else
        snprintf(wt, sizeof wt, "expected: the background (no hit)");
    if (!got)
        snprintf(gt, sizeof gt, "your code: no answer");
    else if (got_owner >= 0)
        snprintf(gt, sizeof gt, "your code: sphere %d's colour%s", got_owner + 1,
                 f.got_hit ? "" : " (a sphere the ray does not see)");
    else if (got_owner == -1)
        snprintf(gt, sizeof gt, "your code: the background");
    else
        snprintf(gt, sizeof gt, "your code: a colour of nothing in the scene");
    f.want_text = wt;
    f.got_text = gt;
    if (f.rlen > 0)
        ray_figure(m, &f);
    sphere_table(m, t, e, r, c->want, got);
    free(h);
}

/* ---- Part 3b: images ---------------------------------------------------------- */

/* A render (the test's small image) magnified scale times, from the
 * colours given per pixel (NULL rows beyond answered are grey). */
static int magnified(Image *img, const Test *t, double (*rgb)[CASE_MAX_OUT], bool use_want,
                     int answered, int scale)
{
    int nx = t->image_nx, ny = t->ncases / t->image_nx;
    char err[128];
    if (image_alloc(img, nx * scale, ny * scale, err, sizeof err) < 0)
        return -1;
    for (int j = 0; j < ny * scale; j++)
        for (int i = 0; i < nx * scale; i++) {
            int c = (j / scale) * nx + i / scale;
            unsigned char *px = img->rgb + 3 * ((size_t)j * (size_t)img->width + (size_t)i);
            const double *v = use_want ? t->cases[c].want : c < answered ? rgb[c] : NULL;
            for (int k = 0; k < 3; k++)
                px[k] = v ? image_channel(v[k]) : ((i / 4 + j / 4) % 2 ? 150 : 190);
        }
    return 0;
}

void fig_image(Markup *m, const Test *t, const TestResult *r, int c)
{
    int nx = t->image_nx, ny = nx > 0 ? t->ncases / nx : 0;
    const Answers *a = &r->answers;
    if (nx <= 0 || ny <= 0 || nx * ny != t->ncases) {
        fig_color(m, t, &t->cases[c], a->got && c < a->answered ? a->got[c] : NULL);
        return;
    }
    int scale = 1;
    while (scale < 16 && nx * (scale + 1) <= 340 && ny * (scale + 1) <= 260)
        scale++;
    Image mine, ref;
    if (magnified(&mine, t, a->got, false, a->answered, scale) < 0)
        return;
    if (magnified(&ref, t, NULL, true, 0, scale) < 0) {
        image_free(&mine);
        return;
    }
    double W = nx * scale, H = ny * scale, gap = 40, x0 = 10, top = 30;
    double fw = fmax(2 * W + gap + 20, 560), fh = top + H + 60;
    fig_begin(m, fw, fh, "your render and the reference's, with the pixel marked");
    svg_text(m, x0, 19, "start", 14, COL_TEXT, true, "Your picture and the reference's (%dx%d pixels, "
             "shown %d times larger)", nx, ny, scale);
    for (int k = 0; k < 2; k++) {
        double x = x0 + k * (W + gap);
        const char *col = k ? COL_WANT : COL_GOT;
        mk_printf(m, "<image x=\"%.0f\" y=\"%.0f\" width=\"%.0f\" height=\"%.0f\" href=\"", x, top, W, H);
        mk_png_uri(m, k ? &ref : &mine);
        mk_printf(m, "\"/>\n");
        svg_rect(m, x, top, W, H, "none", "#888888", 1);
        /* every wrong pixel outlined thinly, the one shown strongly */
        for (int q = 0; q < a->answered && q < t->ncases; q++)
            if (a->ok && !a->ok[q] && q != c)
                svg_rect(m, x + (q % nx) * scale, top + (q / nx) * scale, scale, scale, "none", col, 0.8);
        double px = x + (c % nx) * scale, py = top + (c / nx) * scale;
        svg_rect(m, px - 2, py - 2, scale + 4, scale + 4, "none", col, 2.5);
        svg_circle(m, px + scale / 2.0, py + scale / 2.0, scale / 2.0 + 9, "none", col, 1.5);
        svg_text(m, x, top + H + 18, "start", 13, col, true, "%s", k ? "the reference" : "your code");
    }
    svg_text(m, x0, top + H + 38, "start", 12, COL_NOTE, false,
             "The circled pixel is (i = %d, j = %d): column i from the left, row j from the top. "
             "Thin outlines: the other wrong pixels.", c % nx, c / nx);
    if (a->answered < t->ncases)
        svg_text(m, x0, top + H + 54, "start", 12, COL_NOTE, false,
                 "Checkered: pixels your code never answered (it stopped after %d of %d).",
                 a->answered, t->ncases);
    fig_end(m);
    image_free(&mine);
    image_free(&ref);
    double e[3] = { 0, 0, 0 };
    const double *p = t->cases[c].in;
    mk_printf(m, "<p>The ray of this pixel starts at the eye e = (0, 0, 0) and passes through the "
                 "pixel's centre (%.6g, %.6g, %.6g).</p>\n", p[0], p[1], p[2]);
    sphere_table(m, t, e, p, t->cases[c].want,
                 a->got && c < a->answered ? a->got[c] : NULL);
}
