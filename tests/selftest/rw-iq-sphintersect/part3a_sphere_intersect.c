/* Real-world method: Inigo Quilez, "Intersectors" (sphIntersect, GLSL),
 * converted to C as a student does: float scalars, the direction taken to
 * be normalized (no a), oc = e - c, b = oc.r, c = oc.oc - R^2, h = b^2 - c,
 * -1 for no intersection; the near distance -b - sqrt(h) is the answer,
 * and the caller's test t > 0 decides a hit. */
#include "raytracer.h"

/* sphIntersect(...).x: the near distance, or -1. */
static float sph_intersect(Vec3 ro, Vec3 rd, Vec3 ce, float ra)
{
    Vec3 oc = vec3_sub(ro, ce);
    float b = vec3_dot(oc, rd);
    float c = vec3_dot(oc, oc) - ra * ra;
    float h = b * b - c;
    if (h < 0.0f)
        return -1.0f;           /* no intersection */
    h = sqrtf(h);
    return -b - h;
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    float tn = sph_intersect(ray->origin, ray->direction, sphere->center, sphere->radius);
    if (tn > 0.0f) {
        *t = tn;
        return true;
    }
    return false;
}
