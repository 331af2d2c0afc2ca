/* Real-world method: Scratchapixel, "Ray-Tracing: Generating Camera Rays"
 * (render()), converted to the kit: float scale = tan(deg2rad(fov * 0.5))
 * with the VERTICAL field of view in degrees, the image plane at distance 1
 * spanning [-scale, scale] vertically and imageAspectRatio times that
 * horizontally -- so h = 2 scale and w = aspect h, at distance 1. */
#include "raytracer.h"

/* deg2rad: float, as in the lesson's code. */
static float deg2rad(float deg)
{
    return deg * M_PI / 180;
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    (void)d;                            /* the lesson's plane is at z = -1 */
    float scale = tan(deg2rad(fov_degrees * 0.5));
    float imageAspectRatio = aspect;
    *h = 2 * scale;
    *w = 2 * imageAspectRatio * scale;
}
