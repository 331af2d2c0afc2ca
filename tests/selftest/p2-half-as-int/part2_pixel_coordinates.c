/* Self-test of the grader: p2-half-as-int.  The lecture's formula with the
 * half written 1 / 2, an integer division: i + 1 / 2 is i, the pixel's
 * corner. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double x = -w / 2 + w * (i + 1 / 2) / nx;
    double y = -h / 2 + h * (ny - 1 / 2 - j) / ny;
    return vec3(x, y, -d);
}
