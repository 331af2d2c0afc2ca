/* Self-test of the grader: hostile-memory-hog. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <stdlib.h>
#include <string.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    for (;;) {
        char *p = malloc(1 << 20);          /* a mebibyte at a time, to the limit */
        if (!p)
            break;
        memset(p, 1, 1 << 20);
    }
    *w = *h = fov_degrees + aspect + d;
}
