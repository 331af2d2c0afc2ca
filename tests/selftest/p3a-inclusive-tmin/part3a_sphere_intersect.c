/* Self-test of the grader: p3a-inclusive-tmin.  Embree's sphere test (the
 * offset of the centre from the ray's line, then the half-chord) in double,
 * with Embree's ray interval [tnear, tfar] taken as it is, both ends
 * included: tnear = 0, tfar = infinity.  A ray that starts on the sphere
 * then hits at t = 0, its own origin. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    const double tnear = 0, tfar = INFINITY;
    Vec3 c0 = vec3_sub(sphere->center, ray->origin);
    double rd2 = 1 / vec3_dot(ray->direction, ray->direction);
    double projC0 = vec3_dot(c0, ray->direction) * rd2;
    Vec3 perp = vec3_sub(c0, vec3_scale(ray->direction, projC0));
    double l2 = vec3_dot(perp, perp), r2 = sphere->radius * sphere->radius;
    if (!(l2 <= r2))
        return false;
    double td = sqrt((r2 - l2) * rd2);
    double t_front = projC0 - td, t_back = projC0 + td;
    if (tnear <= t_front && t_front <= tfar) {
        *t = t_front;
        return true;
    }
    if (tnear <= t_back && t_back <= tfar) {
        *t = t_back;
        return true;
    }
    return false;
}
