/* Part 1 with the half angle and its tangent in float, the rest in double:
 * no answer is a float, but none is right past float's seven digits. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    float t = tanf((float)(fov_degrees * M_PI / 360));
    *h = 2 * d * t;
    *w = aspect * *h;
}
