/* Part 3b whose smallest t so far starts at 0: no t > 0 is smaller, so
 * every ray keeps the background. */
#include "raytracer.h"
Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    return ray;
}
Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    Vec3 color = scene->background;
    double best = 0;
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t) && t < best) {
            best = t;
            color = scene->spheres[k].color;
        }
    }
    return color;
}
