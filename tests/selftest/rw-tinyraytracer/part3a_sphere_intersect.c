/* Real-world method: tinyraytracer (Dmitry Sokolov, 2022 version,
 * ray_sphere_intersect), converted to the kit: the geometric method in
 * float with the direction taken to be a unit vector -- L = c - e,
 * tca = L.r, d2 = L.L - tca^2, thc = sqrt(R^2 - d2) -- and the first of
 * tca - thc, tca + thc beyond .001. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 L = vec3_sub(sphere->center, ray->origin);
    float tca = vec3_dot(L, ray->direction);
    float d2 = vec3_dot(L, L) - tca * tca;
    float r2 = sphere->radius * sphere->radius;
    if (d2 > r2)
        return false;
    float thc = sqrtf(r2 - d2);
    float t0 = tca - thc, t1 = tca + thc;
    if (t0 > .001) {            /* .001: so a ray leaving a surface does not hit it again */
        *t = t0;
        return true;
    }
    if (t1 > .001) {
        *t = t1;
        return true;
    }
    return false;
}
