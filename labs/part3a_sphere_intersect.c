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
    /* TODO Part 3a: solve the quadratic, return the smallest root t > 0. */
    (void)sphere;
    (void)ray;
    (void)t;
    return false;
}
