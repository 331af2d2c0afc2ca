/* Self-test of the grader: rw-scratchapixel-triangle-geometric.
 * Scratchapixel's rayTriangleIntersect without MOLLER_TRUMBORE (NOTE.md):
 * the plane of the triangle, then an inside-outside test per edge; float,
 * fabs(N.r) < kEpsilon = 1e-8 a miss, t < 0 a miss. */
#include "raytracer.h"
#include <math.h>

static const float kEpsilon = 1e-8;

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 v0 = tri->a, v1 = tri->b, v2 = tri->c;
    Vec3 v0v1 = vec3_sub(v1, v0);
    Vec3 v0v2 = vec3_sub(v2, v0);
    Vec3 N = vec3_cross(v0v1, v0v2); /* no need to normalize */

    /* step 1: the point P where the ray meets the triangle's plane */
    float NdotRayDirection = vec3_dot(N, ray->direction);
    if (fabs(NdotRayDirection) < kEpsilon)
        return false; /* parallel */
    float d = -vec3_dot(N, v0);
    float tt = -(vec3_dot(N, ray->origin) + d) / NdotRayDirection;
    if (tt < 0)
        return false; /* the triangle is behind */
    Vec3 P = vec3_add(ray->origin, vec3_scale(ray->direction, tt));

    /* step 2: inside-outside, edge by edge */
    Vec3 C = vec3_cross(vec3_sub(v1, v0), vec3_sub(P, v0));
    if (vec3_dot(N, C) < 0)
        return false;
    C = vec3_cross(vec3_sub(v2, v1), vec3_sub(P, v1));
    if (vec3_dot(N, C) < 0)
        return false;
    C = vec3_cross(vec3_sub(v0, v2), vec3_sub(P, v2));
    if (vec3_dot(N, C) < 0)
        return false;

    *t = tt;
    return true;
}
