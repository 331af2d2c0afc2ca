/* Part 3b, right, with Part 3a's function defined here as well, after it:
 * Part 3b does not link either, as it is graded with the reference's
 * Part 3a. */
#include "raytracer.h"

#include <math.h>

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    return ray;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    Vec3 color = scene->background;
    double nearest = INFINITY;
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t) && t < nearest) {
            nearest = t;
            color = scene->spheres[k].color;
        }
    }
    return color;
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 oc = vec3_sub(ray->origin, sphere->center);
    double A = vec3_dot(ray->direction, ray->direction);
    double B = vec3_dot(oc, ray->direction);
    double C = vec3_dot(oc, oc) - sphere->radius * sphere->radius;
    double disc = B * B - A * C;
    if (A == 0 || disc < 0)
        return false;
    double t0 = (-B - sqrt(disc)) / A, t1 = (-B + sqrt(disc)) / A;
    *t = t0 > 0 ? t0 : t1;
    return *t > 0;
}
