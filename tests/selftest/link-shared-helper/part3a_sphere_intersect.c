/* Self-test of the grader: link-shared-helper.  The lecture's Part 3a with
 * a helper dot(), not static; Part 3b (part3b_ray_color.c) defines its own
 * dot() the same way.  Each file is right, and each builds alone. */
#include "raytracer.h"

double dot(Vec3 a, Vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 f = vec3_sub(ray->origin, sphere->center);
    double A = dot(ray->direction, ray->direction);
    double B = dot(f, ray->direction);
    double C = dot(f, f) - sphere->radius * sphere->radius;
    double disc = B * B - A * C;
    if (!(A > 0) || !(disc >= 0))
        return false;
    double t0 = (-B - sqrt(disc)) / A, t1 = (-B + sqrt(disc)) / A;
    if (t0 > 0) {
        *t = t0;
        return true;
    }
    if (t1 > 0) {
        *t = t1;
        return true;
    }
    return false;
}
