/* Self-test of the grader: hostile-compile-error. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    return vec3(i * w / nx, j * h / ny, -d)   /* a missing semicolon */
}
