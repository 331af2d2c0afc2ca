/*
 * render.h - the renderer's main loop: every pixel through Parts 1 to 3b.
 *
 *     image_plane_size(fov, nx / ny, d, &w, &h)          once   (Part 1)
 *     s = pixel_coordinates(i, j, nx, ny, w, h, d)       per pixel (Part 2)
 *     ray = camera_ray(scene->eye, s)                    per pixel (Part 3b)
 *     colour = ray_color(scene, &ray)                    per pixel (Part 3b)
 *
 * A scene with planes or triangles takes its colours from closest_color
 * (closest.h) instead: the closest hit over spheres (Part 3a), planes
 * (Part 4) and triangles (Part 5).  A scene of spheres alone never calls
 * plane_intersect or triangle_intersect.
 */
#ifndef KIT_RENDER_H
#define KIT_RENDER_H

#include <stdbool.h>
#include "../raytracer.h"
#include "image.h"

typedef struct {
    int threads;         /* worker threads; 0 = one per core                  */
    bool progress;       /* show progress on stderr: on a terminal a line
                            redrawn once the render takes more than a
                            second, elsewhere a line every few seconds, and
                            a word when no row is drawn for long         */
} RenderOptions;

typedef struct {
    double seconds;          /* wall-clock time of the render                */
    double rays_per_second;  /* nx * ny / seconds                            */
    int threads;             /* threads actually used                        */
} RenderStats;

/* What the calling thread was drawing, for a message when the student's
 * code crashes: sets *j0 and *j1 to the rows (j0 .. j1 - 1) and returns 1,
 * or returns 0 while sizing the image plane (Part 1), or -1 outside a
 * render.  Reads only the thread's own variables: safe in a signal handler. */
int render_crash_rows(int *j0, int *j1);

/* Renders scene into img, which must be scene->nx x scene->ny.
 * Returns 0, or -1 with a reason in err (e.g. threads could not start). */
int render_scene(const Scene *scene, Image *img, const RenderOptions *opt,
                 RenderStats *stats, char *err, size_t errlen);

#endif
