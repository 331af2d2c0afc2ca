/* Real-world method: pbrt-v4 (Sphere::BasicIntersect), converted to the
 * kit in plain double (pbrt computes it in interval arithmetic): in the
 * sphere's own space oi = e - c, di = r; a = di.di, b = 2 di.oi,
 * c = oi.oi - R^2; the discriminant as 4 a (R + |v|)(R - |v|) with
 * v = oi - (b / 2a) di; q = -(b -+ sqrt(discrim)) / 2 by the sign of b;
 * t0 = q / a, t1 = c / q, sorted; the first root > 0 below tMax. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    const double tMax = INFINITY;
    double radius = sphere->radius;
    Vec3 oi = vec3_sub(ray->origin, sphere->center);    /* objectFromRender */
    Vec3 di = ray->direction;

    double a = di.x * di.x + di.y * di.y + di.z * di.z;
    double b = 2 * (di.x * oi.x + di.y * oi.y + di.z * oi.z);
    double c = oi.x * oi.x + oi.y * oi.y + oi.z * oi.z - radius * radius;

    /* The discriminant from the line's closest point to the centre. */
    Vec3 v = vec3_sub(oi, vec3_scale(di, b / (2 * a)));
    double length = vec3_length(v);
    double discrim = 4 * a * (radius + length) * (radius - length);
    if (discrim < 0)
        return false;

    double rootDiscrim = sqrt(discrim);
    double q = b < 0 ? -.5 * (b - rootDiscrim) : -.5 * (b + rootDiscrim);
    double t0 = q / a, t1 = c / q;
    if (t0 > t1) {
        double swap = t0;
        t0 = t1;
        t1 = swap;
    }

    /* The nearest root in (0, tMax]. */
    if (t0 > tMax || t1 <= 0)
        return false;
    double tShapeHit = t0;
    if (tShapeHit <= 0) {
        tShapeHit = t1;
        if (tShapeHit > tMax)
            return false;
    }
    *t = tShapeHit;
    return true;
}
