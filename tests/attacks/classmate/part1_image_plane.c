/* A classmate's Part 1, right, with a line no other file has (read-kit
 * must not find it): CLASSMATE-WORK-7f3a9c. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
