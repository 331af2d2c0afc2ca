/* Real-world method: Ray Tracing in One Weekend, v3.0 (2020, sphere::hit),
 * converted to the kit: double, oc = origin - center, half_b = oc.r, a hit
 * only when the discriminant is > 0, roots accepted in (t_min, t_max) with
 * the book's t_min = 0.001 and t_max = infinity. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    const double t_min = 0.001, t_max = INFINITY;   /* world.hit(r, 0.001, infinity, rec) */
    Vec3 oc = vec3_sub(ray->origin, sphere->center);
    double a = vec3_dot(ray->direction, ray->direction);
    double half_b = vec3_dot(oc, ray->direction);
    double c = vec3_dot(oc, oc) - sphere->radius * sphere->radius;
    double discriminant = half_b * half_b - a * c;

    if (discriminant > 0) {
        double root = sqrt(discriminant);
        double temp = (-half_b - root) / a;
        if (temp < t_max && temp > t_min) {
            *t = temp;
            return true;
        }
        temp = (-half_b + root) / a;
        if (temp < t_max && temp > t_min) {
            *t = temp;
            return true;
        }
    }
    return false;
}
