/*
 * fastpath.c - the specialised fast path: what the lab's scenes need and
 * nothing more.
 *
 * The eye is the origin of every ray, so per sphere the centre relative to
 * the eye, c, and C = |c|^2 - R^2 are computed once, not once per ray.  Rays
 * are camera rays, so |r| = 1 and the quadratic is t^2 - 2 b t + C = 0 with
 * b = c.r: a ray can meet the sphere only if b^2 >= C.
 *
 * For one sphere and a packet of FAST_PACKET rays the work is split in two
 * fixed-length loops without branches, which the compiler vectorises
 * (SSE2 / NEON at -O2):
 *   1. filter: b = c.r and the test b >= sqrt(C), with the threshold set a
 *      little lower to cover every rounding (so no true hit is ever filtered
 *      out).  Three multiplies, two adds and a compare: no sqrt, no
 *      division.  Most rays miss most spheres, so for most (sphere, packet)
 *      pairs no ray passes and the pair costs nothing more.
 *   2. solve, for packets where some ray passed: the accurate root of Ray
 *      Tracing Gems ch. 7 -- discriminant R^2 - |c - b r|^2, and the near
 *      root as C / (b + sqrt(disc)), which does not cancel -- and the
 *      nearest hit so far kept, for the rays that pass the same test.
 * The per-ray choices are made with masks, not branches: a comparison's
 * answer is read from the sign bit of a difference, and values are blended
 * with and/or.  (gcc cannot vectorise a double comparison turned into a
 * 64-bit integer with plain SSE2, nor a ?: between two arrays, but it does
 * vectorise these.)  sqrt is vectorised only if the compiler need not set
 * errno, hence -fno-math-errno for this file (it changes no result).
 * The filter takes two spheres per pass over the packet, so each ray is
 * loaded once for both.  A sphere that contains the eye (C <= 0) is solved
 * ray by ray: it is rare.  fast_closest_m runs the filter in float (four
 * lanes) and the solve in double; its answers are the double path's.
 * C itself is computed exactly (products split with fma, sums in double-
 * double) and rounded once, which is affordable because it happens once per
 * sphere; so the fast path is also more accurate than the per-ray formulas
 * for rays that start close to a big sphere.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "bench.h"

/* ---- building the per-sphere data --------------------------------------- */

/* a + b = s + e exactly (Knuth's two-sum). */
static void two_sum(double a, double b, double *s, double *e)
{
    double z = a + b, bb = z - a;
    *s = z;
    *e = (a - (z - bb)) + (b - bb);
}

/* hi + lo = hi_in + lo_in + x, in double-double. */
static void dd_add(double *hi, double *lo, double x)
{
    double s, e;
    two_sum(*hi, x, &s, &e);
    e += *lo;
    two_sum(s, e, hi, lo);
}

/* a * a + b * b + c * c - r * r, each product exact (fma gives its low
 * part), summed in double-double and rounded once. */
static double exact_c(double a, double b, double c, double r)
{
    double v[4] = { a, b, c, r }, hi = 0, lo = 0;
    for (int k = 0; k < 4; k++) {
        double sign = k < 3 ? 1 : -1;
        double p = v[k] * v[k];
        double e = fma(v[k], v[k], -p);
        dd_add(&hi, &lo, sign * p);
        dd_add(&hi, &lo, sign * e);
    }
    return hi + lo;
}

int fast_build(FastScene *fs, const Sphere *spheres, int n, Vec3 eye)
{
    fs->n = n;
    size_t m = n > 0 ? (size_t)n : 1;
    fs->cx = malloc(6 * m * sizeof(double));
    fs->fcx = malloc(6 * m * sizeof(float));
    if (!fs->cx || !fs->fcx) {
        fast_free(fs);
        return -1;
    }
    fs->cy = fs->cx + m;
    fs->cz = fs->cx + 2 * m;
    fs->r2 = fs->cx + 3 * m;
    fs->c = fs->cx + 4 * m;
    fs->bthr = fs->cx + 5 * m;
    fs->fcy = fs->fcx + m;
    fs->fcz = fs->fcx + 2 * m;
    fs->fr2 = fs->fcx + 3 * m;
    fs->fc = fs->fcx + 4 * m;
    fs->fbthr = fs->fcx + 5 * m;
    for (int k = 0; k < n; k++) {
        const Sphere *s = &spheres[k];
        double cx = s->center.x - eye.x, cy = s->center.y - eye.y, cz = s->center.z - eye.z;
        double R = s->radius;
        double C = exact_c(cx, cy, cz, R);
        double len = sqrt(cx * cx + cy * cy + cz * cz);
        fs->cx[k] = cx;
        fs->cy[k] = cy;
        fs->cz[k] = cz;
        fs->r2[k] = R * R;
        fs->c[k] = C;
        /* From outside (C > 0) a ray meets the sphere only if b >= sqrt(C)
         * (exactly: b^2 >= A C with A = |r|^2 = 1 to a few u).  fl(b) is
         * within 3.x u |c| of b, so b below sqrt(C) - 8 eps |c| is a certain
         * miss.  From inside every ray hits: no filter. */
        fs->bthr[k] = C > 0 ? sqrt(C) * (1 - 4 * DBL_EPSILON) - 8 * DBL_EPSILON * len : -INFINITY;
        /* Float: the same data rounded once.  The float threshold also
         * covers the rounding of c and r to float, and lies below the double
         * one by more than the float b can differ from the double b: so a
         * ray that passes the double filter passes the float one too. */
        fs->fcx[k] = (float)cx;
        fs->fcy[k] = (float)cy;
        fs->fcz[k] = (float)cz;
        fs->fr2[k] = (float)(R * R);
        fs->fc[k] = (float)C;
        double fthr = fs->bthr[k] - 16 * FLT_EPSILON * len;
        float f = (float)fthr;
        fs->fbthr[k] = C > 0 ? ((double)f > fthr ? nextafterf(f, -INFINITY) : f) : -INFINITY;
    }
    return 0;
}

