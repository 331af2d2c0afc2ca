/* Part 1, right, with a helper that Part 3b's file uses too: it links in
 * make render, where every file is there, and not where Part 3b is graded
 * with the reference's other parts. */
#include "raytracer.h"

double twice(double x);
double twice(double x)
{
    return 2 * x;
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double t = fov_degrees <= 90 ? tan(fov_degrees * (M_PI / 360))
                                 : 1 / tan((180 - fov_degrees) * (M_PI / 360));
    *h = twice(d * t);
    *w = aspect * *h;
}
