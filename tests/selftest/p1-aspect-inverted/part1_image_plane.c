/* Self-test of the grader: p1-aspect-inverted. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = *h / aspect;
}
