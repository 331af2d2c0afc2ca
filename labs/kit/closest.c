/*
 * closest.c - see closest.h.
 */
#include "closest.h"

/* Why the attributes.  The renderer is built with link-time optimisation,
 * and its speed on spheres comes from inlining the student's stage
 * functions into render.c's loop, which compilers do freely only for a
 * function called from one place.  These functions are the other place.
 * flatten inlines their calls into them, so that no call of a stage
 * function is left here and render.c's are the only ones; noinline keeps
 * them, grown by that, out of render.c's loop.  Without them clang renders
 * the sphere scenes a sixth slower (gcc and clang; elsewhere nothing). */
#if defined(__GNUC__)
#define CLOSEST_APART __attribute__((flatten, noinline))
#else
#define CLOSEST_APART
#endif

Vec3 closest_color(const Scene *scene, const Ray *ray) CLOSEST_APART;
void closest_rows(const Scene *scene, Image *img, double w, double h, int j0, int j1) CLOSEST_APART;

/* Makes (t, color) the nearest so far when t is nearer than *nearest by
 * more than a tie (closest.h), so that of two hits equal but for rounding
 * the first one offered stays. */
static void closest_keep(double t, Vec3 color, double *nearest, Vec3 *seen)
{
    if (t < *nearest * (1 - CLOSEST_TIE)) {
        *nearest = t;
        *seen = color;
    }
}

Vec3 closest_color(const Scene *scene, const Ray *ray)
{
    double nearest = INFINITY, t;
    Vec3 seen = scene->background;
    /* Each test first, then its t: the order in which a call's arguments
     * are evaluated is not fixed in C. */
    for (int k = 0; k < scene->nspheres; k++)
        if (sphere_intersect(&scene->spheres[k], ray, &t))
            closest_keep(t, scene->spheres[k].color, &nearest, &seen);
    for (int k = 0; k < scene->nplanes; k++)
        if (plane_intersect(&scene->planes[k], ray, &t))
            closest_keep(t, scene->planes[k].color, &nearest, &seen);
    for (int k = 0; k < scene->ntriangles; k++)
        if (triangle_intersect(&scene->triangles[k], ray, &t))
            closest_keep(t, scene->triangles[k].color, &nearest, &seen);
    return seen;
}

void closest_rows(const Scene *scene, Image *img, double w, double h, int j0, int j1)
{
    const int nx = scene->nx, ny = scene->ny;
    for (int j = j0; j < j1; j++) {
        unsigned char *px = img->rgb + (size_t)3 * nx * (size_t)j;
        for (int i = 0; i < nx; i++) {
            Ray ray = camera_ray(scene->eye, pixel_coordinates(i, j, nx, ny, w, h, scene->d));
            Vec3 color = closest_color(scene, &ray);
            px[0] = image_channel(color.x);
            px[1] = image_channel(color.y);
            px[2] = image_channel(color.z);
            px += 3;
        }
    }
}
