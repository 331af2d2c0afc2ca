/*
 * fig_parts.h - the figure of each kind of test case, one function a kind
 * (fig_view.c, fig_spheres.c, fig_flat.c), drawn with fig_draw.h and
 * fig_ray.h; figure_case (figures.h) picks the one for a case.  Each
 * appends an inline <svg> (and, for some, a table) to m; got is the
 * submission's answer, or NULL when it gave none.
 */
#ifndef FIG_PARTS_H
#define FIG_PARTS_H

#include "grader.h"
#include "markup.h"

void fig_plane(Markup *m, const Test *t, const Case *c, const double *got);      /* Part 1  */
void fig_pixel(Markup *m, const Test *t, const Case *c, const double *got);      /* Part 2  */
void fig_sphere(Markup *m, const Test *t, const Case *c, const double *got);     /* Part 3a */
void fig_camera(Markup *m, const Test *t, const Case *c, const double *got);     /* Part 3b */
void fig_color(Markup *m, const Test *t, const Case *c, const double *got);      /* Part 3b */
void fig_image(Markup *m, const Test *t, const TestResult *r, int c);            /* Part 3b */
void fig_planehit(Markup *m, const Test *t, const Case *c, const double *got);   /* Part 4  */
void fig_triangle(Markup *m, const Test *t, const Case *c, const double *got);   /* Part 5  */

#endif
