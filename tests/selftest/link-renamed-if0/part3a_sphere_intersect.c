/* Self-test of the grader: link-renamed-if0.  The function renamed
 * sphere_intersect_v2, and an old version of sphere_intersect kept under
 * #if 0: the part does not link, and the message names the function the
 * file does define (the one under #if 0 is not code). */
#include "raytracer.h"

/*
 * sphere_intersect - the first point, ahead of the ray's origin, where the
 *                    ray x(t) = e + t r meets the sphere |x - c| = R.
 *
 * Parameters:
 *   sphere       centre c and radius R > 0
 *   ray          origin e and direction r; r need NOT have unit length
 *   t            out: on a hit, the smallest t > 0 with |e + t r - c| = R
 * Returns:       true on a hit (and stores *t), false on a miss (*t unused).
 *                A tangent ray hits. From inside the sphere the hit is the
 *                exit point. A sphere wholly behind e, a zero direction and
 *                NaN input are misses.
 * Example:       c = (0, 0, -5), R = 1, e = (0, 0, 0), r = (0, 0, -2):
 *                roots t = 2 and t = 3, so *t = 2 (the point (0, 0, -4)).
 * Formula:       with f = e - c, put x(t) into |x - c|^2 = R^2:
 *                A t^2 + 2 B t + C = 0,  A = r.r,  B = f.r,  C = f.f - R^2
 *                t = (-B -+ sqrt(B^2 - A C)) / A;  no hit when B^2 - A C < 0;
 *                take the smallest root t > 0 (tmin = 0).
 */
#if 0
bool sphere_intersect(const Sphere *s, const Ray *ray, double *t) { return false; }
#endif
bool sphere_intersect_v2(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 r = ray->direction;
    Vec3 f = vec3_sub(ray->origin, sphere->center);     /* f = e - c */
    double R2 = sphere->radius * sphere->radius;
    double A = vec3_dot(r, r);
    double AR2 = A * R2;

    /* The discriminant B^2 - A C, computed without cancellation.  By
     * Lagrange's identity (f.f)(r.r) - (f.r)^2 = |f x r|^2, so
     *     B^2 - A C = A R^2 - |f x r|^2,
     * and |f x r|^2 / A is the squared distance from c to the line: the
     * line meets the sphere when that distance is at most R.  Written as
     * B^2 - A C it loses the radius when the sphere is small and far (both
     * terms are about A |f|^2 and their difference is rounding error); this
     * form's error grows only like |f| / R (Ray Tracing Gems, ch. 7). */
    Vec3 n = vec3_cross(f, r);

    /* Most rays miss most spheres, so the miss test stops as soon as it
     * can.  nn = |f x r|^2 is summed a term at a time, and adding a term
     * that is not negative never makes a rounded sum smaller: once a
     * partial sum exceeds A R^2, the whole one does too, and the line
     * misses.  n.x comes first because for the lab's camera (looking
     * down -z) it is how far above or below c the ray passes, the same
     * along a row of pixels, so the branch is well predicted.  T is
     * A R^2 itself unless A R^2 is tiny (below 2^-969); there T also
     * guarantees nn - A R^2 > DBL_MIN, the careful branch's miss test.
     * NaNs fail every comparison and go on. */
    double T = AR2 + 2 * DBL_MIN;
    double nn = n.x * n.x;
    if (nn > T)
        return false;
    nn += n.y * n.y;
    if (nn > T)
        return false;
    nn += n.z * n.z;
    if (nn > T)
        return false;

    double sq;                          /* sqrt(disc), disc = B^2 - A C */
    if (AR2 > 0x1p-900 && AR2 < 0x1p+900) {
        sq = sqrt(AR2 - nn);            /* nn <= A R^2 here, or NaN */
    } else {
        /* r so short or long that A R^2 leaves the range of double (or
         * NaN input).  A difference nn - A R^2 that small may be rounding
         * of underflowed terms: only a clear miss is trusted.  Measure
         * instead from l = f - (B / A) r, the point of the line closest to
         * c, whose size does not depend on |r|:
         * disc = A (R^2 - l.l), and sqrt(disc) = sqrt(A) sqrt(R^2 - l.l). */
        if (nn - AR2 > DBL_MIN)
            return false;
        if (!(A > 0))                   /* zero or NaN direction */
            return false;
        Vec3 l = vec3_sub(f, vec3_scale(r, vec3_dot(f, r) / A));
        double D = R2 - vec3_dot(l, l);
        if (!(D >= 0))                  /* a miss, or NaN input */
            return false;
        sq = sqrt(A) * sqrt(D);
    }

    /* The roots are (-B -+ sq) / A.  Take the one of larger size without
     * cancellation, q / A with q = -(B + sign(B) sq), a sum of two numbers
     * of one sign; the other is C / q, since the product of the roots is
     * C / A. */
    double B = vec3_dot(f, r);
    double C = vec3_dot(f, f) - R2;
    double q = B < 0 ? sq - B : -(B + sq);
    double root = C / q;                /* the root nearer 0 */
    if (!(root > 0))                    /* behind e: try the other one */
        root = q / A;
    /* Both roots behind e (a sphere behind, or outside and heading away),
     * a double root at t = 0 (q = 0 gives NaN or infinity), or a t out of
     * range: no hit. */
    if (!(root > 0) || root >= INFINITY)
        return false;
    *t = root;
    return true;
}
