/* Self-test of the grader: tol-just-outside-flat.  A right Part 5 whose t is
 * multiplied by 1 + 1.5e-9, just outside the core tolerance of
 * 1e-9 of t. */
#include "raytracer.h"

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 e1 = vec3_sub(tri->b, tri->a), e2 = vec3_sub(tri->c, tri->a);
    Vec3 s = vec3_sub(ray->origin, tri->a), q = vec3_cross(ray->direction, e2);
    double det = vec3_dot(e1, q);
    if (det == 0)
        return false;
    double beta = vec3_dot(s, q) / det;
    Vec3 sx = vec3_cross(s, e1);
    double gamma = vec3_dot(ray->direction, sx) / det;
    if (!(beta >= 0 && gamma >= 0 && beta + gamma <= 1))
        return false;
    double root = vec3_dot(e2, sx) / det;
    if (!(root > 0 && root < INFINITY))
        return false;
    *t = root * (1 + 1.5e-9);
    return true;
}
