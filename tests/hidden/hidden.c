/*
 * hidden.c - the hidden tests (visibility "after_published"): a few fixed
 * cases and cases drawn from a seed at grading time, with expected values
 * from the oracle.  The instructor's kit only: never in the student kit.
 * The seed comes from tests/weights.conf alone: every submission meets the
 * same cases, so a regrade draws them again and a resubmission that changes
 * only a comment draws no others.
 */
#include "../oracle/testgen.h"
#include "../oracle/oracle.h"
#include "../oracle/draw.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static Test *hidden_test(TestList *l, int part, Kind kind, const char *name, const char *note)
{
    Test *t = tg_test(l, part, kind, 1, name, note);
    t->hidden = true;
    return t;
}

/* Log-uniform in [lo, hi]: exp of a uniform draw between log lo and log hi. */
static double log_uniform(uint64_t *g, double lo, double hi)
{
    return exp(draw_uni(g, log(lo), log(hi)));
}

/* A random direction of the given length, uniform on the sphere. */
static void random_direction(uint64_t *g, double len, double r[3])
{
    double z = draw_uni(g, -1, 1), phi = draw_uni(g, 0, 2 * M_PI), s = sqrt(1 - z * z);
    r[0] = len * s * cos(phi), r[1] = len * s * sin(phi), r[2] = len * z;
}

/* r scaled to length |len|, reversed when len < 0. */
static void scale_to(double r[3], double len)
{
    double f = len / sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int q = 0; q < 3; q++)
        r[q] *= f;
}

/* The distance from c to the line of the ray from the origin along r. */
static double off_line(const double c[3], const double r[3])
{
    double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2], cr = (c[0] * r[0] + c[1] * r[1] + c[2] * r[2]) / rr;
    double q[3] = { c[0] - cr * r[0], c[1] - cr * r[1], c[2] - cr * r[2] };
    return sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
}

/* Part 3b's random scene: 8 spheres in four pairs, each pair's far sphere
 * straight behind its near one as the eye sees them, listed near first in
 * two pairs and far first in the other two; and 60 rays from the origin.
 * Whatever the seed, 16 rays pass through both spheres of a pair (so that
 * the nearest hit is neither always the first sphere listed nor always
 * the last), 12 hit nothing (so that the background counts), and 32 go
 * anywhere the spheres are.  The pairs lie one in each quadrant of the
 * view, apart: seen from the eye, a sphere's edge is at most 0.21 radians
 * from its centre (radius 2 at distance 9.6), and the pairs' directions
 * are at least 0.49 radians apart, so a ray through one pair meets no
 * other. */
