/* Self-test of the grader: p3b-crash-on-miss.  ray_color keeps a pointer
 * to the closest sphere and forgets the background: a ray that hits nothing
 * reads through a null pointer and crashes.  Every hit is right. */
#include "raytracer.h"

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    return ray;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    const Sphere *closest = 0;
    double tmin = INFINITY;
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t) && t < tmin) {
            tmin = t;
            closest = &scene->spheres[k];
        }
    }
    return *(volatile Vec3 *)&closest->color;
}
