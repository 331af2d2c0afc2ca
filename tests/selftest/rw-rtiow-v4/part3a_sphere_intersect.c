/* Real-world method: Ray Tracing in One Weekend, v4 (2024, sphere::hit),
 * converted to the kit: double, oc = center - origin, h = r.oc, a miss when
 * the discriminant is < 0, and a root kept only when the interval
 * ray_t = (0.001, infinity) surrounds it (both ends excluded). */
#include "raytracer.h"

/* interval::surrounds: min < x < max. */
static bool surrounds(double min, double max, double x)
{
    return min < x && x < max;
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    const double ray_t_min = 0.001, ray_t_max = INFINITY;  /* interval(0.001, infinity) */
    Vec3 oc = vec3_sub(sphere->center, ray->origin);
    double a = vec3_dot(ray->direction, ray->direction);
    double h = vec3_dot(ray->direction, oc);
    double c = vec3_dot(oc, oc) - sphere->radius * sphere->radius;

    double discriminant = h * h - a * c;
    if (discriminant < 0)
        return false;

    /* The nearest root in the acceptable range. */
    double sqrtd = sqrt(discriminant);
    double root = (h - sqrtd) / a;
    if (!surrounds(ray_t_min, ray_t_max, root)) {
        root = (h + sqrtd) / a;
        if (!surrounds(ray_t_min, ray_t_max, root))
            return false;
    }
    *t = root;
    return true;
}
