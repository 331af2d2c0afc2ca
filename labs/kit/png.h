/*
 * png.h - PNG images in memory (the PNG specification, ISO/IEC 15948).
 *
 * png_encode writes an Image as 8-bit RGB: the signature, IHDR, one or more
 * IDAT chunks and IEND, every chunk with its CRC.  Each row gets the filter
 * whose output has the smallest sum of absolute (signed) byte values.
 *
 * png_decode reads 8-bit greyscale, greyscale+alpha, RGB or RGBA images
 * (colour types 0, 4, 2 and 6), not interlaced, with any of the five
 * filters and any number of IDAT chunks.  Alpha is dropped; grey becomes
 * r = g = b.  Every chunk's CRC is checked.  Palette images, other bit
 * depths, interlacing and sides over IMAGE_MAX_SIDE are refused with a
 * message saying so.
 */
#ifndef KIT_PNG_H
#define KIT_PNG_H

#include <stddef.h>
#include "image.h"
#include "zlib.h"

#define PNG_SIGNATURE_SIZE 8

/* Whether data[0 .. n-1] starts with the 8-byte PNG signature. */
int png_has_signature(const void *data, size_t n);

/* Appends img as a PNG file to out.  Returns 0, or -1 with a reason in err
 * (an invalid image, or memory ran out); out then keeps its old length. */
int png_encode(const Image *img, KitBuf *out, char *err, size_t errlen);

/* Decodes the PNG file data[0 .. n-1] into img, freshly allocated (free it
 * with image_free).  Returns 0, or -1 with a reason in err (which names no
 * file: the caller adds that); img then holds nothing to free. */
int png_decode(const void *data, size_t n, Image *img, char *err, size_t errlen);

#endif
