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
     * A |f|^2.  Instead measure from the point of the line closest to c:
     * l = f - (B / A) r, and the half-chord s satisfies s^2 A = R^2 - l.l,
     * whose error grows only like |f| / R, not (|f| / R)^2. */
    double b = B / A;                   /* the closest point is at t = -b */
    Vec3 l = vec3_sub(f, vec3_scale(r, b));
    double disc = R2 - vec3_dot(l, l);
    if (!(disc >= 0))                   /* a miss, or NaN input */
        return false;
    double s = sqrt(disc) / sqrt(A);    /* not sqrt(disc / A): that overflows */
    /* The roots are -b -+ s.  Take the one of larger size, q, without
     * cancellation; the other is C / (A q), since their product is C / A. */
    double q = -(b + copysign(s, b));
    if (q == 0)                         /* double root at t = 0: no t > 0 */
        return false;
    double t1 = q, t2 = C / (A * q);
    double tnear = t1 < t2 ? t1 : t2, tfar = t1 < t2 ? t2 : t1;
    double root = tnear > 0 ? tnear : tfar;
    if (!(root > 0 && root < INFINITY))   /* behind e, or out of range */
        return false;
    *t = root;
    return true;
}
