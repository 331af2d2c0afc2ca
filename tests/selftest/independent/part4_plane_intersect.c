/* Self-test: Part 4 written apart from the reference, as a student might
 * from the plane's equation n.x = D: the normal made unit first, the
 * plane's constant D = n.p, then t = (D - n.e) / (n.r). */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    Vec3 n = vec3_normalize(plane->normal);
    double D = vec3_dot(n, plane->point);
    double denom = vec3_dot(n, ray->direction);
    if (denom == 0)
        return false;
    double root = (D - vec3_dot(n, ray->origin)) / denom;
    if (!(root > 0) || root == INFINITY)
        return false;
    *t = root;
    return true;
}
