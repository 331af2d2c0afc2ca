/* Real-world method: Scratchapixel, "A Minimal Ray-Tracer: Rendering Simple
 * Shapes" (Sphere::intersect, geometric solution), converted to the kit:
 * float, the direction taken to be a unit vector, L = c - e, tca = L.r with
 * an early miss when tca < 0, d2 = L.L - tca^2 against R^2,
 * thc = sqrt(R^2 - d2), and the first of tca - thc, tca + thc that is not
 * negative. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    float radius2 = sphere->radius * sphere->radius;
    Vec3 L = vec3_sub(sphere->center, ray->origin);
    float tca = vec3_dot(L, ray->direction);
    if (tca < 0)
        return false;
    float d2 = vec3_dot(L, L) - tca * tca;
    if (d2 > radius2)
        return false;
    float thc = sqrt(radius2 - d2);
    float t0 = tca - thc, t1 = tca + thc;
    if (t0 > t1) {
        float swap = t0;
        t0 = t1;
        t1 = swap;
    }
    if (t0 < 0) {
        t0 = t1;
        if (t0 < 0)
            return false;
    }
    *t = t0;
    return true;
}
