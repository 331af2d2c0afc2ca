/*
 * closest.h - the colours of a scene with planes or triangles.
 *
 * Part 3b's ray_color draws scenes of spheres alone, and knows nothing of
 * planes and triangles.  For a scene that has them, the renderer draws
 * with these functions instead: a pixel's colour is that of the object hit
 * at the smallest t > 0, over the spheres (sphere_intersect, Part 3a), the
 * planes (plane_intersect, Part 4) and the triangles (triangle_intersect,
 * Part 5), or the background.  An object replaces the best so far only when
 * its t is smaller by more than CLOSEST_TIE of itself: two hits closer than
 * that are a tie, which the first in the order spheres, planes, triangles
 * (each in file order) wins.  Where two surfaces meet (a wall on the
 * ground) their hits are equal but for rounding, and which one a correct
 * formula puts first hangs on the last bits of the ray; the tie keeps such
 * a pixel the same for every formula that the core tests accept (within
 * 1e-9 of t), the reference's included, so that make compare finds a
 * correct submission's render identical to the reference's.
 */
#ifndef KIT_CLOSEST_H
#define KIT_CLOSEST_H

#include "../raytracer.h"
#include "image.h"

#define CLOSEST_TIE 1e-9        /* hits this close (relative) are a tie */

/* The colour ray sees in scene. */
Vec3 closest_color(const Scene *scene, const Ray *ray);

/* Draws rows j0 .. j1 - 1 of img (scene->nx x scene->ny) for an image plane
 * w x h: for each pixel, its centre (Part 2), the camera ray (Part 3b) and
 * closest_color.  Never fails. */
void closest_rows(const Scene *scene, Image *img, double w, double h, int j0, int j1);

#endif
