/* Self-test of the grader: p4-tmin-small. An epsilon of 1e-6 against
 * shadow acne: it drops only the nearest hits, below the tests' own hint
 * of a tmin such as 0.001. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    Vec3 n = plane->normal;
    double rn = vec3_dot(ray->direction, n);
    double num = vec3_dot(vec3_sub(plane->point, ray->origin), n);
    if (rn == 0)
        return false;
    double t0 = num / rn;
    if (t0 < 1e-6)
        return false;
    *t = t0;
    return true;
}
