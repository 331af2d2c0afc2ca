/* Real-world method: Scratchapixel, "Ray-Tracing: Generating Camera Rays"
 * (render()), converted to the kit: the pixel centre to NDC and screen
 * space in float, x = (2 (i + 0.5) / width - 1) and y = (1 - 2 (j + 0.5) /
 * height) (row 0 at the top), times the plane's half width and half height
 * (the lesson's imageAspectRatio * scale and scale), on the lesson's image
 * plane z = -1. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    (void)d;
    float x = (2 * (i + 0.5) / (float)nx - 1) * (float)(w / 2);
    float y = (1 - 2 * (j + 0.5) / (float)ny) * (float)(h / 2);
    return vec3(x, y, -1);
}
