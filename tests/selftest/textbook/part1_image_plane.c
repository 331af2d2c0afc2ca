/* Self-test of the grader: the lecture's textbook formulas, as most
 * students write them.  Full core marks; some hard cases fail. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees / 2 * M_PI / 180);
    *w = aspect * *h;
}
