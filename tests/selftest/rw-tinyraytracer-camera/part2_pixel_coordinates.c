/* Real-world method: tinyraytracer (Dmitry Sokolov, main's ray loop),
 * converted to the kit: the pixel's offset from the image centre in pixel
 * units, dir_x = (i + 0.5) - width/2 and dir_y = -(j + 0.5) + height/2 (the
 * minus "flips the image": row 0 is the top), stored in float as the source
 * does; then scaled to the plane's units, w / nx and h / ny per pixel, on
 * the plane z = -d. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    float dir_x = (i + 0.5) - nx / 2.;
    float dir_y = -(j + 0.5) + ny / 2.;
    return vec3(dir_x * (w / nx), dir_y * (h / ny), -d);
}
