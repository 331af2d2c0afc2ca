/* Self-test of the grader: tol-just-inside.  The reference's camera_ray with
 * the direction's x moved by 0.75e-9, just inside the core
 * tolerance of 1e-9 (each component of the unit direction); ray_color right. */
#include "raytracer.h"

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    ray.direction.x += 0.75e-9;
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
