/* Self-test of the grader: p4-no-parallel-check-nan-safe. Divides by r.n without checking it,
 * and refuses t with !(t > 0), so only an infinite t gets through. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    Vec3 n = plane->normal;
    double rn = vec3_dot(ray->direction, n);
    double num = vec3_dot(vec3_sub(plane->point, ray->origin), n);
    double t0 = num / rn;
    if (!(t0 > 0))
        return false;
    *t = t0;
    return true;
}
