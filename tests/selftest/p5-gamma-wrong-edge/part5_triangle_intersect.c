/* Self-test of the grader: p5-gamma-wrong-edge.  gamma from s x e2, not
 * s x e1: almost every hit is missed, for a reason the grader has no model
 * of, so no hint may put the misses down to one (an epsilon on det fitted
 * the far tiny triangles, all of whose hits it misses too). */
#include "raytracer.h"

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 e1 = vec3_sub(tri->b, tri->a), e2 = vec3_sub(tri->c, tri->a);
    Vec3 s = vec3_sub(ray->origin, tri->a);
    Vec3 q = vec3_cross(ray->direction, e2);
    double det = vec3_dot(e1, q);
    if (det == 0)
        return false;
    double beta = vec3_dot(s, q) / det;
    double gamma = vec3_dot(ray->direction, vec3_cross(s, e2)) / det;
    if (beta < 0 || gamma < 0 || beta + gamma > 1)
        return false;
    double t0 = vec3_dot(e2, vec3_cross(s, e1)) / det;
    if (!(t0 > 0))
        return false;
    *t = t0;
    return true;
}
