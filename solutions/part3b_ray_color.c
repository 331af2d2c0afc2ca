/* Part 3b: the ray through a pixel, and the colour it sees. */
#include "raytracer.h"

/*
 * camera_ray - the ray from the eye through a pixel's centre.
 *
 * Parameters:
 *   eye          e, the ray's origin (the origin in this lab)
 *   pixel        the pixel's centre on the image plane (Part 2)
 * Returns:       the ray with origin e and the UNIT direction from e
 *                towards the pixel.
 * Example:       eye (0, 0, 0), pixel (3, 0, -4) -> origin (0, 0, 0),
 *                direction (0.6, 0, -0.8)
 * Formula:       r = (s - e) / |s - e|,  s = the pixel's centre
 */
Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    Ray ray = { eye, vec3_normalize(vec3_sub(pixel, eye)) };
    return ray;
}

/*
 * ray_color - the colour a ray sees: that of the closest sphere it hits.
 *
 * Parameters:
 *   scene        the spheres (scene->spheres[0 .. scene->nspheres - 1]) and
 *                the background colour (scene->background)
 *   ray          the ray (from camera_ray)
 * Returns:       the colour of the sphere with the smallest hit t (Part 3a),
 *                or scene->background when the ray hits no sphere.
 * Example:       red sphere hit at t = 4, blue sphere hit at t = 2 -> blue;
 *                no sphere hit -> scene->background
 * Formula:       colour = colour of argmin over spheres k of t_k, where
 *                sphere_intersect(sphere k, ray, &t_k) is true
 */
Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    Vec3 color = scene->background;
    double tmin = INFINITY;             /* the closest hit so far */
    for (int k = 0; k < scene->nspheres; k++) {
        double t;
        if (sphere_intersect(&scene->spheres[k], ray, &t) && t < tmin) {
            tmin = t;
            color = scene->spheres[k].color;
        }
    }
    return color;
}
