/*
 * figures.h - the report page's figure of one test case: a drawing, in
 * SVG, of that very case, with what was expected (blue) and what the
 * submission returned (orange), to scale.
 *
 *   Part 1   the view frustum from the side and the image plane face on
 *   Part 2   the image plane's pixel grid around the pixel
 *   Part 3a  the plane through the ray and the sphere's centre
 *   Part 3b  camera rays: the eye, the pixel and the two directions;
 *            colours: the ray and its spheres; images: the two renders
 *            with the pixel marked, and the ray's spheres listed by t
 *   Part 4   the plane seen edge on, in the plane of the ray and the normal
 *   Part 5   the triangle (or the mesh near the ray) seen along the ray
 *
 * Hit points are computed again here, in double, for display only: the
 * grade never depends on them.  This is the top of the figure files:
 * figure_case picks the figure of a case's kind, one function a kind below
 * (fig_view.c, fig_spheres.c, fig_flat.c), drawn with fig_draw.h and
 * fig_ray.h.
 */
#ifndef FIGURES_H
#define FIGURES_H

#include "grader.h"
#include "markup.h"

/* Appends the figure of case c of test t to m: an inline <svg> element,
 * then (for some kinds) a table.  got is the submission's answer to the
 * case, or NULL when it gave none (the figure then shows the expected
 * answer alone).  For image tests r gives every pixel's answer. */
void figure_case(Markup *m, const Test *t, const TestResult *r, int c, const double *got);

/* The figure of each kind; each appends an inline <svg> (and, for some, a
 * table) to m, as figure_case does. */
void fig_plane(Markup *m, const Test *t, const Case *c, const double *got);      /* Part 1  */
void fig_pixel(Markup *m, const Test *t, const Case *c, const double *got);      /* Part 2  */
void fig_sphere(Markup *m, const Test *t, const Case *c, const double *got);     /* Part 3a */
void fig_camera(Markup *m, const Test *t, const Case *c, const double *got);     /* Part 3b */
void fig_color(Markup *m, const Test *t, const Case *c, const double *got);      /* Part 3b */
void fig_image(Markup *m, const Test *t, const TestResult *r, int c);            /* Part 3b */
void fig_planehit(Markup *m, const Test *t, const Case *c, const double *got);   /* Part 4  */
void fig_triangle(Markup *m, const Test *t, const Case *c, const double *got);   /* Part 5  */

#endif
