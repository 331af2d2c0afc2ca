/* Self-test of the grader: p2-integer-division-top.  The handout's y form,
 * y = h/2 - (j + 0.5) h / ny, over one integer denominator: (2 j + 1) /
 * (2 ny) is 0 in C, as is (2 i + 1) / (2 nx), so every pixel is the plane's
 * top-left corner (-w/2, h/2). */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double x = -w / 2 + w * ((2 * i + 1) / (2 * nx));
    double y = h / 2 - h * ((2 * j + 1) / (2 * ny));
    return vec3(x, y, -d);
}
