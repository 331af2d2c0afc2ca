/* Part 3a after raylib's GetRayCollisionSphere (rmodels.c): float,
 * raySpherePos = c - e, vector = raySpherePos . r, distance =
 * |raySpherePos|, d = R^2 - (distance^2 - vector^2); a hit when d >= 0;
 * from inside (distance < R) the distance vector + sqrt(d), else
 * vector - sqrt(d).  raylib's ray direction is normalised. */
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 raySpherePos = vec3_sub(sphere->center, ray->origin);
    float radius = (float)sphere->radius;
    float vector = (float)vec3_dot(raySpherePos, ray->direction);
    float distance = (float)vec3_length(raySpherePos);
    float d = radius * radius - (distance * distance - vector * vector);
    bool hit = d >= 0.0f;
    if (distance < radius)
        *t = vector + sqrtf(d);
    else
        *t = vector - sqrtf(d);
    return hit;
}
