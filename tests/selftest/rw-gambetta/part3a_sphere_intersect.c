/* Real-world method: Gabriel Gambetta, "Computer Graphics from Scratch",
 * chapter 2 (IntersectRaySphere and TraceRay), converted to the kit:
 * CO = O - center, a = D.D, b = 2 CO.D, c = CO.CO - r^2, b^2 - 4ac, both
 * roots (-b +- sqrt) / 2a, and the smaller one in TraceRay's range
 * t_min < t < t_max with the book's camera-ray values t_min = 1 (beyond the
 * projection plane) and t_max = infinity. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    const double t_min = 1, t_max = INFINITY;          /* TraceRay(O, D, 1, inf) */
    double r = sphere->radius;
    Vec3 CO = vec3_sub(ray->origin, sphere->center);
    Vec3 D = ray->direction;

    double a = vec3_dot(D, D);
    double b = 2 * vec3_dot(CO, D);
    double c = vec3_dot(CO, CO) - r * r;
    double discriminant = b * b - 4 * a * c;
    if (discriminant < 0)
        return false;                                   /* inf, inf */
    double t1 = (-b + sqrt(discriminant)) / (2 * a);
    double t2 = (-b - sqrt(discriminant)) / (2 * a);

    double closest_t = INFINITY;
    if (t1 < closest_t && t_min < t1 && t1 < t_max)
        closest_t = t1;
    if (t2 < closest_t && t_min < t2 && t2 < t_max)
        closest_t = t2;
    if (closest_t == INFINITY)
        return false;
    *t = closest_t;
    return true;
}
