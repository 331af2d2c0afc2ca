/* Self-test of the grader: p2-integer-division. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double x = -w / 2 + w * ((2 * i + 1) / (2 * nx));
    double y = -h / 2 + h * ((2 * (ny - j) - 1) / (2 * ny));
    (void)i; (void)j; (void)nx; (void)ny; (void)w; (void)h;
    return vec3(x, y, -d);
}
