/* Part 3b, right, but for its use of a helper defined in Part 1's file. */
#include "raytracer.h"

double twice(double x);

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    return ray;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    double best = INFINITY;
    Vec3 color = scene->background;
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t) && twice(t) < twice(best)) {
            best = t;
            color = scene->spheres[k].color;
        }
    }
    return color;
}
