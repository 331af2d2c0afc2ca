/* Self-test of the grader: rw-scratchapixel-moller-trumbore.  Scratchapixel's
 * rayTriangleIntersect built with MOLLER_TRUMBORE and without CULLING
 * (NOTE.md): float, fabs(det) < kEpsilon = 1e-8 a miss, and no test of t. */
#include "raytracer.h"
#include <math.h>

static const float kEpsilon = 1e-8;

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 v0v1 = vec3_sub(tri->b, tri->a);
    Vec3 v0v2 = vec3_sub(tri->c, tri->a);
    Vec3 pvec = vec3_cross(ray->direction, v0v2);
    float det = vec3_dot(v0v1, pvec);
    /* ray and triangle are parallel if det is close to 0 */
    if (fabs(det) < kEpsilon)
        return false;
    float invDet = 1 / det;

    Vec3 tvec = vec3_sub(ray->origin, tri->a);
    float u = vec3_dot(tvec, pvec) * invDet;
    if (u < 0 || u > 1)
        return false;

    Vec3 qvec = vec3_cross(tvec, v0v1);
    float v = vec3_dot(ray->direction, qvec) * invDet;
    if (v < 0 || u + v > 1)
        return false;

    float tt = vec3_dot(v0v2, qvec) * invDet;
    *t = tt;
    return true;
}
