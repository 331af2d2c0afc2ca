/* Real-world method: tinyraytracer (Dmitry Sokolov, main's ray loop),
 * converted to the kit.  tinyraytracer puts an image plane of height
 * `height` pixels at distance height / (2 tan(fov / 2)), with fov the
 * VERTICAL field of view in RADIANS (its constant fov = 1.05, "60 degrees").
 * In the kit's units: h = 2 d tan(fov / 2), w = aspect h -- with the
 * kit's fov_degrees passed to tan as the source passes its fov. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double fov = fov_degrees;
    *h = 2. * d * tan(fov / 2.);
    *w = *h * aspect;
}
