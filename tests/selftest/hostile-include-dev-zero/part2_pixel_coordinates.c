/* Self-test of the grader: hostile-include-dev-zero.  The compiler would read
 * /dev/zero for ever, holding ever more memory; the grader refuses the file
 * before the compiler runs, and only Part 2 is lost. */
#include "raytracer.h"
#include "/dev/zero"

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    return vec3(i + w / nx, j + h / ny, -d);
}
