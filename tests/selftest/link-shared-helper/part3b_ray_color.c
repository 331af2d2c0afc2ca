/* Self-test of the grader: link-shared-helper.  Part 3b with its own dot(),
 * not static, as Part 3a (part3a_sphere_intersect.c) has one. */
#include "raytracer.h"

double dot(Vec3 a, Vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Vec3 d = vec3_sub(pixel, eye);
    Ray ray = { eye, vec3_scale(d, 1 / sqrt(dot(d, d))) };
    return ray;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    Vec3 color = scene->background;
    double tmin = INFINITY;
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t) && t < tmin) {
            tmin = t;
            color = scene->spheres[k].color;
        }
    }
    return color;
}
