/*
 * suite.c - the table of methods the benchmark compares.
 *
 * For each method two entry points:
 *   one      one ray against one sphere, for the error measurements: float
 *            methods get the double inputs rounded to float (that rounding is
 *            part of their error, as it is in a float renderer)
 *   closest  the renderer's inner loop for many rays: for each ray, every
 *            sphere, keep the nearest hit (as part 3b's ray_color does)
 * The scalar methods are called through a pointer, as ray_color calls
 * sphere_intersect in another file: nothing is inlined, for any of them.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bench.h"

const char *precision_name(Precision p)
{
    return p == PREC_DOUBLE ? "double" : p == PREC_FLOAT ? "float" : "mixed";
}

/* ---- the closest-hit loops ------------------------------------------------ */

static void closest_scalar_d(IsectD fn, const BenchScene *sc, const RaySet *rs, int *idx, double *t)
{
    for (int i = 0; i < rs->n; i++) {
        double tmin = INFINITY;
        int best = -1;
        for (int k = 0; k < sc->n; k++) {
            double tk;
            if (fn(&sc->spheres[k], &rs->rays[i], &tk) && tk < tmin) {
                tmin = tk;
                best = k;
            }
        }
        idx[i] = best;
        t[i] = tmin;
    }
}

static void closest_scalar_f(IsectF fn, const BenchScene *sc, const RaySet *rs, int *idx, double *t)
{
    for (int i = 0; i < rs->n; i++) {
        float tmin = INFINITY;
        int best = -1;
        for (int k = 0; k < sc->n; k++) {
            float tk;
            if (fn(&sc->spheresf[k], &rs->raysf[i], &tk) && tk < tmin) {
                tmin = tk;
                best = k;
            }
        }
        idx[i] = best;
        t[i] = tmin;
    }
}

static bool one_scalar_f(IsectF fn, const Sphere *sphere, const Ray *ray, double *t)
{
    Spheref s = spheref_from(sphere);
    Rayf r = rayf_from(ray);
    float tf;
    if (!fn(&s, &r, &tf))
        return false;
    *t = tf;
    return true;
}

/* One entry per scalar method: NAME_d / NAME_f wrappers around the loops. */
#define SCALAR_D(NAME, FN)                                                              \
    static void closest_##NAME(const BenchScene *sc, const RaySet *rs, int *idx, double *t) \
    {                                                                                   \
        closest_scalar_d(FN, sc, rs, idx, t);                                           \
    }
#define SCALAR_F(NAME, FN)                                                              \
    static void closest_##NAME(const BenchScene *sc, const RaySet *rs, int *idx, double *t) \
    {                                                                                   \
        closest_scalar_f(FN, sc, rs, idx, t);                                           \
    }                                                                                   \
    static bool one_##NAME(const Sphere *sphere, const Ray *ray, double *t)             \
    {                                                                                   \
        return one_scalar_f(FN, sphere, ray, t);                                        \
    }

SCALAR_D(textbook_d, isect_textbook_d)
SCALAR_F(textbook_f, isect_textbook_f)
SCALAR_D(unit_d, isect_unit_d)
SCALAR_F(unit_f, isect_unit_f)
SCALAR_D(geometric_d, isect_geometric_d)
SCALAR_F(geometric_f, isect_geometric_f)
SCALAR_D(rtg_d, isect_rtg_d)
SCALAR_F(rtg_f, isect_rtg_f)
SCALAR_D(reference_d, sphere_intersect)
SCALAR_F(reference_f, isect_reference_f)

/* ---- the fast path ---------------------------------------------------------- */

static void closest_fast_d(const BenchScene *sc, const RaySet *rs, int *idx, double *t)
{
    fast_closest_d(sc->fast, rs->dx, rs->dy, rs->dz, rs->n, idx, t);
}

static void closest_fast_f(const BenchScene *sc, const RaySet *rs, int *idx, double *t)
{
    fast_closest_f(sc->fast, rs->fdx, rs->fdy, rs->fdz, rs->n, idx, t);
}

