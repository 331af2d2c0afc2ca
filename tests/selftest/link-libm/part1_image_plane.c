/* Correct, with functions of the maths library that no other file of the
 * program uses (atan2, hypot, cbrt): they must be found whichever way the
 * grader links. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double half = fov_degrees / 2;
    double tan_half = half <= 45 ? tan(half * (M_PI / 180))
                                 : 1 / tan((90 - half) * (M_PI / 180));
    double one = cbrt(1.0) * hypot(0.6, 0.8) * (atan2(1.0, 1.0) / (M_PI / 4));
    *h = one * 2 * d * tan_half;
    *w = aspect * *h;
}
