/* Right, but named hit_sphere, as the function is in Ray Tracing in One
 * Weekend: it compiles, and the part's program does not link, as the
 * tests call sphere_intersect. */
#include "raytracer.h"

#include <math.h>

bool hit_sphere(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 oc = vec3_sub(ray->origin, sphere->center);
    double a = vec3_dot(ray->direction, ray->direction);
    double half_b = vec3_dot(oc, ray->direction);
    double c = vec3_dot(oc, oc) - sphere->radius * sphere->radius;
    double discriminant = half_b * half_b - a * c;
    if (a == 0 || discriminant < 0)
        return false;
    double root = (-half_b - sqrt(discriminant)) / a;
    if (root <= 0)
        root = (-half_b + sqrt(discriminant)) / a;
    if (root <= 0)
        return false;
    *t = root;
    return true;
}
