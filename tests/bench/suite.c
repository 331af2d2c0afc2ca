/*
 * suite.c - the table of methods the benchmark compares.
 *
 * For each method two entry points:
 *   method_one      one ray against one sphere, for the error measurements:
 *                   float methods get the double inputs rounded to float
 *                   (that rounding is part of their error, as it is in a
 *                   float renderer)
 *   method_closest  the renderer's inner loop for many rays: for each ray,
 *                   every sphere, keep the nearest hit (as part 3b's
 *                   ray_color does)
 * The scalar methods are called through a pointer, as ray_color calls
 * sphere_intersect in another file: nothing is inlined, for any of them.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench.h"

const char *precision_name(Precision p)
{
    return p == PREC_DOUBLE ? "double" : p == PREC_FLOAT ? "float" : "mixed";
}

char *method_cells(char *buf, const char *name, Precision p, const char *sep)
{
    snprintf(buf, METHOD_LABEL, "%s%s%s", name, sep, precision_name(p));
    return buf;
}

/* ---- the closest-hit loops ------------------------------------------------ */

void method_closest(const Method *m, const BenchScene *sc, const RaySet *rs, int *idx, double *t)
{
    if (m->scalar_d)
        closest_d(m->scalar_d, sc->spheres, sc->n, rs->rays, rs->n, idx, t);
    else if (m->scalar_f)
        closest_f(m->scalar_f, sc->spheresf, sc->n, rs->raysf, rs->n, idx, t);
    else if (m->precision == PREC_DOUBLE)
        fast_closest_d(sc->fast, rs->dx, rs->dy, rs->dz, rs->n, idx, t);
    else if (m->precision == PREC_FLOAT)
        fast_closest_f(sc->fast, rs->fdx, rs->fdy, rs->fdz, rs->n, idx, t);
    else
        fast_closest_m(sc->fast, rs->fdx, rs->fdy, rs->fdz, rs->dx, rs->dy, rs->dz, rs->n, idx, t);
}

/* ---- one test ----------------------------------------------------------------- */

/* The fast path's: the scene is this one sphere, seen from the ray's origin
 * (the fast path's eye); c - e is rounded once, as f = e - c is elsewhere. */
static bool one_fast(Precision p, const Sphere *sphere, const Ray *ray, double *t)
{
    FastScene fs;
    if (fast_build(&fs, sphere, 1, ray->origin) != 0)
        abort();
    double dx = ray->direction.x, dy = ray->direction.y, dz = ray->direction.z;
    float fx = (float)dx, fy = (float)dy, fz = (float)dz;
    int idx;
    if (p == PREC_DOUBLE)
        fast_closest_d(&fs, &dx, &dy, &dz, 1, &idx, t);
    else if (p == PREC_FLOAT)
        fast_closest_f(&fs, &fx, &fy, &fz, 1, &idx, t);
    else
        fast_closest_m(&fs, &fx, &fy, &fz, &dx, &dy, &dz, 1, &idx, t);
    fast_free(&fs);
    return idx == 0;
}

bool method_one(const Method *m, const Sphere *sphere, const Ray *ray, double *t)
{
    if (m->scalar_d)
        return m->scalar_d(sphere, ray, t);
    if (!m->scalar_f)
        return one_fast(m->precision, sphere, ray, t);
    Spheref s = spheref_from(sphere);
    Rayf r = rayf_from(ray);
    float tf;
    if (!m->scalar_f(&s, &r, &tf))
        return false;
    *t = tf;
    return true;
}

/* ---- the table ---------------------------------------------------------------- */

/* name, precision, assumes |r| = 1, the ray layouts it reads, the scalar
 * function (none: the fast path; mixed: its float filter, double solve);
 * in the order of their names in bench.h (TEXTBOOK_D ... FAST_M).  A
 * scalar method is two rows, its double and its float function. */
#define SCALAR(name, unit, fn_d, fn_f)                          \
    { name, PREC_DOUBLE, unit, LAYOUT_AOS_D, fn_d, NULL },      \
    { name, PREC_FLOAT, unit, LAYOUT_AOS_F, NULL, fn_f }
const Method bench_methods[] = {
    SCALAR("textbook", false, isect_textbook_d, isect_textbook_f),
    SCALAR("unit", true, isect_unit_d, isect_unit_f),
    SCALAR("geometric", true, isect_geometric_d, isect_geometric_f),
    SCALAR("rtg", false, isect_rtg_d, isect_rtg_f),
    SCALAR("reference", false, sphere_intersect, isect_reference_f),
    { "fast", PREC_DOUBLE, true, LAYOUT_SOA_D, NULL, NULL },
    { "fast", PREC_FLOAT, true, LAYOUT_SOA_F, NULL, NULL },
    { "fast", PREC_MIXED, true, LAYOUT_SOA_D | LAYOUT_SOA_F, NULL, NULL },
};
const int bench_nmethods = (int)(sizeof bench_methods / sizeof bench_methods[0]);
_Static_assert(sizeof bench_methods / sizeof bench_methods[0] == FAST_M + 1,
               "a name in bench.h for each method");
