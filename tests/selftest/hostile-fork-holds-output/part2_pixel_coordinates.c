/* Self-test of the grader: hostile-fork-holds-output. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <unistd.h>

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    static int forked;
    if (!forked++ && fork() == 0) {
        setsid();
        sleep(60);
    }
    (void)i; (void)j; (void)nx; (void)ny; (void)w; (void)h; (void)d;
    return vec3(0, 0, 0);      /* wrong, whether or not the fork worked */
}
