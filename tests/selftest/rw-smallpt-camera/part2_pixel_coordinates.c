/* Real-world method: smallpt (Kevin Beason, main's camera), converted to
 * the kit: the point cx ((x + 0.5) / w - .5) + cy ((y + 0.5) / h - .5) +
 * cam.d, the pixel centre of the source's 2x2 subpixel tent filter, with
 * cx, cy the plane's width and height vectors (here (w, 0, 0) and
 * (0, h, 0)) and cam.d the axis (here (0, 0, -d)).  smallpt's y counts
 * rows from the BOTTOM (pixel (x, y) is stored at row h - y - 1); here it
 * is the kit's j, as copied. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    Vec3 cx = vec3(w, 0, 0), cy = vec3(0, h, 0), camd = vec3(0, 0, -d);
    Vec3 p = vec3_add(vec3_scale(cx, (i + .5) / nx - .5), vec3_scale(cy, (j + .5) / ny - .5));
    return vec3_add(p, camd);
}
