/*
 * harness_render.c - the child side of the report page's render: draws a
 * scene with the submission's Parts 1-3b, pixel by pixel as the kit's
 * renderer does (labs/kit/render.c), and sends the colours back.  Linked
 * with the submission's four core stage files, never with the grader.
 *
 * Reads from stdin:   render nx ny
 *                     fov F d D
 *                     background r g b
 *                     spheres M, then M lines cx cy cz R r g b
 * Writes to fd 3:     nx * ny * 3 bytes (r, g, b per pixel, rows from the
 *                     top): each colour made a byte by the kit's
 *                     image_channel, as the renderer makes it.
 * The parent checks that the count is right.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "raytracer.h"
#include "kit/scene.h"                  /* the guard sphere */
#include "kit/image.h"
#include "harness_init.h"

#include <stdio.h>
#include <stdlib.h>

/* Reads n numbers into v; 0, or -1 at bad input. */
static int read_numbers(double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (scanf("%lf", &v[k]) != 1)
            return -1;
    return 0;
}

int main(void)
{
    harness_init();
    FILE *out = fdopen(3, "w");
    int nx, ny, m;
    double view[2], bg[3];
    if (!out || scanf(" render %d %d", &nx, &ny) != 2 || nx < 1 || ny < 1 || nx > 16384 || ny > 16384)
        return 3;
    if (scanf(" fov %lf d %lf", &view[0], &view[1]) != 2
        || scanf(" background %lf %lf %lf", &bg[0], &bg[1], &bg[2]) != 3
        || scanf(" spheres %d", &m) != 1 || m < 0 || m > 100000)
        return 3;
    static char buf[1 << 16];
    setvbuf(out, buf, _IOFBF, sizeof buf);

    Scene scene = { 0 };
    scene.nx = nx;
    scene.ny = ny;
    scene.fov_degrees = view[0];
    scene.d = view[1];
    scene.eye = vec3(0, 0, 0);
    scene.background = vec3(bg[0], bg[1], bg[2]);
    Sphere *spheres = calloc((size_t)m + 1, sizeof *spheres);
    if (!spheres)
        return 3;
    for (int s = 0; s < m; s++) {
        double v[7];
        if (read_numbers(v, 7))
            return 3;
        spheres[s].center = vec3(v[0], v[1], v[2]);
        spheres[s].radius = v[3];
        spheres[s].color = vec3(v[4], v[5], v[6]);
    }
    spheres[m] = scene_guard_sphere();  /* past the last: scene.h */
    scene.spheres = spheres;
    scene.nspheres = m;

    /* Part 1 once, then per pixel Part 2, camera_ray and ray_color. */
    double w = 0, h = 0;
    image_plane_size(scene.fov_degrees, (double)nx / ny, scene.d, &w, &h);
    unsigned char *row = malloc(3 * (size_t)nx);      /* written a row at a time */
    if (!row)
        return 3;
    for (int j = 0; j < ny; j++) {
        for (int i = 0; i < nx; i++) {
            Ray ray = camera_ray(scene.eye, pixel_coordinates(i, j, nx, ny, w, h, scene.d));
            Vec3 seen = ray_color(&scene, &ray);
            row[3 * i] = image_channel(seen.x);
            row[3 * i + 1] = image_channel(seen.y);
            row[3 * i + 2] = image_channel(seen.z);
        }
        if (fwrite(row, 3, (size_t)nx, out) != (size_t)nx)
            return 3;
    }
    return fflush(out) == 0 ? 0 : 3;
}
