/* Part 3a: where a ray meets a sphere. */
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
bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 r = ray->direction;
    Vec3 f = vec3_sub(ray->origin, sphere->center);     /* f = e - c */
    double R2 = sphere->radius * sphere->radius;
    double A = vec3_dot(r, r);
    double B = vec3_dot(f, r);
    double ff = vec3_dot(f, f);
    double C = ff - R2;

    if (!(A > 0))                       /* zero or NaN direction */
        return false;
    if (C > 0 && B >= 0)                /* outside and heading away */
        return false;
    /* Most rays miss most spheres: when the lecture's B^2 - A C is below
     * minus a bound on its rounding error, the miss is certain and costs
     * no more than the lecture's test.  The bound, 16 eps A (f.f + R^2),
     * covers the roundings of f, A, B, C and the products (about 21 u);
     * DBL_MIN keeps it positive when the products underflow. */
    if (B * B - A * C < -(16 * DBL_EPSILON * A * (ff + R2) + DBL_MIN))
        return false;

    /* Otherwise solve accurately (Ray Tracing Gems, ch. 7).  B^2 - A C loses
     * the radius when the sphere is small and far: both terms are about
     * A |f|^2.  Instead measure from the point of the line closest to c,
     * l = f - (B / A) r: then B^2 - A C = A (R^2 - l.l), whose error grows
     * only like |f| / R, not (|f| / R)^2. */
    Vec3 l = vec3_sub(f, vec3_scale(r, B / A));
    double D = R2 - vec3_dot(l, l);
    if (!(D >= 0))                      /* a miss, or NaN input */
        return false;
    double AD = A * D;                  /* = B^2 - A C, accurately */
    double sq = AD > 0x1p-900 && AD < 0x1p+900 ? sqrt(AD) : sqrt(A) * sqrt(D);
    /* The roots are (-B -+ sq) / A.  Take the one of larger size without
     * cancellation, q / A with q = -(B + sign(B) sq); the other is C / q,
     * since the product of the roots is C / A. */
    double q = -(B + copysign(sq, B));
    if (q == 0)                         /* a double root at t = 0: no t > 0 */
        return false;
    double root = C / q;                /* the root nearer 0 */
    if (!(root > 0))                    /* behind e: try the other one */
        root = q / A;
    if (!(root > 0 && root < INFINITY)) /* both behind e, or out of range */
        return false;
    *t = root;
    return true;
}
