/* Self-test of the grader: textbook-ground.  The textbook's ray/plane test,
 * t = (p - e).n / (r.n), right: r.n = 0 and t <= 0 (or NaN) are misses. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    double rn = vec3_dot(ray->direction, plane->normal);
    if (rn == 0)
        return false;
    double t0 = vec3_dot(vec3_sub(plane->point, ray->origin), plane->normal) / rn;
    if (!(t0 > 0) || t0 >= INFINITY)
        return false;
    *t = t0;
    return true;
}
