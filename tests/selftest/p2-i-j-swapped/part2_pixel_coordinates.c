/* Part 2 with (i, j) read as (row, column): x from j, y from i. */
#include "raytracer.h"
Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    return vec3(-w / 2 + (j + 0.5) * w / nx, h / 2 - (i + 0.5) * h / ny, -d);
}
