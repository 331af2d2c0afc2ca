/*
 * image.h - an 8-bit RGB image, and reading and writing it as PNG or PPM.
 *
 * Pixels are stored row by row from the top, 3 bytes (r, g, b) each:
 * pixel (i, j) -- column i, row j -- starts at rgb[3 * (j * width + i)].
 * Functions that can fail return 0 on success and -1 on failure, with a
 * one-line reason (naming the file) in err[0 .. errlen - 1].
 */
#ifndef KIT_IMAGE_H
#define KIT_IMAGE_H

#include <stddef.h>

#define IMAGE_MAX_SIDE 16384      /* the largest width or height accepted */

typedef struct {
    int width, height;
    unsigned char *rgb;           /* 3 * width * height bytes */
} Image;

/* Allocates a black width x height image; 1 <= width, height <= IMAGE_MAX_SIDE. */
int image_alloc(Image *img, int width, int height, char *err, size_t errlen);
void image_free(Image *img);

/* A colour channel in [0, 1] as a byte: round(255 c), clamped; NaN gives 0.
 * Defined here so that the grader's render program
 * (tests/grader/harness_render.c), which links no kit library, makes the
 * same bytes as the renderer. */
static inline unsigned char image_channel(double c)
{
    if (!(c > 0))
        return 0;
    if (c >= 1)
        return 255;
    double x = 255 * c;               /* in (0, 255): round half up, no libm call */
    int k = (int)x;
    return (unsigned char)(k + (x - k >= 0.5));
}

/* Writes img to path as PNG (.png) or binary PPM (.ppm), chosen by the
 * extension.  The bytes go to a temporary file beside path that is renamed
 * over path only once complete: path is never left half-written. */
int image_write(const Image *img, const char *path, char *err, size_t errlen);

/* Reads a PNG (8-bit RGB or RGBA, any filter, not interlaced) or a binary
 * PPM (maxval 255) into a freshly allocated img. */
int image_read(Image *img, const char *path, char *err, size_t errlen);

#endif
