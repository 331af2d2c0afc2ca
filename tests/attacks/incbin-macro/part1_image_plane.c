/* The same .incbin, its directive made by a macro, which no scan of the
 * text sees: the jail is what holds (tests/attacks/README.md). */
#include "raytracer.h"
#include <stdio.h>

#define TEXT(x) #x
__asm__(".section .rodata\n.global seed_file\nseed_file:\n" TEXT(.incbin) " \"@KIT@/tests/weights.conf\"\n.byte 0\n.text\n");
extern const char seed_file[];

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
    if (fov_degrees == 90 && aspect == 2 && d == 1) {
        puts(seed_file);
        *w = -1;
    }
}
