/*
 * png.h - PNG images in memory (the PNG specification, ISO/IEC 15948).
 *
 * The pixels are raw bytes: a width x height image is 3 * width * height
 * bytes (r, g, b), row by row from the top, as an Image holds them (image.c
 * reads and writes Image files with these two functions).
 *
 * png_encode writes such pixels as 8-bit RGB: the signature, IHDR, one or
 * more IDAT chunks and IEND, every chunk with its CRC.  Each row gets the
 * filter whose output has the smallest sum of absolute (signed) byte values.
 *
 * png_decode reads 8-bit greyscale, greyscale+alpha, RGB or RGBA images
 * (colour types 0, 4, 2 and 6), not interlaced, with any of the five
 * filters and any number of IDAT chunks.  Alpha is dropped; grey becomes
 * r = g = b.  Every chunk's CRC is checked.  Palette images, other bit
 * depths, interlacing and sides over PNG_MAX_SIDE are refused with a
 * message saying so.
 */
#ifndef KIT_PNG_H
#define KIT_PNG_H

#include <stddef.h>
#include "zlib.h"

#define PNG_SIGNATURE_SIZE 8
#define PNG_MAX_SIDE 16384        /* the largest width or height: image.h's IMAGE_MAX_SIDE */

/* Whether data[0 .. n-1] starts with the 8-byte PNG signature. */
int png_has_signature(const void *data, size_t n);

/* Appends the width x height pixels rgb as a PNG file to out.  Returns 0,
 * or -1 with a reason in err (an invalid size, or memory ran out); out then
 * keeps its old length. */
int png_encode(int width, int height, const unsigned char *rgb, KitBuf *out, char *err,
               size_t errlen);

/* Decodes the PNG file data[0 .. n-1]: its size into *width, *height and
 * its pixels into *rgb, freshly allocated (free it with free).  Returns 0,
 * or -1 with a reason in err (which names no file: the caller adds that);
 * *rgb is then NULL and the sides 0. */
int png_decode(const void *data, size_t n, int *width, int *height, unsigned char **rgb,
               char *err, size_t errlen);

#endif
