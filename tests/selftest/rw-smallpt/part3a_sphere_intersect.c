/* Real-world method: smallpt (Kevin Beason, Sphere::intersect), converted to
 * the kit: op = c - e, b = op.r with r taken to be a unit vector,
 * det = b^2 - op.op + R^2, and the first of b - sqrt(det), b + sqrt(det)
 * beyond eps = 1e-4; 0 means no hit. */
#include "raytracer.h"

/* The distance to the hit, 0 when there is none. */
static double intersect(const Sphere *s, const Ray *r)
{
    Vec3 op = vec3_sub(s->center, r->origin);
    double eps = 1e-4, b = vec3_dot(op, r->direction);
    double det = b * b - vec3_dot(op, op) + s->radius * s->radius;
    if (det < 0)
        return 0;
    det = sqrt(det);
    double tn = b - det, tf = b + det;
    return tn > eps ? tn : (tf > eps ? tf : 0);
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    double d = intersect(sphere, ray);
    if (d == 0)
        return false;
    *t = d;
    return true;
}
