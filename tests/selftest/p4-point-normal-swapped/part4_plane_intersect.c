/* Self-test of the grader: p4-point-normal-swapped. The point used as the normal and the normal as the point. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    Vec3 n = plane->point;
    double rn = vec3_dot(ray->direction, n);
    double num = vec3_dot(vec3_sub(plane->normal, ray->origin), n);
    if (rn == 0)
        return false;
    double t0 = num / rn;
    if (t0 <= 0)
        return false;
    *t = t0;
    return true;
}
