/* Real-world method: Gabriel Gambetta, "Computer Graphics from Scratch",
 * chapter 2 (the main loop, CanvasToViewport and PutPixel), converted to
 * the kit: canvas coordinates x = -Cw/2 .. Cw/2 - 1 and y = -Ch/2 ..
 * Ch/2 - 1 with y up, PutPixel's screen column Cw/2 + x and row
 * Ch/2 - y - 1 (so x = i - nx/2, y = ny/2 - 1 - j), and CanvasToViewport's
 * (x Vw / Cw, y Vh / Ch, d) with the viewport Vw x Vh = w x h.  The book
 * looks down +z; the kit's plane is at z = -d. */
#include "raytracer.h"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double x = i - nx / 2.0, y = ny / 2.0 - 1 - j;
    return vec3(x * w / nx, y * h / ny, -d);
}
