/* Part 3b right, but its first call takes 300 MB, and crashes where it
 * cannot have them: more than a test's memory, less than the report
 * page's render once had (tests/attacks/README.md). */
#include "raytracer.h"
#include <stdlib.h>
#include <string.h>

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Vec3 r = vec3_sub(pixel, eye);
    Ray ray = { eye, vec3_scale(r, 1 / vec3_length(r)) };
    return ray;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    static char *hog;
    if (!hog) {
        hog = malloc((size_t)300 << 20);
        memset(hog, 1, (size_t)300 << 20);      /* a null hog crashes here */
    }
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