void fast_free(FastScene *fs)
{
    free(fs->cx);
    free(fs->fcx);
    fs->cx = NULL;
    fs->fcx = NULL;
    fs->n = 0;
}

/* ---- the packet loops, for double and for float ------------------------------ */

/* fastpath_body.h holds the filter, the solve and the packet loop, written
 * once and compiled for double (uint64_t masks) and for float (uint32_t). */
#define REAL double
#define UINT uint64_t
#define SIGN_SHIFT 63
#define BIG DBL_MAX
#define SQRT sqrt
#define COPYSIGN copysign
#define FIELD(name) name
#define NAME(x) x##_d
#include "fastpath_body.h"
#undef REAL
#undef UINT
#undef SIGN_SHIFT
#undef BIG
#undef SQRT
#undef COPYSIGN
#undef FIELD
#undef NAME

#define REAL float
#define UINT uint32_t
#define SIGN_SHIFT 31
#define BIG FLT_MAX
#define SQRT sqrtf
#define COPYSIGN copysignf
#define FIELD(name) f##name
#define NAME(x) x##_f
#include "fastpath_body.h"

/* Mixed: the float filter decides which packets to solve (its threshold
 * lets through every ray the double filter would), then the double solve
 * decides ray by ray exactly as the double path does: the answers are the
 * double path's, bit for bit. */
void fast_closest_m(const FastScene *fs, const float *fdx, const float *fdy, const float *fdz,
                    const double *dx, const double *dy, const double *dz,
                    int count, int *idx, double *t)
{
    for (int p0 = 0; p0 < count; p0 += FAST_PACKET) {
        int np = count - p0 < FAST_PACKET ? count - p0 : FAST_PACKET;
        const float *frx, *fry, *frz;
        const double *rx, *ry, *rz;
        float fpad[3][FAST_PACKET];
        double pad[3][FAST_PACKET], tbest[FAST_PACKET];
        uint64_t kbest[FAST_PACKET];
        packet_rays_f(fdx, fdy, fdz, p0, np, fpad, &frx, &fry, &frz);
        packet_rays_d(dx, dy, dz, p0, np, pad, &rx, &ry, &rz);
        packet_start_d(tbest, kbest);
        for (int k = 0; k < fs->n; k++) {
            if (!(fs->c[k] > 0))
                solve_rays_d(fs, k, rx, ry, rz, np, tbest, kbest);
            else if (filter_f(fs->fcx[k], fs->fcy[k], fs->fcz[k], fs->fbthr[k], frx, fry, frz))
                solve_outside_d(fs, k, rx, ry, rz, tbest, kbest);
        }
        packet_finish_d(tbest, kbest, np, idx + p0, t + p0);
    }
}

long fast_filter_only(const FastScene *fs, const double *dx, const double *dy, const double *dz,
                      int count)
{
    long passed = 0;
    for (int p0 = 0; p0 < count; p0 += FAST_PACKET) {
        int np = count - p0 < FAST_PACKET ? count - p0 : FAST_PACKET;
        const double *rx, *ry, *rz;
        double pad[3][FAST_PACKET];
        packet_rays_d(dx, dy, dz, p0, np, pad, &rx, &ry, &rz);
        for (int k = 0; k < fs->n; k++) {
            if (!(fs->c[k] > 0)) {
                passed++;
            } else if (k + 1 < fs->n && fs->c[k + 1] > 0) {
                unsigned pass = filter2_d(fs, k, rx, ry, rz);
                passed += (long)(pass & 1u) + (long)(pass >> 1);
                k++;
            } else {
                passed += filter_d(fs->cx[k], fs->cy[k], fs->cz[k], fs->bthr[k], rx, ry, rz);
            }
        }
    }
    return passed;
}
