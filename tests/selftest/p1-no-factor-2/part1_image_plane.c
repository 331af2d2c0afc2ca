/* Self-test of the grader: p1-no-factor-2. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
