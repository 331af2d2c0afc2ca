/* Self-test of the grader: p1-w-h-swapped. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *w = 2 * d * tan(fov_degrees * M_PI / 360);
    *h = aspect * *w;
}
