/*
 * closest.h - the colours of a scene with planes or triangles.
 *
 * Part 3b's ray_color draws scenes of spheres alone, and knows nothing of
 * planes and triangles.  For a scene that has them, the renderer draws
 * with these functions instead: a pixel's colour is that of the object hit
 * at the smallest t > 0, over the spheres (sphere_intersect, Part 3a), the
 * planes (plane_intersect, Part 4) and the triangles (triangle_intersect,
 * Part 5), or the background.
 *
 * What "closest" means is what the plain loop does: every object in the
 * order spheres, planes, triangles (each in file order), each replacing
 * the best so far only when its t is strictly smaller.  So of the hits with
 * the smallest t the first in that order wins; a hit at t = NaN or +infinity
 * never wins, nor does a hit whose t the function left unset (it counts as
 * NaN); a hit at t <= 0, which a correct function never reports, is taken
 * as it comes.
 *
 * With a hierarchy (bvh.h) the same colours come from testing only the
 * objects whose boxes the ray meets before the closest hit so far; every
 * hit is still decided by the same functions.  The guarantee: the colour is
 * the plain loop's, ties and all, for functions that depend on their
 * arguments alone (no state kept from call to call, nothing written through
 * their pointers) and that are honest: every hit they report at a t < +inf
 * is in the box of the object they were given, that is, t is in the
 * interval over which the line x(t) = e + t r is in the box, widened at
 * each end by 2^-20 of the end (bvh_slab).  A correct function is honest:
 * its t errs by far less.  An honest function may be wrong in every other
 * way: hits at a wrong t inside the box, at t <= 0, at NaN or +infinity,
 * misses where the ray hits, are all drawn as the plain loop draws them.
 * A hit outside the box (a stray hit) would be lost where a box test skips
 * the object, so the kit looks for them: closest_probe tries each object
 * (or thousands of them) with rays aimed around it, and every hit the
 * hierarchy takes is checked; at one stray hit the picture is drawn with
 * the plain loop.  (Moller-Trumbore's t for a ray in its triangle's plane
 * is any number: cracks.scene's side walls, whose planes hold the eye,
 * give it stray hits.)
 */
#ifndef KIT_CLOSEST_H
#define KIT_CLOSEST_H

#include <stdbool.h>
#include "../raytracer.h"
#include "bvh.h"
#include "image.h"

/* The colour ray sees in scene: the plain loop over every object. */
Vec3 closest_color(const Scene *scene, const Ray *ray);

/* The same colour, through bvh (built for scene), as guaranteed above.
 * When a hit it takes is a stray hit, sets *stray and returns at once
 * (the colour is then meaningless); otherwise leaves *stray alone. */
Vec3 closest_color_bvh(const Scene *scene, const Bvh *bvh, const Ray *ray, bool *stray);

/* Aims rays from the eye at each of scene's spheres and triangles (at up
 * to CLOSEST_PROBE_OBJECTS of them, spread through the scene), at points in
 * and around them, both ways.  Returns true when a function reports a
 * stray hit for one of them: then only the plain loop draws the scene as
 * the plain loop does. */
#define CLOSEST_PROBE_OBJECTS 4096
bool closest_probe(const Scene *scene, const Bvh *bvh);

/* Draws rows j0 .. j1 - 1 of img (scene->nx x scene->ny) for an image plane
 * w x h: for each pixel, its centre (Part 2) plus nudge in x and y, the
 * camera ray (Part 3b) and
 * closest_color, or closest_color_bvh when bvh is not NULL.  Returns
 * true, or false at the first stray hit (the rows are then unfinished). */
bool closest_rows(const Scene *scene, const Bvh *bvh, Image *img, double w, double h,
                  const double nudge[2], int j0, int j1);

#endif
