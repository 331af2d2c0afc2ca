/* Real-world method: Mitsuba 3's perspective sensor, converted to the kit:
 * its fov applies to fov_axis, by default "x", so it is the HORIZONTAL
 * field of view (x_fov); the frustum's half width at the near plane is
 * right = tan(0.5 deg_to_rad(x_fov)) near_clip and its half height
 * top = right / aspect.  Here near_clip is the kit's d. */
#include "raytracer.h"

static double deg_to_rad(double deg)
{
    return deg * (M_PI / 180.0);
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double x_fov = fov_degrees;         /* fov_axis = "x" */
    double near_clip = d;
    double right = tan(0.5 * deg_to_rad(x_fov)) * near_clip;
    double top = right / aspect;
    *w = 2 * right;
    *h = 2 * top;
}
