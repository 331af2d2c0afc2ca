/* Self-test of the grader: p2-z-sign. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double x = -w / 2 + w * (i + 0.5) / nx;
    double y = -h / 2 + h * (ny - 0.5 - j) / ny;
    (void)i; (void)j; (void)nx; (void)ny; (void)w; (void)h;
    return vec3(x, y, d);
}
