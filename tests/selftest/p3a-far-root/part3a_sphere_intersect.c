/* Self-test of the grader: p3a-far-root. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 f = vec3_sub(ray->origin, sphere->center);
    double A = vec3_dot(ray->direction, ray->direction);
    double B = vec3_dot(f, ray->direction);
    double C = vec3_dot(f, f) - sphere->radius * sphere->radius;
    double disc = B * B - A * C;
    if (disc < 0 || A == 0)
        return false;
    double t0 = (-B + sqrt(disc)) / A;
    if (t0 <= 0)
        return false;
    *t = t0;
    return true;
}
