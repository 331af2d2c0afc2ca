/* Self-test of the grader: p1-d-ignored. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    (void)d;
    *h = 2 * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
