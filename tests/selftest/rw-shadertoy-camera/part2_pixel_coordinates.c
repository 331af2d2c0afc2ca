/* Real-world method: the Shadertoy camera idiom (mainImage's fragCoord, as
 * in Inigo Quilez's shaders), converted to the kit: fragCoord is the pixel
 * centre (i + 0.5, j + 0.5) with its origin at the BOTTOM-left (OpenGL's
 * gl_FragCoord), uv = (fragCoord - 0.5 iResolution.xy) / iResolution.y so
 * that both axes are measured in units of the image height (square
 * pixels), and the point uv times the plane's height h on z = -d.  Here j
 * is the kit's j, as copied. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    (void)w;                            /* uv.x is scaled by the height */
    double fragx = i + 0.5, fragy = j + 0.5;
    double uvx = (fragx - 0.5 * nx) / ny;
    double uvy = (fragy - 0.5 * ny) / ny;
    return vec3(uvx * h, uvy * h, -d);
}
