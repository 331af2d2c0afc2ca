/* Real-world method: pbrt-v4's perspective camera, converted to the kit:
 * the screen window is [-frame, frame] x [-1, 1] when frame = nx / ny > 1
 * and [-1, 1] x [-1/frame, 1/frame] otherwise, and Perspective(fov) scales
 * it by 1 / tan(Radians(fov) / 2) -- so fov spans the image's SHORTER side:
 * vertical for wide images, horizontal for tall ones.  The plane at the
 * kit's distance d is the screen window times d tan(fov / 2). */
#include "raytracer.h"

/* pbrt's Radians: (Pi / 180) deg. */
static double Radians(double deg)
{
    return (M_PI / 180) * deg;
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    double frame = aspect;
    double xmin, xmax, ymin, ymax;
    if (frame > 1) {
        xmin = -frame, xmax = frame;
        ymin = -1, ymax = 1;
    } else {
        xmin = -1, xmax = 1;
        ymin = -1 / frame, ymax = 1 / frame;
    }
    double tanAng = tan(Radians(fov_degrees) / 2);
    *w = (xmax - xmin) * tanAng * d;
    *h = (ymax - ymin) * tanAng * d;
}