static void color_scene(Test *t, uint64_t *g)
{
    t->background[0] = 0.25, t->background[1] = 0.5, t->background[2] = 0.75;
    double cn[4][3], Rn[4], Rf[4], cf[4][3], dn[4], fit[4];
    for (int q = 0; q < 4; q++) {
        double ux = draw_uni(g, -0.04, 0.04), uy = draw_uni(g, -0.04, 0.04);
        double u[3] = { (q % 2 ? 0.3 : -0.3) + ux, (q / 2 ? 0.3 : -0.3) + uy, -1 };
        double zn = draw_uni(g, 5, 9), zf = zn + draw_uni(g, 4, 10);
        Rn[q] = draw_uni(g, 0.4, 0.9);
        Rf[q] = draw_uni(g, Rn[q], 2);
        for (int k = 0; k < 3; k++)
            cn[q][k] = zn * u[k], cf[q][k] = zf * u[k];
        dn[q] = sqrt(cn[q][0] * cn[q][0] + cn[q][1] * cn[q][1] + cn[q][2] * cn[q][2]);
        fit[q] = 0.8 * fmin(Rn[q] / dn[q], Rf[q] / (dn[q] * zf / zn));   /* an angle inside both */
    }
    for (int s = 0; s < 8; s++) {
        int q = s / 2;
        bool near = (s % 2 == 0) == (q % 2 == 0);         /* near first in pairs 0 and 2 */
        double col[3] = { (s + 1) / 8.0, (s % 3) / 2.0, (7 - s) / 7.0 };
        test_add_sphere(t, near ? cn[q] : cf[q], near ? Rn[q] : Rf[q], col);
    }
    for (int k = 0; k < 16; k++) {                          /* through a pair */
        int q = k % 4;
        double u[3], r[3];
        random_direction(g, 1, u);
        double cu = (u[0] * cn[q][0] + u[1] * cn[q][1] + u[2] * cn[q][2]) /
                    (cn[q][0] * cn[q][0] + cn[q][1] * cn[q][1] + cn[q][2] * cn[q][2]);
        double w[3] = { u[0] - cu * cn[q][0], u[1] - cu * cn[q][1], u[2] - cu * cn[q][2] };
        double wl = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        double a = draw_uni(g, 0, fit[q]) * dn[q] / (wl > 0 ? wl : 1);
        for (int i = 0; i < 3; i++)
            r[i] = cn[q][i] + a * w[i];
        tg_color(t, V(0, 0, 0), r);
    }
    for (int k = 0; k < 12; k++) {                          /* between the spheres */
        double r[3] = { 0, 0, 1 };
        for (int tries = 0; tries < 200; tries++) {
            double cx = draw_uni(g, -0.6, 0.6), cy = draw_uni(g, -0.6, 0.6);
            double cand[3] = { cx, cy, -1 };
            bool clear = true;
            for (int s = 0; s < t->nspheres && clear; s++)
                clear = off_line(t->spheres[s].c, cand) > 1.05 * t->spheres[s].R;
            if (clear) {
                memcpy(r, cand, sizeof r);
                break;
            }
        }
        if (r[2] > 0) {                                     /* none found: away from them all */
            r[0] = draw_uni(g, -0.6, 0.6);
            r[1] = draw_uni(g, -0.6, 0.6);
        }
        tg_color(t, V(0, 0, 0), r);
    }
    for (int k = 0; k < 32; k++) {                          /* anywhere */
        double rx = draw_uni(g, -0.3, 0.3), ry = draw_uni(g, -0.3, 0.3);
        double r[3] = { rx, ry, -1 };
        tg_color(t, V(0, 0, 0), r);
    }
}

