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

/* Part 3a: the exact answer for the exact inputs. */
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
 * for t: ORACLE_K_T * u * kappa.  The derivation is in oracle.c. */
#define ORACLE_K_T 64.0

/* Part 3b: the unit vector along v, correctly rounded per component. */
Vec3 oracle_unit(Vec3 v);

/* Part 3b: index of the sphere whose hit is closest along ray, or -1 for the
 * background.  *ambiguous is set when another answer is within rounding
 * (a silhouette, or two hits whose t agree to rounding); *alternative is then
 * that other index (-1 = background). */
int oracle_closest(const Scene *scene, const Ray *ray, bool *ambiguous, int *alternative);

#endif
