/* Part 2 with a copy of Part 1's function in it: the part's program holds
 * Part 1's reference, so that name is defined twice and Part 2 does not
 * build (students see the same in their own build, which links all four
 * files). */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    return vec3(-w / 2 + (i + 0.5) * w / nx, h / 2 - (j + 0.5) * h / ny, -d);
}