void testgen_hidden(TestList *l, uint64_t seed)
{
    uint64_t g = seed;
    Test *t;

    t = hidden_test(l, PART1, KIND_PLANE, "Part 1: hidden: fixed cases",
                    "a very wide image, a field of view near 180 and a tiny one");
    tg_plane(t, 30, 10, 1);
    tg_plane(t, 179, 1, 1);
    tg_plane(t, 1, 0.1, 50);
    t = hidden_test(l, PART1, KIND_PLANE, "Part 1: hidden: random fields of view, aspects and distances",
                    "alpha from 1 to 179 degrees, aspect from 0.25 to 4, d from 0.1 to 10");
    for (int k = 0; k < 30; k++) {
        double d = log_uniform(&g, 0.1, 10), aspect = log_uniform(&g, 0.25, 4);
        tg_plane(t, draw_uni(&g, 1, 179), aspect, d);
    }

    t = hidden_test(l, PART2, KIND_PIXEL, "Part 2: hidden: random pixels of random images",
                    "images from 1 x 1 to 4000 x 3000, any pixel");
    for (int k = 0; k < 40; k++) {
        int nx = draw_int(&g, 1, 4000), ny = draw_int(&g, 1, 3000);
        double h = log_uniform(&g, 0.01, 100);
        double d = log_uniform(&g, 0.01, 100);
        int j = draw_int(&g, 0, ny - 1);
        tg_pixel(t, draw_int(&g, 0, nx - 1), j, nx, ny, h * nx / ny, h, d);
    }

    t = hidden_test(l, PART3A, KIND_SPHERE, "Part 3a: hidden: random rays at random spheres",
                    "origins outside the sphere; about half the rays hit, some spheres are behind");
    for (int k = 0; k < 120; k++) {
        double R = log_uniform(&g, 0.1, 10), D = R * draw_uni(&g, 1.2, 30);
        double dir[3], c[3], e[3];
        for (int q = 0; q < 3; q++)
            e[q] = draw_uni(&g, -5, 5);
        random_direction(&g, D, c);
        for (int q = 0; q < 3; q++)
            c[q] += e[q];
        /* aim at a point near the sphere: a hit about half the time */
        double aim[3];
        random_direction(&g, R * draw_uni(&g, 0, 2), aim);
        for (int q = 0; q < 3; q++)
            dir[q] = (c[q] + aim[q] - e[q]) * (k % 7 == 0 ? -1 : 1);
        /* |r| from 0.01 to 100, but at most (D - R) / 0.01, so that every
         * hit is at t >= 0.01: hits just ahead of the origin are for the
         * test of rays from just outside (below), and a tmin such as
         * 0.001 must not lose this one by the luck of a seed */
        scale_to(dir, fmin(log_uniform(&g, 0.01, 100), (D - R) / 0.01));
        tg_sphere(t, c, R, e, dir);
    }
    t = hidden_test(l, PART3A, KIND_SPHERE, "Part 3a: hidden: random rays from inside spheres",
                    "every ray starts inside: the hit is where it leaves");
    for (int k = 0; k < 40; k++) {
        double R = log_uniform(&g, 0.1, 100), c[3] = { 1, -2, 3 }, off[3], e[3], dir[3];
        random_direction(&g, R * draw_uni(&g, 0, 0.95), off);
        for (int q = 0; q < 3; q++)
            e[q] = c[q] + off[q];
        random_direction(&g, log_uniform(&g, 0.1, 10), dir);
        tg_sphere(t, c, R, e, dir);
    }

    t = hidden_test(l, PART3A, KIND_SPHERE, "Part 3a: hidden: random rays from just outside spheres",
                    "each ray starts a hair outside the sphere, hits it at t from 1e-9 to 1e-2 "
                    "(tmin = 0), and a plain hit farther on");
    for (int k = 0; k < 12; k++) {
        double R = log_uniform(&g, 0.5, 5), c[3] = { -1, 2, -6 }, u[3], e[3], dir[3];
        double gap = log_uniform(&g, 1e-9, 1e-2);
        random_direction(&g, 1, u);
        for (int q = 0; q < 3; q++) {
            e[q] = c[q] + (R + gap) * u[q];        /* on the line through c, gap outside */
            dir[q] = -u[q];                          /* back towards c: t about gap */
        }
        tg_sphere(t, c, R, e, dir);
        if (k % 3 == 0)
            tg_sphere(t, c, R, (const double[3]){ 0, 0, 0 }, (const double[3]){ -1, 2, -6 });
    }
    t = hidden_test(l, PART3B, KIND_CAMERA, "Part 3b: hidden: camera_ray through random pixels",
                    "eyes anywhere, pixels anywhere: origin e, unit direction towards the pixel");
    for (int k = 0; k < 20; k++) {
        double e[3], p[3];
        random_direction(&g, draw_uni(&g, 0, 5) * (k % 2), e);
        random_direction(&g, log_uniform(&g, 0.01, 100), p);
        for (int q = 0; q < 3; q++)
            p[q] += e[q];
        tg_camera(t, e, p);
    }
    t = hidden_test(l, PART3B, KIND_COLOR, "Part 3b: hidden: ray_color in a random scene of 8 spheres",
                    "rays from the origin through spheres one behind another, between the spheres, "
                    "and at random");
    color_scene(t, &g);
    Test *img = tg_image(l, "Part 3b: hidden: render the wide scene at 64 x 20", "labs/scenes/wide.scene", 64, 20);
    img->hidden = true;
    img = tg_image(l, "Part 3b: hidden: render the behind scene at 32 x 24", "labs/scenes/behind.scene", 32, 24);
    img->hidden = true;

    /* Hard cases drawn from this seed, beyond the public ones. */
    tg_hard(l, seed, 1, true);
}

