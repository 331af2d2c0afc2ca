/* Part 4 (optional): where a ray meets a plane. */
#include "raytracer.h"

/*
 * plane_intersect - the point, ahead of the ray's origin, where the ray
 *                   x(t) = e + t r meets the plane (x - p).n = 0.
 *
 * Parameters:
 *   plane        a point p of the plane and its normal n; n need NOT have
 *                unit length
 *   ray          origin e and direction r; r need NOT have unit length
 *   t            out: on a hit, the t > 0 with (e + t r - p).n = 0
 * Returns:       true on a hit (and stores *t), false on a miss (*t unused).
 *                The plane has two sides: a hit from either side counts.
 *                A ray parallel to the plane or lying in it, a plane behind
 *                e, a zero direction or normal, and NaN input are misses.
 * Example:       p = (0, -1, 0), n = (0, 2, 0) (the ground y = -1),
 *                e = (0, 0, 0), r = (0, -0.5, -1):
 *                (p - e).n = -2, r.n = -1, so *t = 2 (the point (0, -1, -2)).
 * Formula:       put x(t) into (x - p).n = 0:  (e - p).n + t (r.n) = 0, so
 *                t = (p - e).n / (r.n);  a hit only when r.n is not 0
 *                (else the ray is parallel to the plane) and t > 0 (tmin =
 *                0); asked so, a NaN t is no hit.
 */
bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    /* TODO Part 4: solve for t; check r.n and t > 0. */
    (void)plane;
    (void)ray;
    (void)t;
    return false;
}
