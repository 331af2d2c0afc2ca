/* Part 1 with pi written out to six digits, as many tutorials do. */
#include "raytracer.h"

#define PI 3.14159

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * PI / 360);
    *w = aspect * *h;
}
