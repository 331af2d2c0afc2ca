/* Self-test of the grader: hostile-exit. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <stdlib.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    (void)fov_degrees; (void)aspect; (void)d; (void)w; (void)h;
    exit(0);
}