/* ---- Parts 4 and 5 -------------------------------------------------------- */

void testgen_hidden_flat_random(TestList *l, uint64_t seed)
{
    uint64_t g = seed;
    Test *t = hidden_test(l, PART4, KIND_PLANEHIT, "Part 4: hidden: random rays at random planes",
                          "planes and origins anywhere within 10, any lengths of n and r; about half hit");
    for (int k = 0; k < 60; k++) {
        double p[3], n[3], e[3], r[3], on[3], side[3];
        random_direction(&g, draw_uni(&g, 0, 10), p);
        random_direction(&g, log_uniform(&g, 0.1, 10), n);
        random_direction(&g, draw_uni(&g, 0, 10), e);
        random_direction(&g, draw_uni(&g, 0, 5), side);
        /* aim at a point of the plane: p + side with side's normal part removed */
        double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        double sn = (side[0] * n[0] + side[1] * n[1] + side[2] * n[2]) / nn;
        for (int q = 0; q < 3; q++)
            on[q] = p[q] + side[q] - sn * n[q];
        double len = log_uniform(&g, 0.01, 100);
        for (int q = 0; q < 3; q++)
            r[q] = on[q] - e[q];
        scale_to(r, k % 3 == 0 ? -len : len);
        tg_planehit(t, p, n, e, r);
    }

    t = hidden_test(l, PART5, KIND_TRIANGLE, "Part 5: hidden: random rays at random triangles",
                    "triangles of every shape and size within 10 of the eye; about half the rays hit");
    for (int k = 0; k < 100; k++) {
        double v[3][3], c[3], e[3], w[3], r[3];
        random_direction(&g, draw_uni(&g, 0, 10), c);
        /* the third a tiny one, 1e-5 across and aimed inside (k even, and
         * not a multiple of 9: those rays point away), so that every seed
         * has a hit where |det| is below 1e-8 (an epsilon there loses it) */
        double size = k == 2 ? 1e-5 : log_uniform(&g, 0.01, 5);
        for (int i = 0; i < 3; i++) {
            random_direction(&g, size * draw_uni(&g, 0.2, 1), v[i]);
            for (int q = 0; q < 3; q++)
                v[i][q] += c[q];
        }
        random_direction(&g, draw_uni(&g, 0, 3), e);
        /* aim at a point with random barycentric weights: inside for
         * even k; for odd k outside, beyond each edge in turn (one weight
         * negative, each other one larger than it is negative), so that
         * every seed's misses lie beyond every edge: beyond bc with
         * alpha < 0 and beta, gamma < 1 each, where only beta + gamma > 1
         * tells the miss */
        double sum = 0;
        for (int i = 0; i < 3; i++)
            sum += w[i] = !(k % 2) ? draw_uni(&g, 0.02, 1)
                        : i == (k / 2) % 3 ? -draw_uni(&g, 0.05, 0.45) : draw_uni(&g, 0.5, 1);
        double len = log_uniform(&g, 0.1, 10);
        for (int q = 0; q < 3; q++)
            r[q] = (w[0] * v[0][q] + w[1] * v[1][q] + w[2] * v[2][q]) / sum - e[q];
        scale_to(r, k % 9 == 0 ? -len : len);
        tg_triangle(t, v[0], v[1], v[2], e, r);
    }
}

void testgen_hidden_flat(TestList *l, uint64_t seed)
{
    testgen_hidden_flat_random(l, seed);
    /* Hard cases drawn from this seed, beyond the public ones. */
    tg_hard_flat(l, seed, 1, true);
}
