/* Part 2: the 3-d coordinates of a pixel's centre. */
#include "raytracer.h"

/*
 * pixel_coordinates - the centre of pixel (i, j) on the image plane.
 *
 * Parameters:
 *   i, j         column (from the left) and row (from the top), 0-based:
 *                0 <= i < nx, 0 <= j < ny
 *   nx, ny       image size in pixels (columns, rows), >= 1
 *   w, h         the image plane's width and height (Part 1), scene units
 *   d            distance from the eye to the image plane, > 0
 * Returns:       the point (x, y, z) at the pixel's centre; z = -d.
 * Example:       nx = 4, ny = 2, w = 4, h = 2, d = 1:
 *                pixel (0, 0) -> (-1.5,  0.5, -1)   (top left)
 *                pixel (3, 1) -> ( 1.5, -0.5, -1)   (bottom right)
 * Formula:       x = -w/2 + w (i + 0.5) / nx
 *                y = -h/2 + h (ny - 0.5 - j) / ny   (row 0 is the top: +y is up)
 *                z = -d
 */
Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    /* The lecture's formula over one denominator:
     *   -w/2 + w (i + 0.5) / nx = (2 i + 1 - nx) w / (2 nx).
     * The integer factor is exact, so x(nx - 1 - i) = -x(i) exactly and the
     * centre column is exactly 0; the error is one rounding of w / (2 nx)
     * and one of the product. */
    double x = (2.0 * i + 1 - nx) * (w / (2.0 * nx));
    double y = (ny - 1 - 2.0 * j) * (h / (2.0 * ny));
    return vec3(x, y, -d);
}
