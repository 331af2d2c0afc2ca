/* Self-test: a correct submission written without looking at solutions/. */
#include "raytracer.h"

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Vec3 dir = vec3_sub(pixel, eye);
    double len = sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
    Ray ray = { eye, { dir.x / len, dir.y / len, dir.z / len } };
    return ray;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    int nearest = -1;
    double nearest_t = 0;
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t) && (nearest < 0 || t < nearest_t)) {
            nearest = k;
            nearest_t = t;
        }
    }
    return nearest < 0 ? scene->background : scene->spheres[nearest].color;
}
