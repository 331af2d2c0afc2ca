/* Self-test of the grader: hostile-memory-hog. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <stdlib.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    /* A mebibyte at a time, to the limit, writing what it takes.  On Linux
     * the limit is on address space (RLIMIT_AS): malloc fails at it whether
     * the memory is written or not, so one byte of each mebibyte is
     * written, sparing a page fault for every 4 KiB in each of the part's
     * twenty runs.  Elsewhere (macOS) the grader watches the memory in use,
     * which only written pages count in: a byte of every page there. */
    size_t step = 4096;
#ifdef __linux__                /* portable: the limit differs (sandbox.h) */
    step = (size_t)1 << 20;
#endif
    for (;;) {
        char *p = malloc((size_t)1 << 20);
        if (!p)
            break;
        for (size_t k = 0; k < ((size_t)1 << 20); k += step)
            p[k] = 1;
    }
    *w = *h = fov_degrees + aspect + d;
}
