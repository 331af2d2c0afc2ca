/* Self-test of the grader: p4-epsilon. Two-sided, but |r.n| below an
 * epsilon is taken for parallel, as Scratchapixel's denom > 1e-6 does. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    double denom = vec3_dot(plane->normal, ray->direction);
    if (fabs(denom) < 1e-6)
        return false;
    double t0 = vec3_dot(vec3_sub(plane->point, ray->origin), plane->normal) / denom;
    if (!(t0 > 0))
        return false;
    *t = t0;
    return true;
}
