/* Real-world method: Ray Tracing in One Weekend, v4 (camera::initialize and
 * get_ray), converted to the kit: the camera at the origin looking down -z
 * (u = +x, v = +y, w = +z), viewport_u across the top edge and viewport_v
 * DOWN the left edge, pixel deltas viewport_u / image_width and
 * viewport_v / image_height (the book's vec3 division multiplies by 1/t),
 * pixel00_loc half a delta in from the upper-left corner, and pixel (i, j)
 * at pixel00_loc + i delta_u + j delta_v: rows counted from the top. */
#include "raytracer.h"

/* The book's v / t: (1 / t) v. */
static Vec3 divide(Vec3 v, double t)
{
    return vec3_scale(v, 1 / t);
}

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double focal_length = d;
    Vec3 center = vec3(0, 0, 0);
    Vec3 u = vec3(1, 0, 0), v = vec3(0, 1, 0), wv = vec3(0, 0, 1);

    Vec3 viewport_u = vec3_scale(u, w);                 /* across the top edge */
    Vec3 viewport_v = vec3_scale(vec3_negate(v), h);    /* down the left edge */
    Vec3 pixel_delta_u = divide(viewport_u, nx);
    Vec3 pixel_delta_v = divide(viewport_v, ny);

    Vec3 viewport_upper_left = vec3_sub(vec3_sub(vec3_sub(center, vec3_scale(wv, focal_length)),
                                                 divide(viewport_u, 2)),
                                        divide(viewport_v, 2));
    Vec3 pixel00_loc = vec3_add(viewport_upper_left,
                                vec3_scale(vec3_add(pixel_delta_u, pixel_delta_v), 0.5));
    return vec3_add(vec3_add(pixel00_loc, vec3_scale(pixel_delta_u, i)), vec3_scale(pixel_delta_v, j));
}
