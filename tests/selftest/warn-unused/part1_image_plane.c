/* Part 1, right but for the hard cases near 180 degrees, with a variable
 * left over from an earlier try: the compiler warns, and every report says
 * so, though no test fails for it. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double half_angle;
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
