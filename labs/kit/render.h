/*
 * render.h - the renderer's main loop: every pixel through Parts 1 to 3b.
 *
 *     image_plane_size(fov, nx / ny, d, &w, &h)          once   (Part 1)
 *     s = pixel_coordinates(i, j, nx, ny, w, h, d)       per pixel (Part 2)
 *     ray = camera_ray(scene->eye, s)                    per pixel (Part 3b)
 *     colour = ray_color(scene, &ray)                    per pixel (Part 3b)
 *
 * A scene with planes or triangles takes its colours from closest.h
 * instead: the closest hit over spheres (Part 3a), planes (Part 4) and
 * triangles (Part 5), through a bounding volume hierarchy (bvh.h) when the
 * scene has enough spheres and triangles to gain by one.  A scene of
 * spheres alone never calls plane_intersect or triangle_intersect, and
 * builds no hierarchy.
 */
#ifndef KIT_RENDER_H
#define KIT_RENDER_H

#include <stdbool.h>
#include "../raytracer.h"
#include "image.h"

/* When a scene drawn by closest.h gets a hierarchy. */
typedef enum {
    RENDER_HIERARCHY_AUTO,   /* with RENDER_HIERARCHY_MIN spheres and triangles or more */
    RENDER_HIERARCHY_OFF,    /* never: every object for every ray            */
    RENDER_HIERARCHY_ON      /* always                                       */
} RenderHierarchy;

/* Below this many spheres and triangles, testing them all is cheap, and
 * for a scene whose objects fill the view, cheaper than walking a
 * hierarchy (tests/bench/README.md, "Part 5 at scale"). */
#define RENDER_HIERARCHY_MIN 16

typedef struct {
    int threads;         /* worker threads; 0 = one per core                  */
    bool progress;       /* show progress on stderr: on a terminal a line
                            redrawn once the render takes more than a
                            second, elsewhere a line every few seconds; a
                            word when no row is drawn for long, and a note
                            when a stray hit sets the hierarchy aside     */
    RenderHierarchy hierarchy;
    double nudge[2];     /* added to every pixel centre's x and y: 0, but
                            for the renders that find edges (edges.h)     */
} RenderOptions;

typedef struct {
    double seconds;          /* wall-clock time of the render                */
    double rays_per_second;  /* nx * ny / seconds                            */
    int threads;             /* threads actually used                        */
    int objects;             /* spheres and triangles in the hierarchy; 0 when
                                none was built                               */
    int nodes;               /* its nodes                                    */
    double build_seconds;    /* building it and probing it (closest_probe),
                                before the render                            */
    bool stray;              /* a stray hit (closest.h) set it aside: every
                                object was tested for every ray              */
} RenderStats;

/* What the calling thread was drawing, for a message when the student's
 * code crashes: sets *j0 and *j1 to the rows (j0 .. j1 - 1) and returns 1,
 * or returns 0 while sizing the image plane (Part 1), or -1 outside a
 * render.  Reads only the thread's own variables: safe in a signal handler. */
int render_crash_rows(int *j0, int *j1);

/* The monotonic clock in seconds, whose origin is arbitrary: the render's
 * own clock, for timing what comes before it (reading the scene). */
double render_now(void);

/* Renders scene into img, which must be scene->nx x scene->ny.  A NULL
 * opt means one thread per core, no progress and RENDER_HIERARCHY_AUTO.
 * Returns 0, or -1 with a reason in err (e.g. threads could not start). */
int render_scene(const Scene *scene, Image *img, const RenderOptions *opt,
                 RenderStats *stats, char *err, size_t errlen);

#endif
