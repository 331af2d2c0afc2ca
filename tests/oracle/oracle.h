/*
 * oracle.h - independent, more precise answers for every part: the values the
 * grader's expected results and the benchmark's errors are measured against.
 *
 * Everything is computed in double-double arithmetic (about 106 bits, portable
 * ISO C with fma; see dd.h), from the exact double inputs, and rounded to
 * double once at the end.  None of it shares code with solutions/.
 * This directory is the instructor's: it never ships in the student kit.
 */
#ifndef ORACLE_H
#define ORACLE_H

#include <stdbool.h>
#include "../../labs/raytracer.h"

#define ORACLE_U 0x1p-53            /* unit roundoff of double */

/* Part 1: h = 2 d tan(fov/2 degrees), w = aspect h, each within a few units
 * of 1e-30 relative before the final rounding (so correctly rounded but for
 * ties within that).  Requires 0 < fov < 180. */
void oracle_image_plane(double fov_degrees, double aspect, double d, double *w, double *h);

/* Part 2: the exact pixel centre x = w (2i + 1 - nx) / (2 nx),
 * y = h (ny - 1 - 2j) / (2 ny), z = -d, each correctly rounded. */
Vec3 oracle_pixel(int i, int j, int nx, int ny, double w, double h, double d);

/* Part 3a: the exact answer for the exact inputs.
 *
 * Hit or miss comes from the sign of the exact discriminant; t is the
 * smallest root t > 0 (tangent counts, from inside it is the exit point)
 * rounded once.  NaN input and a zero direction are misses (not ambiguous);
 * infinite input is outside the contract (ambiguous miss).  A negative
 * radius is read as |R| (every formula squares it).
 *
 * ambiguous is set when rounding of the inputs alone (one unit roundoff)
 * could change the answer, so that a correct double method may give
 * either:
 *   - the line passes within ORACLE_K_SILHOUETTE u (|f| + R) of the
 *     silhouette ahead of the origin: | |l| - R | <= that, with f = e - c
 *     and l the offset from the centre to the line's closest point; except
 *     an exact tangent whose every usual intermediate (f, A, B, C, B^2,
 *     A C, B/A, l, l.l, R^2, |r|, r/|r|) is a double without rounding, as
 *     in small-integer examples: every method finds it, so it is a hit;
 *   - the origin is within rounding of the surface, so t > 0 versus t = 0
 *     is in doubt: |f.f - R^2| <= ORACLE_K_SURFACE u (f.f + R^2);
 *   - the smallest root exceeds DBL_MAX (t = inf, hit = false).
 * On an ambiguous miss t is where a hit would be: the line's closest point
 * to the centre when it is ahead (silhouette), else 0 (kappa = inf).
 * oracle_sphere_accepts() says which answers an ambiguous case allows.
 *
 * kappa is derived in oracle.c:
 *     kappa = 1 + R (|f| + R + L) / (L s),   L = t |r|,
 * s the exact half-chord sqrt(R^2 - l.l) (floored at sqrt(u R (|f| + R))
 * within the silhouette band), right for both roots (oracle.c says why
 * numerics.md's criterion is not). */
typedef struct {
    bool hit;          /* a root t > 0 exists (tangent counts)                 */
    double t;          /* on a hit: the smallest root t > 0, rounded to double */
    bool ambiguous;    /* the line passes within rounding of the silhouette, or
                          the origin lies within rounding of the surface:
                          either hit or miss is acceptable                     */
    double kappa;      /* condition number of t (>= 1): a backward-stable
                          method's relative error is at most about K u kappa  */
} OracleHit;

OracleHit oracle_sphere(const Sphere *sphere, const Ray *ray);

/* The relative tolerance the grader allows a correct double implementation
 * for t: ORACLE_K_T * u * kappa.  The derivation of kappa is in oracle.c.
 * Measured over 28 hard families, 40,000 cases each (tests/oracle/hard.h),
 * the worst error in units of u kappa is 1.99 for the reference, 2.02 for
 * the closest-point form on a normalized direction and 2.01 for pbrt's
 * (R - |l|)(R + |l|) with -b -+ s.  8 is the smallest power of two that
 * leaves a factor of 2 (it leaves 4).  The lecture's B^2 - A C stays within
 * it on lecture-like scenes (distance up to about 5 radii: at most 6.6). */
#define ORACLE_K_T 8.0

/* The ambiguity bands of oracle_sphere, in units of u (|f| + R) and of
 * u (f.f + R^2).  The farthest from the silhouette that a correct method
 * (the same three) answered hit/miss wrongly was 1.46; the farthest from
 * the surface, 3.02 (pbrt's form, which finds the near root as -b - s).
 * 8 leaves a factor of 2.6 or more. */
#define ORACLE_K_SILHOUETTE 8.0
#define ORACLE_K_SURFACE    8.0

/* The absolute tolerance for t at hit->t: ORACLE_K_T * u * kappa * t,
 * computed so that it stays finite as t -> 0 (the origin on the surface).
 * hit is oracle_sphere(sphere, ray).  INFINITY when hit->t is not finite. */
