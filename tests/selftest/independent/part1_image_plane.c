/* Self-test of the grader and the renderer: a correct submission written
 * without looking at solutions/, the way a careful student might. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double half_angle = fov_degrees / 2 * (M_PI / 180);
    *h = 2 * d * tan(half_angle);
    *w = aspect * *h;
}
