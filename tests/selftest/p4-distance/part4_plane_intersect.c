/* Self-test of the grader: p4-distance. Normalises r and returns the distance. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    Vec3 n = plane->normal;
    Vec3 r = vec3_normalize(ray->direction);
    double rn = vec3_dot(r, n);
    double num = vec3_dot(vec3_sub(plane->point, ray->origin), n);
    if (rn == 0)
        return false;
    double t0 = num / rn;
    if (t0 <= 0)
        return false;
    *t = t0;
    return true;
}
