/* Self-test of the grader: p1-float. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    float half = (float)fov_degrees * 3.14159265f / 360.0f;
    *h = 2.0f * (float)d * tanf(half);
    *w = (float)aspect * (float)*h;
}
