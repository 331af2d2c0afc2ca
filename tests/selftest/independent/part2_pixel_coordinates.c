/* Self-test: a correct submission written without looking at solutions/. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double pixel_w = w / nx, pixel_h = h / ny;
    Vec3 s = { -w / 2 + (i + 0.5) * pixel_w, h / 2 - (j + 0.5) * pixel_h, -d };
    return s;
}
