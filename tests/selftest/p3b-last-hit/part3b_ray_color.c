/* Part 3b with no comparison of t: each hit replaces the colour, so the
 * last sphere hit in the list wins, near or far. */
#include "raytracer.h"
Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    return ray;
}
Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    Vec3 color = scene->background;
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t))
            color = scene->spheres[k].color;
    }
    return color;
}