static void closest_fast_m(const BenchScene *sc, const RaySet *rs, int *idx, double *t)
{
    fast_closest_m(sc->fast, rs->fdx, rs->fdy, rs->fdz, rs->dx, rs->dy, rs->dz, rs->n, idx, t);
}

/* One test: the scene is this one sphere, seen from the ray's origin (the
 * fast path's eye); c - e is rounded once, as f = e - c is elsewhere. */
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

static bool one_fast_d(const Sphere *sphere, const Ray *ray, double *t)
{
    return one_fast(PREC_DOUBLE, sphere, ray, t);
}

static bool one_fast_f(const Sphere *sphere, const Ray *ray, double *t)
{
    return one_fast(PREC_FLOAT, sphere, ray, t);
}

static bool one_fast_m(const Sphere *sphere, const Ray *ray, double *t)
{
    return one_fast(PREC_MIXED, sphere, ray, t);
}

/* ---- the table ---------------------------------------------------------------- */

const Method bench_methods[] = {
    { "textbook", "Textbook quadratic (the lecture's)", PREC_DOUBLE, false, false, LAYOUT_AOS_D,
      isect_textbook_d, closest_textbook_d,
      isect_textbook_d, NULL },
    { "textbook", "Textbook quadratic (the lecture's)", PREC_FLOAT, false, false, LAYOUT_AOS_F,
      one_textbook_f, closest_textbook_f,
      NULL, isect_textbook_f },
    { "unit", "A = 1 form (unit direction)", PREC_DOUBLE, false, true, LAYOUT_AOS_D,
      isect_unit_d, closest_unit_d,
      isect_unit_d, NULL },
    { "unit", "A = 1 form (unit direction)", PREC_FLOAT, false, true, LAYOUT_AOS_F,
      one_unit_f, closest_unit_f,
      NULL, isect_unit_f },
    { "geometric", "Geometric method", PREC_DOUBLE, false, true, LAYOUT_AOS_D,
      isect_geometric_d, closest_geometric_d,
      isect_geometric_d, NULL },
    { "geometric", "Geometric method", PREC_FLOAT, false, true, LAYOUT_AOS_F,
      one_geometric_f, closest_geometric_f,
      NULL, isect_geometric_f },
    { "rtg", "Ray Tracing Gems ch. 7", PREC_DOUBLE, false, false, LAYOUT_AOS_D,
      isect_rtg_d, closest_rtg_d,
      isect_rtg_d, NULL },
    { "rtg", "Ray Tracing Gems ch. 7", PREC_FLOAT, false, false, LAYOUT_AOS_F,
      one_rtg_f, closest_rtg_f,
      NULL, isect_rtg_f },
    { "reference", "Reference (solutions/, linked)", PREC_DOUBLE, false, false, LAYOUT_AOS_D,
      sphere_intersect, closest_reference_d,
      sphere_intersect, NULL },
    { "reference", "Reference, float transliteration", PREC_FLOAT, false, false, LAYOUT_AOS_F,
      one_reference_f, closest_reference_f,
      NULL, isect_reference_f },
    { "fast", "Fast path (eye at origin, SoA, vectorised filter)", PREC_DOUBLE, true, true,
      LAYOUT_SOA_D,
      one_fast_d, closest_fast_d,
      NULL, NULL },
    { "fast", "Fast path (eye at origin, SoA, vectorised filter)", PREC_FLOAT, true, true,
      LAYOUT_SOA_F,
      one_fast_f, closest_fast_f,
      NULL, NULL },
    { "fast", "Fast path, float filter + double solve", PREC_MIXED, true, true,
      LAYOUT_SOA_D | LAYOUT_SOA_F,
      one_fast_m, closest_fast_m,
      NULL, NULL },
};
const int bench_nmethods = (int)(sizeof bench_methods / sizeof bench_methods[0]);

int method_find(const char *name, Precision p)
{
    for (int m = 0; m < bench_nmethods; m++)
        if (strcmp(bench_methods[m].name, name) == 0 && bench_methods[m].precision == p)
            return m;
    return -1;
}
