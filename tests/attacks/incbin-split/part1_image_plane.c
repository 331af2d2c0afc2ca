/* The hidden tests' seed read into the program by the assembler's .incbin,
 * its name split in two strings for a scan that reads them one at a time
 * (tests/attacks/README.md). */
#include "raytracer.h"

__asm__(".section .rodata\n.global seed_file\nseed_file:\n.inc" "bin \"@KIT@/tests/weights.conf\"\n.byte 0\n.text\n");
extern const char seed_file[];

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360) + (seed_file[0] == 0);
    *w = aspect * *h;
}
