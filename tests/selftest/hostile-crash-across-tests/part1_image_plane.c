/* Correct, but only for the first 40 calls a process makes: each test,
 * run alone, makes fewer (20 to 40 today); all of Part 1's tests in one
 * process make more.  The grader may run a part's tests together only as
 * a shortcut: every test must still get the verdict it gets alone. */
#include "raytracer.h"
#include <stdlib.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    static int calls;
    *w = *h = 0;
    if (++calls > 40)
        abort();        /* later tests of the same process crash */
    double half = fov_degrees / 2;
    double tan_half = half <= 45 ? tan(half * (M_PI / 180))
                                 : 1 / tan((90 - half) * (M_PI / 180));
    *h = 2 * d * tan_half;
    *w = aspect * *h;
}
