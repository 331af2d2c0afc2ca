/* Self-test of the grader: hostile-memory-hog. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <stdlib.h>
#include <string.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    /* A mebibyte at a time, to the limit.  The limit is on address space,
     * so one byte written in each stops at the same place as writing them
     * all, without a page fault for every 4 KiB of it in each of the
     * part's twenty runs. */
    for (;;) {
        char *p = malloc(1 << 20);
        if (!p)
            break;
        memset(p, 1, 1);
    }
    *w = *h = fov_degrees + aspect + d;
}
