/* Self-test of the grader: hostile-infinite-loop. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    volatile double x = 0;
    for (;;)
        x += i + j + nx + ny + w + h + d;
}