double oracle_sphere_t_tolerance(const Sphere *sphere, const Ray *ray, const OracleHit *hit);

/* The hits oracle_sphere_accepts takes for an ambiguous case, as the
 * grader can judge them: *near_tol (>= tol) covers every accepted t whose
 * window reaches that of hit->t (within tol), and [*lo, *hi] is the next
 * window apart from it -- from an origin within rounding of the surface,
 * the root on the far side, or, from just inside, t near 0.  Returns false
 * (*lo > *hi) when there is none. */
bool oracle_sphere_other_hits(const Sphere *sphere, const Ray *ray, const OracleHit *hit,
                              double tol, double *near_tol, double *lo, double *hi);

/* Whether an answer (hit, t) to sphere_intersect(sphere, ray, &t) is
 * correct: the grader's whole rule for Part 3a in one place.
 *   - A hit's t must be finite and > 0.
 *   - Not ambiguous: hit must match, and |t - oracle t| <= the tolerance.
 *   - Ambiguous: a miss is accepted, and so is a hit whose t is within
 *     tolerance of any candidate: the oracle's t, either root >= 0, 0 when
 *     the origin is on the surface, the closest point at the silhouette. */
bool oracle_sphere_accepts(const Sphere *sphere, const Ray *ray, bool hit, double t);

/* Part 3b: the unit vector along v, correctly rounded per component. */
Vec3 oracle_unit(Vec3 v);

/* Part 3b: index of the sphere whose hit is closest along ray, or -1 for the
 * background.  *ambiguous is set when another answer is within rounding
 * (a silhouette, or two hits whose t agree to rounding); *alternative is then
 * that other index (-1 = background).
 * Precisely: ambiguous when the best sphere's oracle_sphere answer is
 * ambiguous (alternative: the next hit, or -1), or when another sphere's
 * acceptable t values (oracle_sphere_accepts) reach below the best one's
 * largest acceptable t (alternative: the sphere whose values start lowest;
 * that one wins over the former).  Exact ties go to the lower index, as a
 * loop that replaces its best only on a strictly smaller t does.
 * Either pointer may be NULL. */
int oracle_closest(const Scene *scene, const Ray *ray, bool *ambiguous, int *alternative);

/* ---- Parts 4 and 5: planes and triangles (flat.c) ------------------------ */

/* The exact answer for a plane or a triangle, and what a correct double
 * method may answer instead.
 *
 * Hit or miss is decided in exact arithmetic (expansion.h): the smallest
 * t > 0 at which the ray meets the plane, or the closed triangle (edges and
 * vertices included); both sides count.  A zero direction, a zero normal,
 * a zero-area triangle, a ray parallel to the plane or lying in it, and NaN
 * input are misses; infinite input is outside the contract (ambiguous).
 * ambiguous is set when rounding of the inputs could change the answer:
 * the ray grazes an edge of the triangle, is parallel within rounding, or
 * starts on the plane within rounding (flat.c says how that is measured).
 * oracle_flat_accepts() applies the rule. */
typedef struct {
    bool hit;          /* a hit at t > 0                                       */
    double t;          /* on a hit, t rounded once; on a miss, where the ray
                          meets the plane (any sign), or 0 when parallel       */
    bool ambiguous;    /* either answer is acceptable                          */
    double tol;        /* accepted |t - this t| (absolute)                     */
    double t_min;      /* parallel within rounding: a hit at t >= t_min is
                          accepted too (INFINITY when not parallel)            */
    double kappa;      /* condition number of t (>= 1)                         */
} OracleFlat;

OracleFlat oracle_plane(const Plane *plane, const Ray *ray);
OracleFlat oracle_triangle(const Triangle *tri, const Ray *ray);

/* Whether the answer (hit, t) is correct, given the oracle's o:
 *   - a hit's t must be finite and > 0;
 *   - a miss is right when the oracle misses or is ambiguous;
 *   - a hit is right when within tol of the oracle's t (also for an
 *     ambiguous miss: a grazed edge, or t near 0), or, parallel within
 *     rounding, at t >= t_min. */
bool oracle_flat_accepts(const OracleFlat *o, bool hit, double t);

/* The first hit of a ray among several triangles, for a closed mesh that
 * the ray crosses away from its silhouette: the smallest exact hit, with
 * the largest tolerance among the triangles hit there (two triangles that
 * share the edge the ray crosses meet it at the same t).  Never ambiguous:
 * a watertight method must hit there.  A ray that hits none gives
 * hit = false. */
OracleFlat oracle_mesh(const Triangle *tris, int n, const Ray *ray);

/* The band of doubt, in units of u times a quantity's sensitivity to
 * rounding of the inputs (flat.c), for edges, parallel rays and origins on
 * the plane.  Measured in tests/unit/test_flat.c. */
#define ORACLE_K_FLAT_BAND 16.0

#endif
