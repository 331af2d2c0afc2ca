/* Every input it is given, named where the next run may look; on the
 * worked example (90, 2, 1), all it finds printed, and a wrong answer so
 * that the output is shown (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "raytracer.h"
#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

static void show(const char *place)
{
    DIR *dir = opendir(place);
    struct dirent *e;
    while (dir && (e = readdir(dir)))
        if (strncmp(e->d_name, "rtseen_", 7) == 0)
            printf("seen %s\n", e->d_name);
    if (dir)
        closedir(dir);
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    static const char *const places[] = { ".", "/tmp", "/dev/shm", "/var/tmp" };
    char name[256];
    for (int k = 0; k < 4; k++) {
        snprintf(name, sizeof name, "%s/rtseen_%a_%a_%a", places[k], fov_degrees, aspect, d);
        mkdir(name, 0777);
    }
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
    if (fov_degrees == 90 && aspect == 2 && d == 1) {
        for (int k = 0; k < 4; k++)
            show(places[k]);
        *w = -1;
    }
}
