/* Real-world method: Ray Tracing in One Weekend, 2016 edition (sphere::hit),
 * as a student converts it to the kit: the book's float scalars, b = oc.r
 * (half the quadratic's b), a hit only when the discriminant is > 0, and
 * the roots the book's main loop accepts, t in (0.001, MAXFLOAT). */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    const float t_min = 0.001f, t_max = FLT_MAX;    /* world->hit(r, 0.001, MAXFLOAT, rec) */
    Vec3 oc = vec3_sub(ray->origin, sphere->center);
    float a = vec3_dot(ray->direction, ray->direction);
    float b = vec3_dot(oc, ray->direction);
    float c = vec3_dot(oc, oc) - sphere->radius * sphere->radius;
    float discriminant = b * b - a * c;
    if (discriminant > 0) {
        float temp = (-b - sqrt(discriminant)) / a;     /* the near root first */
        if (temp < t_max && temp > t_min) {
            *t = temp;
            return true;
        }
        temp = (-b + sqrt(discriminant)) / a;
        if (temp < t_max && temp > t_min) {
            *t = temp;
            return true;
        }
    }
    return false;
}
