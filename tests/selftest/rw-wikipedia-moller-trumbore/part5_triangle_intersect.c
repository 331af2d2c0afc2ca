/* Self-test of the grader: rw-wikipedia-moller-trumbore.  The Moller-
 * Trumbore test as Wikipedia's C++ example writes it (NOTE.md): its
 * scalars float, an epsilon of 1e-7 on det and on t. */
#include "raytracer.h"

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    const float EPSILON = 0.0000001;
    Vec3 edge1 = vec3_sub(tri->b, tri->a), edge2 = vec3_sub(tri->c, tri->a);
    Vec3 h = vec3_cross(ray->direction, edge2);
    float a = vec3_dot(edge1, h);
    if (a > -EPSILON && a < EPSILON)
        return false; /* taken for a ray parallel to the triangle */
    float f = 1.0 / a;
    Vec3 s = vec3_sub(ray->origin, tri->a);
    float u = f * vec3_dot(s, h);
    if (u < 0.0 || u > 1.0)
        return false;
    Vec3 q = vec3_cross(s, edge1);
    float v = f * vec3_dot(ray->direction, q);
    if (v < 0.0 || u + v > 1.0)
        return false;
    float tt = f * vec3_dot(edge2, q);
    if (tt > EPSILON) {
        *t = tt;
        return true;
    }
    return false; /* the line meets the triangle, the ray does not */
}
