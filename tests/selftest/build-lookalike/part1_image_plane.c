/* Self-test of the grader: build-lookalike.  The reference’s Part 1 with a
 * non-breaking space in its code, as a copy from a web page or PDF gives
 * it: the compiler says "stray '\302'", the grader names the character. */
#include "raytracer.h"

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    /* tan(alpha / 2) with alpha / 2 in degrees.  Above 45 degrees use
     * tan(x) = 1 / tan(90 - x): 90 - x is exact, so a field of view near 180
     * keeps all its digits instead of losing five of them to the rounding
     * of pi / 2 (tan is steep there). */
    double half = fov_degrees / 2;
    double tan_half = half <= 45 ? tan(half * (M_PI / 180))
                                 : 1 / tan((90 - half) * (M_PI / 180));
    *h = 2 * d * tan_half;
    *w = aspect * *h;
}
