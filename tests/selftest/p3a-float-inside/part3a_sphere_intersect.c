/* Part 3a with the discriminant and its square root in float, the rest in
 * double: t is not a float, but right to float's digits at best. */
#include "raytracer.h"
bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 oc = vec3_sub(ray->origin, sphere->center);
    double a = vec3_dot(ray->direction, ray->direction);
    double b = vec3_dot(oc, ray->direction);
    double c = vec3_dot(oc, oc) - sphere->radius * sphere->radius;
    float disc = (float)(b * b - a * c);
    if (!(a > 0) || disc < 0)
        return false;
    double s = sqrtf(disc);
    double t0 = (-b - s) / a, t1 = (-b + s) / a;
    if (t0 > 0) { *t = t0; return true; }
    if (t1 > 0) { *t = t1; return true; }
    return false;
}
