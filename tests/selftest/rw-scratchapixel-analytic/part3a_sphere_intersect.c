/* Real-world method: Scratchapixel, "A Minimal Ray-Tracer: Rendering Simple
 * Shapes" (solveQuadratic and Sphere::intersect, analytic solution),
 * converted to the kit: float, b = 2 r.L with L = e - c, the roots from
 * q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2 as q / a and c / q (a double root
 * as -b / 2a), sorted, and the first one that is not negative. */
#include "raytracer.h"

/* The real roots of a x^2 + b x + c = 0; false when there are none. */
static bool solve_quadratic(float a, float b, float c, float *x0, float *x1)
{
    float discr = b * b - 4 * a * c;
    if (discr < 0)
        return false;
    if (discr == 0) {
        *x0 = *x1 = -0.5 * b / a;
    } else {
        float q = b > 0 ? -0.5 * (b + sqrt(discr)) : -0.5 * (b - sqrt(discr));
        *x0 = q / a;
        *x1 = c / q;
    }
    return true;
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    float t0, t1;
    Vec3 L = vec3_sub(ray->origin, sphere->center);
    float a = vec3_dot(ray->direction, ray->direction);
    float b = 2 * vec3_dot(ray->direction, L);
    float c = vec3_dot(L, L) - sphere->radius * sphere->radius;
    if (!solve_quadratic(a, b, c, &t0, &t1))
        return false;
    if (t0 > t1) {
        float swap = t0;
        t0 = t1;
        t1 = swap;
    }
    if (t0 < 0) {
        t0 = t1;                /* t0 behind the origin: use t1 */
        if (t0 < 0)
            return false;       /* both behind */
    }
    *t = t0;
    return true;
}
