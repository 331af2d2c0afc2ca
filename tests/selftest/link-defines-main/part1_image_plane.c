/* A stage file with its own main (left from trying it alone): the part's
 * program already has one, so the part does not build. */
#include "raytracer.h"
#include <stdio.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}

int main(void)
{
    double w, h;
    image_plane_size(90, 2, 1, &w, &h);
    printf("%g %g\n", w, h);
    return 0;
}
