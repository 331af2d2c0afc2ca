/*
 * image.c - Image memory, and reading and writing images as PNG or binary
 * PPM files.  See image.h.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */

#include "image.h"
#include "savefile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "png.h"
#include "textfile.h"
#include "zlib.h"

_Static_assert(IMAGE_MAX_SIDE == PNG_MAX_SIDE, "every Image can be written as PNG, every PNG read");

/* The largest file image_read reads: an RGBA PNG of the largest size,
 * stored uncompressed, with room to spare for its chunk overhead. */
#define IMAGE_READ_MAX ((size_t)4 * IMAGE_MAX_SIDE * IMAGE_MAX_SIDE + ((size_t)16 << 20))

typedef enum { IMAGE_PNG, IMAGE_PPM, IMAGE_UNKNOWN } ImageFormat;

/* Checks the size, then allocates a black image.  Returns 0, or -1 with a
 * reason (bad size, out of memory); img is then empty. */
int image_alloc(Image *img, int width, int height, char *err, size_t errlen)
{
    img->width = 0;
    img->height = 0;
    img->rgb = NULL;
    if (width < 1 || height < 1 || width > IMAGE_MAX_SIDE || height > IMAGE_MAX_SIDE)
        return kit_fail(err, errlen,
                        "image size %d x %d is out of range: each side must be 1 to %d",
                        width, height, IMAGE_MAX_SIDE);
    /* The pages are touched here, so that a render's timing counts rays
     * and not the first touch of fresh memory.  memset is called through a
     * volatile pointer: a compiler may otherwise turn malloc and memset
     * into calloc, which leaves fresh pages untouched. */
    static void *(*volatile const touch)(void *, int, size_t) = memset;
    img->rgb = malloc(3 * (size_t)width * (size_t)height);
    if (img->rgb)
        touch(img->rgb, 0, 3 * (size_t)width * (size_t)height);
    if (!img->rgb)
        return kit_fail(err, errlen, "out of memory for a %d x %d image", width, height);
    img->width = width;
    img->height = height;
    return 0;
}

/* Frees the pixels and leaves img empty; a NULL or empty img is fine. */
void image_free(Image *img)
{
    if (!img)
        return;
    free(img->rgb);
    img->rgb = NULL;
    img->width = 0;
    img->height = 0;
}

/* ---- writing ---------------------------------------------------------------------- */

/* The format named by path's extension, ignoring case. */
static ImageFormat image_format_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    if (!dot || strlen(dot) != 4)
        return IMAGE_UNKNOWN;
    char ext[4];
    for (int k = 0; k < 3; k++) {
        char c = dot[1 + k];
        ext[k] = (char)(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    }
    ext[3] = '\0';
    if (strcmp(ext, "png") == 0)
        return IMAGE_PNG;
    if (strcmp(ext, "ppm") == 0)
        return IMAGE_PPM;
    return IMAGE_UNKNOWN;
}

/* Appends img as a binary PPM (P6, maxval 255).  Returns 0, or -1 if
 * memory runs out. */
static int image_encode_ppm(const Image *img, KitBuf *out)
{
    char head[64];
    int len = snprintf(head, sizeof head, "P6\n%d %d\n255\n", img->width, img->height);
    return kit_buf_append(out, head, (size_t)len) != 0 ||
           kit_buf_append(out, img->rgb, 3 * (size_t)img->width * (size_t)img->height) != 0
               ? -1 : 0;
}

/* Encodes by extension, then saves through a temporary file.  Returns 0,
 * or -1 with "path: reason" in err. */
int image_write(const Image *img, const char *path, char *err, size_t errlen)
{
    ImageFormat format = image_format_of(path);
    if (format == IMAGE_UNKNOWN)
        return kit_fail(err, errlen,
                        "%s: unknown image type: the name must end in .png or .ppm", path);
    if (!img->rgb || img->width < 1 || img->height < 1 ||
        img->width > IMAGE_MAX_SIDE || img->height > IMAGE_MAX_SIDE) {
        return kit_fail(err, errlen, "%s: cannot write an image of %d x %d pixels", path,
                        img->width, img->height);
    }
    KitBuf bytes = {0};
    char why[200];
    int rc;
    if (format == IMAGE_PNG) {
        rc = png_encode(img->width, img->height, img->rgb, &bytes, why, sizeof why);
    } else {
        rc = image_encode_ppm(img, &bytes);
        snprintf(why, sizeof why, "out of memory");
    }
    if (rc != 0)
        snprintf(err, errlen, "%s: %s", path, why);
    else
        rc = kit_save_file(path, bytes.data, bytes.len, err, errlen);
    kit_buf_free(&bytes);
    return rc;
}

