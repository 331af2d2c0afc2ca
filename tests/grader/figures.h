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
 * grade never depends on them.  The figures of the parts are in
 * fig_parts.h; this is the top of the figure files, which picks one.
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

#endif
