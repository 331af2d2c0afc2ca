/* Real-world method: Ray Tracing in One Weekend, v3 (2020), the camera of
 * chapter 4 and its render loop, converted to the kit: horizontal = (w, 0, 0),
 * vertical = (0, h, 0), lower_left_corner = origin - horizontal/2 -
 * vertical/2 - (0, 0, focal_length), u = i / (image_width - 1),
 * v = j / (image_height - 1), and the point lower_left_corner + u horizontal
 * + v vertical.  The book's j counts rows from the bottom (its loop runs
 * j = image_height - 1 down to 0 to write the top row first); here it is
 * the kit's j, as copied. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double focal_length = d;
    Vec3 origin = vec3(0, 0, 0);
    Vec3 horizontal = vec3(w, 0, 0);
    Vec3 vertical = vec3(0, h, 0);
    Vec3 lower_left_corner = vec3_sub(vec3_sub(vec3_sub(origin, vec3_scale(horizontal, 0.5)),
                                               vec3_scale(vertical, 0.5)),
                                      vec3(0, 0, focal_length));
    double u = (double)i / (nx - 1);
    double v = (double)j / (ny - 1);
    return vec3_add(vec3_add(lower_left_corner, vec3_scale(horizontal, u)), vec3_scale(vertical, v));
}