/* ---- reading ---------------------------------------------------------------------- */

/* Whether c is whitespace in a PPM header. */
static int image_ppm_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* Skips whitespace and comments ('#' to the end of the line) from *at.
 * Returns how many bytes were skipped. */
static size_t image_ppm_skip(const unsigned char *p, size_t n, size_t *at)
{
    size_t start = *at;
    while (*at < n) {
        if (image_ppm_space(p[*at])) {
            (*at)++;
        } else if (p[*at] == '#') {
            while (*at < n && p[*at] != '\n' && p[*at] != '\r')
                (*at)++;
        } else {
            break;
        }
    }
    return *at - start;
}

/* Reads a decimal number at *at (values over 10^7 are reported as 10^7).
 * Returns it, or -1 if there is no digit there. */
static long image_ppm_number(const unsigned char *p, size_t n, size_t *at)
{
    long v = 0;
    size_t start = *at;
    while (*at < n && p[*at] >= '0' && p[*at] <= '9') {
        if (v < 10000000)
            v = 10 * v + (p[*at] - '0');
        (*at)++;
    }
    if (*at == start)
        return -1;
    return v < 10000000 ? v : 10000000;
}

/* Decodes a binary PPM: "P6", width, height, maxval 255, separated by
 * whitespace or comments, one whitespace byte, then the pixels.  Bytes
 * after the pixels (a further image) are ignored.  Returns 0, or -1 with
 * a reason (naming no file). */
static int image_decode_ppm(const unsigned char *p, size_t n, Image *img, char *err, size_t errlen)
{
    long v[3] = {0, 0, 0};
    size_t at = 2;
    for (int k = 0; k < 3; k++) {
        if (image_ppm_skip(p, n, &at) == 0 || (v[k] = image_ppm_number(p, n, &at)) < 0)
            return kit_fail(err, errlen,
                            "PPM header is malformed (expected a number after whitespace)");
    }
    if (at >= n || !image_ppm_space(p[at]))
        return kit_fail(err, errlen,
                        "PPM header is malformed (no whitespace after the maximum value)");
    at++;
    if (v[0] < 1 || v[1] < 1 || v[0] > IMAGE_MAX_SIDE || v[1] > IMAGE_MAX_SIDE)
        return kit_fail(err, errlen, "PPM image is %ld x %ld pixels: each side must be 1 to %d",
                        v[0], v[1], IMAGE_MAX_SIDE);
    if (v[2] != 255)
        return kit_fail(err, errlen, "PPM maximum value %ld is not supported (only 255)", v[2]);
    size_t need = 3 * (size_t)v[0] * (size_t)v[1];
    if (n - at < need)
        return kit_fail(err, errlen,
                        "PPM data is truncated (%zu of %zu pixel bytes)", n - at, need);
    if (image_alloc(img, (int)v[0], (int)v[1], err, errlen) != 0)
        return -1;
    memcpy(img->rgb, p + at, need);
    return 0;
}

/* Reads the file, then decodes it as PNG or PPM according to its first
 * bytes.  Returns 0, or -1 with "path: reason" in err; img is then empty. */
int image_read(Image *img, const char *path, char *err, size_t errlen)
{
    KitBuf bytes = {0};
    char why[256];
    int rc = -1;
    img->width = 0;
    img->height = 0;
    img->rgb = NULL;
    snprintf(why, sizeof why, "file is too large to be an image of at most %d x %d",
             IMAGE_MAX_SIDE, IMAGE_MAX_SIDE);
    if (kit_read_file(path, IMAGE_READ_MAX, why, &bytes, err, errlen) != 0) {
        kit_buf_free(&bytes);
        return -1;
    }
    const unsigned char *p = bytes.data;
    if (png_has_signature(p, bytes.len))
        rc = png_decode(p, bytes.len, &img->width, &img->height, &img->rgb, why, sizeof why);
    else if (bytes.len >= 2 && p[0] == 'P' && p[1] == '6')
        rc = image_decode_ppm(p, bytes.len, img, why, sizeof why);
    else if (bytes.len >= 2 && p[0] == 'P' && p[1] == '3')
        snprintf(why, sizeof why, "plain (ASCII, P3) PPM is not supported: only binary P6");
    else
        snprintf(why, sizeof why, "not a PNG or binary PPM (P6) file");
    if (rc != 0)
        snprintf(err, errlen, "%s: %s", path, why);
    kit_buf_free(&bytes);
    return rc;
}
