/* Real-world method: Ray Tracing in One Weekend, v4, chapter 6 (hit_sphere
 * and the ray_color that calls it), converted to the kit: the full
 * quadratic with b = -2 r.oc (oc = center - origin), b^2 - 4ac, the near
 * root (-b - sqrt(disc)) / 2a alone, -1 for a miss, and the caller's test
 * t > 0. */
#include "raytracer.h"

/* hit_sphere: the near root, or -1 when the discriminant is negative. */
static double hit_sphere(Vec3 center, double radius, const Ray *r)
{
    Vec3 oc = vec3_sub(center, r->origin);
    double a = vec3_dot(r->direction, r->direction);
    double b = -2.0 * vec3_dot(r->direction, oc);
    double c = vec3_dot(oc, oc) - radius * radius;
    double discriminant = b * b - 4 * a * c;
    if (discriminant < 0)
        return -1.0;
    return (-b - sqrt(discriminant)) / (2.0 * a);
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    double root = hit_sphere(sphere->center, sphere->radius, ray);
    if (root > 0.0) {                   /* ray_color: if (t > 0.0) */
        *t = root;
        return true;
    }
    return false;
}
