/* Self-test: a correct submission written without looking at solutions/:
 * the geometric method, with the direction made unit length first. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    double len = vec3_length(ray->direction);
    if (!(len > 0))
        return false;
    Vec3 u = vec3_scale(ray->direction, 1 / len);         /* unit direction */
    Vec3 L = vec3_sub(sphere->center, ray->origin);         /* eye to centre */
    double tca = vec3_dot(L, u);                            /* along the ray to the closest point */
    double d2 = vec3_dot(L, L) - tca * tca;                 /* squared distance centre-line */
    double R2 = sphere->radius * sphere->radius;
    if (!(d2 <= R2))
        return false;
    double thc = sqrt(R2 - d2);
    double s = tca - thc;                                   /* the nearer point */
    if (!(s > 0))
        s = tca + thc;                                      /* inside: the exit point */
    if (!(s > 0))
        return false;                                       /* behind the origin */
    *t = s / len;                                           /* back to the given direction */
    return true;
}
