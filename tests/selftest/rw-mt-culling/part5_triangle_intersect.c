/* Part 5 after Moller and Trumbore, "Fast, Minimum Storage Ray/Triangle
 * Intersection" (JGT 1997), the TEST_CULL branch of its listing:
 * EPSILON 0.000001, edge1 = vert1 - vert0, edge2 = vert2 - vert0, pvec =
 * dir x edge2, det = edge1 . pvec, no hit when det < EPSILON; tvec = orig
 * - vert0, u = tvec . pvec, no hit when u < 0 or u > det; qvec = tvec x
 * edge1, v = dir . qvec, no hit when v < 0 or u + v > det; t = edge2 .
 * qvec / det.  The listing does not test t; the caller keeps t > 0. */
#include "raytracer.h"

#define EPSILON 0.000001

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 edge1 = vec3_sub(tri->b, tri->a);
    Vec3 edge2 = vec3_sub(tri->c, tri->a);
    Vec3 pvec = vec3_cross(ray->direction, edge2);
    double det = vec3_dot(edge1, pvec);
    if (det < EPSILON)
        return false;
    Vec3 tvec = vec3_sub(ray->origin, tri->a);
    double u = vec3_dot(tvec, pvec);
    if (u < 0.0 || u > det)
        return false;
    Vec3 qvec = vec3_cross(tvec, edge1);
    double v = vec3_dot(ray->direction, qvec);
    if (v < 0.0 || u + v > det)
        return false;
    double inv_det = 1.0 / det;
    double root = vec3_dot(edge2, qvec) * inv_det;
    if (!(root > 0))
        return false;
    *t = root;
    return true;
}
