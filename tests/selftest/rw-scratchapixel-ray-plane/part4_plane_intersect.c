/* Self-test of the grader: rw-scratchapixel-ray-plane.  Scratchapixel's
 * intersectPlane (NOTE.md): float, denom = n.r > 1e-6 (the normal taken to
 * point along the ray: one side only), and t >= 0 a hit. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    /* the source: "assuming vectors are all normalized" */
    float denom = vec3_dot(plane->normal, ray->direction);
    if (denom > 1e-6) {
        Vec3 p0l0 = vec3_sub(plane->point, ray->origin);
        float tt = vec3_dot(p0l0, plane->normal) / denom;
        *t = tt;
        return (tt >= 0);
    }
    return false;
}
