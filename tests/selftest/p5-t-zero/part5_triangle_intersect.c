/* Self-test of the grader: p5-t-zero. Accepts t = 0 (t < 0 is the only miss). */
#include "raytracer.h"

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 e1 = vec3_sub(tri->b, tri->a), e2 = vec3_sub(tri->c, tri->a);
    Vec3 s = vec3_sub(ray->origin, tri->a);
    Vec3 q = vec3_cross(ray->direction, e2);
    double det = vec3_dot(e1, q);
    if (det == 0)
        return false;
    double inv = 1 / det;
    double beta = vec3_dot(s, q) * inv;
    if (beta < 0 || beta > 1)
        return false;
    Vec3 sx = vec3_cross(s, e1);
    double gamma = vec3_dot(ray->direction, sx) * inv;
    if (gamma < 0 || beta + gamma > 1)
        return false;
    double t0 = vec3_dot(e2, sx) * inv;
    if (t0 < 0)
        return false;
    *t = t0;
    return true;
}
