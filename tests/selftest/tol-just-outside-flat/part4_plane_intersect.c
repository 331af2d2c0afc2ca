/* Self-test of the grader: tol-just-outside-flat.  A right Part 4 whose t is
 * multiplied by 1 + 1.5e-9, just outside the core tolerance of
 * 1e-9 of t. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    double rn = vec3_dot(ray->direction, plane->normal);
    double root = vec3_dot(vec3_sub(plane->point, ray->origin), plane->normal) / rn;
    if (!(root > 0 && root < INFINITY))
        return false;
    *t = root * (1 + 1.5e-9);
    return true;
}
