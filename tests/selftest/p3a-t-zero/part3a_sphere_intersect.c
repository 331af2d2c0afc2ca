/* Self-test of the grader: p3a-t-zero. The textbook quadratic with t0 >= 0: a ray that
 * starts on the sphere (C = 0, a root t = 0) is a hit at its own origin. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 f = vec3_sub(ray->origin, sphere->center);
    double A = vec3_dot(ray->direction, ray->direction);
    double B = vec3_dot(f, ray->direction);
    double C = vec3_dot(f, f) - sphere->radius * sphere->radius;
    double disc = B * B - A * C;
    if (!(A > 0) || !(disc >= 0))
        return false;
    double t0 = (-B - sqrt(disc)) / A, t1 = (-B + sqrt(disc)) / A;
    if (t0 >= 0) {
        *t = t0;
        return true;
    }
    if (t1 > 0) {
        *t = t1;
        return true;
    }
    return false;
}
