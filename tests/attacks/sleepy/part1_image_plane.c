/* Part 1 right, but each call sleeps just under the time limit of a test
 * (2 s): every test alone then takes nearly its limit
 * (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "raytracer.h"
#include <time.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    struct timespec nap = { 1, 500000000 };
    nanosleep(&nap, NULL);
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
