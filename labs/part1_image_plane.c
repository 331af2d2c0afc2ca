/* Part 1: the size of the image plane. */
#include "raytracer.h"

/*
 * image_plane_size - the width w and height h of the image plane.
 *
 * Parameters:
 *   fov_degrees  alpha, the VERTICAL field of view in degrees, 0 < alpha < 180
 *   aspect       nx / ny, the image's width over its height, > 0
 *   d            distance from the eye to the image plane, > 0 (scene units)
 *   w, h         out: the plane's width and height (scene units)
 * Returns:       nothing; stores *w and *h.
 * Example:       alpha = 90, aspect = 2, d = 1  ->  h = 2 tan(45 deg) = 2, w = 4
 *                alpha = 60, aspect = 1, d = 3  ->  h = w = 6 tan(30 deg) = 3.4641...
 * Formula:       h = 2 d tan(alpha / 2)      (tan takes radians: deg * pi / 180)
 *                w = aspect h
 */
void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    /* TODO Part 1: compute *h from fov_degrees and d, then *w from aspect. */
    (void)fov_degrees;
    (void)aspect;
    (void)d;
    *w = 0.0;
    *h = 0.0;
}
