/*
 * png.c - encoding and decoding PNG images in memory, as raw RGB bytes.
 * See png.h.
 */
#include "png.h"
#include "textfile.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const unsigned char png_signature[PNG_SIGNATURE_SIZE] = {
    0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

#define PNG_IDAT_MAX   32768u        /* bytes of zlib data per IDAT chunk written */
#define PNG_CHUNK_MAX  0x7FFFFFFFu   /* the largest chunk length allowed */

/* Whether the signature is there. */
int png_has_signature(const void *data, size_t n)
{
    return n >= PNG_SIGNATURE_SIZE && memcmp(data, png_signature, PNG_SIGNATURE_SIZE) == 0;
}

/* ---- shared by both directions ------------------------------------------------ */

/* The Paeth predictor: whichever of a (left), b (up), c (up-left) is
 * closest to a + b - c, preferring a, then b. */
static unsigned char png_paeth(unsigned char a, unsigned char b, unsigned char c)
{
    int p = (int)a + b - c;
    int pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    if (pa <= pb && pa <= pc)
        return a;
    return pb <= pc ? b : c;
}

/* The prediction of byte k of a row under filter type (1..4), from the
 * unfiltered bytes to its left (bpp bytes back) and above (prev). */
static unsigned char png_predict(int type, const unsigned char *row, const unsigned char *prev,
                                 size_t k, size_t bpp)
{
    unsigned char a = k >= bpp ? row[k - bpp] : 0;
    unsigned char b = prev[k];
    unsigned char c = k >= bpp ? prev[k - bpp] : 0;
    switch (type) {
    case 1: return a;
    case 2: return b;
    case 3: return (unsigned char)((a + b) / 2);
    case 4: return png_paeth(a, b, c);
    default: return 0;
    }
}

/* ---- encoder -------------------------------------------------------------------- */

/* Appends one chunk: length, type, data, CRC of type and data.
 * Returns 0, or -1 if memory runs out. */
static int png_put_chunk(KitBuf *out, const char *type, const unsigned char *data, size_t n)
{
    unsigned char head[8], tail[4];
    kit_put_be32(head, (uint32_t)n);
    memcpy(head + 4, type, 4);
    uint32_t crc = kit_crc32(kit_crc32(0, head + 4, 4), data, n);
    kit_put_be32(tail, crc);
    if (kit_buf_append(out, head, 8) != 0 || kit_buf_append(out, data, n) != 0 ||
        kit_buf_append(out, tail, 4) != 0)
        return -1;
    return 0;
}

/* Filters row (len bytes, above it prev) with filter type into dst. */
static void png_filter_row(int type, const unsigned char *row, const unsigned char *prev,
                           size_t len, size_t bpp, unsigned char *dst)
{
    /* The first pixel (no left neighbour) as png_predict says; the rest in
     * a loop of one filter type each, with no test of the type or of the
     * left edge per byte. */
    size_t first = bpp < len ? bpp : len;
    for (size_t k = 0; k < first; k++)
        dst[k] = (unsigned char)(row[k] - png_predict(type, row, prev, k, bpp));
    switch (type) {
    case 1:
        for (size_t k = first; k < len; k++)
            dst[k] = (unsigned char)(row[k] - row[k - bpp]);
        break;
    case 2:
        for (size_t k = first; k < len; k++)
            dst[k] = (unsigned char)(row[k] - prev[k]);
        break;
    case 3:
        for (size_t k = first; k < len; k++)
            dst[k] = (unsigned char)(row[k] - (row[k - bpp] + prev[k]) / 2);
        break;
    case 4:
        for (size_t k = first; k < len; k++)
            dst[k] = (unsigned char)(row[k] - png_paeth(row[k - bpp], prev[k], prev[k - bpp]));
        break;
    default:
        memcpy(dst + first, row + first, len - first);
        break;
    }
}

/* A filtered byte read as signed, its absolute value: what the choice of
 * filter adds up. */
static unsigned png_cost(int x)
{
    unsigned v = (unsigned char)x;
    return v < 128 ? v : 256u - v;
}

enum { PNG_RUN = 32 };

/* A difference of bytes (in -510..510) taken modulo 256 and read as a
 * signed byte, its absolute value (0..128): png_cost in 16-bit lanes. */
static int16_t png_cost16(int16_t d)
{
    int16_t v = (int16_t)((int16_t)((d & 0xFF) ^ 0x80) - 0x80);
    int16_t m = (int16_t)-v;
    return v > m ? v : m;
}

/* Adds to sum[0..4] the five filters' costs of the PNG_RUN bytes x (left of
 * them a, above b, above-left c).  A loop of fixed length without branches
 * (the Paeth choice written as selections), in 16-bit numbers, which
 * compilers turn into vector instructions at -O2; a run's sums (at most
 * 32 x 128) fit in 16 bits too. */
static void png_run_costs(const unsigned char *x, const unsigned char *a, const unsigned char *b,
                          const unsigned char *c, size_t sum[5])
{
    int16_t s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0;
    for (int k = 0; k < PNG_RUN; k++) {
        int16_t xk = x[k], ak = a[k], bk = b[k], ck = c[k];
        int16_t d1 = (int16_t)(bk - ck), d2 = (int16_t)(ak - ck), d3 = (int16_t)(ak + bk - 2 * ck);
        int16_t pa = d1 > -d1 ? d1 : (int16_t)-d1;
        int16_t pb = d2 > -d2 ? d2 : (int16_t)-d2;
        int16_t pc = d3 > -d3 ? d3 : (int16_t)-d3;
        int16_t paeth = pa <= pb && pa <= pc ? ak : pb <= pc ? bk : ck;
        s0 = (int16_t)(s0 + png_cost16(xk));
        s1 = (int16_t)(s1 + png_cost16((int16_t)(xk - ak)));
        s2 = (int16_t)(s2 + png_cost16((int16_t)(xk - bk)));
        s3 = (int16_t)(s3 + png_cost16((int16_t)(xk - ((ak + bk) >> 1))));
        s4 = (int16_t)(s4 + png_cost16((int16_t)(xk - paeth)));
    }
    sum[0] += (size_t)s0;
    sum[1] += (size_t)s1;
    sum[2] += (size_t)s2;
    sum[3] += (size_t)s3;
    sum[4] += (size_t)s4;
}

/* The filter type (0..4) whose filtered row has the least sum of absolute
 * values, the lowest type on a tie: the five sums in one pass over the row,
 * without writing any filtered byte (png_filter_row then writes the chosen
 * one).  The first pixel, which has no left neighbour, is a run of its own
 * padded with zeros (which cost 0 under every filter); what is left after
 * the last whole run is taken a byte at a time. */
static int png_choose_filter(const unsigned char *row, const unsigned char *prev, size_t len,
                             size_t bpp)
{
    static const unsigned char zeros[PNG_RUN];
    size_t sum[5] = { 0, 0, 0, 0, 0 }, k = 0;
    if (len >= bpp && bpp <= PNG_RUN) {
        unsigned char x[PNG_RUN] = { 0 }, b[PNG_RUN] = { 0 };
        memcpy(x, row, bpp);
        memcpy(b, prev, bpp);
        png_run_costs(x, zeros, b, zeros, sum);
        k = bpp;
    }
    for (; k + PNG_RUN <= len; k += PNG_RUN)
        png_run_costs(row + k, row + k - bpp, prev + k, prev + k - bpp, sum);
    for (; k < len; k++)
        for (int type = 0; type <= 4; type++)
            sum[type] += png_cost(row[k] - png_predict(type, row, prev, k, bpp));
    int best = 0;
    for (int type = 1; type <= 4; type++)
        if (sum[type] < sum[best])
            best = type;
    return best;
}

/* Builds the filtered image data: each row starts with its filter type,
 * chosen by the minimum sum of absolute differences.  Returns 0 or -1
 * (out of memory). */
static int png_filter_image(int width, int height, const unsigned char *rgb, KitBuf *raw)
{
    size_t len = 3 * (size_t)width, rows = (size_t)height;
    unsigned char *zero = calloc(len, 1);
    if (!zero || kit_buf_reserve(raw, rows * (len + 1)) != 0) {
        free(zero);
        return -1;
    }
    for (size_t j = 0; j < rows; j++) {
        const unsigned char *row = rgb + j * len;
        const unsigned char *prev = j > 0 ? row - len : zero;
        unsigned char *dst = raw->data + raw->len;
        int type = png_choose_filter(row, prev, len, 3);
        dst[0] = (unsigned char)type;
        png_filter_row(type, row, prev, len, 3, dst + 1);
        raw->len += len + 1;
    }
    free(zero);
    return 0;
}

/* Writes the signature, IHDR, the IDAT chunks and IEND.  Returns 0, or -1
 * with a reason in err. */
int png_encode(int width, int height, const unsigned char *rgb, KitBuf *out, char *err,
               size_t errlen)
{
    if (!rgb || width < 1 || height < 1 || width > PNG_MAX_SIDE || height > PNG_MAX_SIDE)
        return kit_fail(err, errlen,
                        "cannot encode an image of %d x %d pixels as PNG", width, height);
    size_t old_len = out->len;
    KitBuf raw = {0}, z = {0};
    unsigned char ihdr[13];
    kit_put_be32(ihdr, (uint32_t)width);
    kit_put_be32(ihdr + 4, (uint32_t)height);
    ihdr[8] = 8;            /* bit depth */
    ihdr[9] = 2;            /* colour type: RGB */
    ihdr[10] = 0;           /* compression: deflate */
    ihdr[11] = 0;           /* filter method: adaptive */
    ihdr[12] = 0;           /* not interlaced */
    int rc = png_filter_image(width, height, rgb, &raw) == 0 &&
             kit_zlib_compress(raw.data, raw.len, &z) == 0 &&
             kit_buf_append(out, png_signature, PNG_SIGNATURE_SIZE) == 0 &&
             png_put_chunk(out, "IHDR", ihdr, sizeof ihdr) == 0 ? 0 : -1;
    for (size_t at = 0; rc == 0 && at < z.len; at += PNG_IDAT_MAX) {
        size_t n = z.len - at < PNG_IDAT_MAX ? z.len - at : PNG_IDAT_MAX;
        rc = png_put_chunk(out, "IDAT", z.data + at, n);
    }
    if (rc == 0)
        rc = png_put_chunk(out, "IEND", NULL, 0);
    kit_buf_free(&raw);
    kit_buf_free(&z);
    if (rc != 0) {
        out->len = old_len;
        snprintf(err, errlen, "out of memory while encoding a PNG");
    }
    return rc;
}

/* ---- decoder -------------------------------------------------------------------- */

typedef struct {
    int width, height;
    int channels;           /* 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA */
} PngHeader;

/* Checks the 13 bytes of IHDR and fills h.  Returns 0, or -1 with a reason. */
static int png_read_ihdr(const unsigned char *d, size_t n, PngHeader *h, char *err, size_t errlen)
{
    if (n != 13)
        return kit_fail(err, errlen, "PNG IHDR chunk has length %zu, not 13", n);
    uint32_t w = kit_get_be32(d), ht = kit_get_be32(d + 4);
    unsigned depth = d[8], type = d[9];
    if (w < 1 || ht < 1 || w > PNG_MAX_SIDE || ht > PNG_MAX_SIDE)
        return kit_fail(err, errlen, "PNG image is %lu x %lu pixels: each side must be 1 to %d",
                        (unsigned long)w, (unsigned long)ht, PNG_MAX_SIDE);
    if (type != 0 && type != 2 && type != 4 && type != 6)
        return kit_fail(err, errlen, "PNG colour type %u is not supported (%s)", type,
                        type == 3 ? "palette images are not; save as RGB" : "invalid");
    if (depth != 8)
        return kit_fail(err, errlen,
                        "PNG bit depth %u is not supported (only 8 bits per channel)", depth);
    if (d[10] != 0 || d[11] != 0)
        return kit_fail(err, errlen, "PNG uses an unknown compression or filter method");
    if (d[12] == 1)
        return kit_fail(err, errlen,
                        "interlaced PNG images are not supported: save it without interlacing");
    if (d[12] != 0)
        return kit_fail(err, errlen, "PNG interlace method %u is invalid", (unsigned)d[12]);
    static const int channels[7] = {1, 0, 3, 0, 2, 0, 4};
    h->width = (int)w;
    h->height = (int)ht;
    h->channels = channels[type];
    return 0;
}

/* Whether the 4 bytes of a chunk type are all ASCII letters. */
static int png_valid_type(const unsigned char *t)
{
    for (int k = 0; k < 4; k++)
        if (!((t[k] >= 'A' && t[k] <= 'Z') || (t[k] >= 'a' && t[k] <= 'z')))
            return 0;
    return 1;
}

/* Walks the chunks after the signature, checking each CRC: reads IHDR into
 * h and gathers all IDAT data into idat, up to IEND.  Returns 0, or -1
 * with a reason. */
static int png_read_chunks(const unsigned char *p, size_t n, PngHeader *h, KitBuf *idat,
                           char *err, size_t errlen)
{
    size_t at = PNG_SIGNATURE_SIZE;
    int seen_ihdr = 0;
    for (;;) {
        if (n - at < 12)
            return kit_fail(err, errlen, "PNG data is truncated (no IEND chunk)");
        uint32_t len = kit_get_be32(p + at);
        const unsigned char *type = p + at + 4, *data = p + at + 8;
        if (len > PNG_CHUNK_MAX || !png_valid_type(type))
            return kit_fail(err, errlen, "PNG data is corrupt (bad chunk header at byte %zu)", at);
        if (len > n - at - 12)
            return kit_fail(err, errlen,
                            "PNG data is truncated (in a %.4s chunk)", (const char *)type);
        if (kit_crc32(0, type, 4 + (size_t)len) != kit_get_be32(data + len))
            return kit_fail(err, errlen, "PNG data is corrupt (CRC mismatch in a %.4s chunk)",
                            (const char *)type);
        at += 12 + (size_t)len;
        if (!seen_ihdr) {
            if (memcmp(type, "IHDR", 4) != 0)
                return kit_fail(err, errlen, "PNG data is corrupt (the first chunk is not IHDR)");
            if (png_read_ihdr(data, len, h, err, errlen) != 0)
                return -1;
            seen_ihdr = 1;
        } else if (memcmp(type, "IDAT", 4) == 0) {
            if (kit_buf_append(idat, data, len) != 0)
                return kit_fail(err, errlen, "out of memory while reading a PNG");
        } else if (memcmp(type, "IEND", 4) == 0) {
            return 0;
        } else if (memcmp(type, "IHDR", 4) == 0) {
            return kit_fail(err, errlen, "PNG data is corrupt (a second IHDR chunk)");
        } else if (!(type[0] & 0x20) && memcmp(type, "PLTE", 4) != 0) {
            return kit_fail(err, errlen, "PNG has a critical %.4s chunk this reader does not know",
                            (const char *)type);
        }
        /* other chunks (ancillary ones, and a suggested palette) are skipped */
    }
}

/* Undoes one row's filter in place: row (stride bytes) from its filtered
 * bytes, prev the unfiltered row above (zeros for the first).  One loop per
 * type, as png_predict defines them, the first pixel (no left neighbour)
 * apart. */
static void png_unfilter_row(int type, unsigned char *row, const unsigned char *prev,
                             size_t stride, size_t bpp)
{
    size_t first = bpp < stride ? bpp : stride;
    switch (type) {
    case 1:
        for (size_t k = bpp; k < stride; k++)
            row[k] = (unsigned char)(row[k] + row[k - bpp]);
        break;
    case 2:
        for (size_t k = 0; k < stride; k++)
            row[k] = (unsigned char)(row[k] + prev[k]);
        break;
    case 3:
        for (size_t k = 0; k < first; k++)
            row[k] = (unsigned char)(row[k] + prev[k] / 2);
        for (size_t k = bpp; k < stride; k++)
            row[k] = (unsigned char)(row[k] + (row[k - bpp] + prev[k]) / 2);
        break;
    case 4:
        for (size_t k = 0; k < first; k++)
            row[k] = (unsigned char)(row[k] + prev[k]);
        for (size_t k = bpp; k < stride; k++)
            row[k] = (unsigned char)(row[k] + png_paeth(row[k - bpp], prev[k], prev[k - bpp]));
        break;
    default:
        break;
    }
}

/* Undoes the filter of every row of raw in place (each row: a filter type
 * byte, then stride bytes).  Returns 0, or -1 with a reason. */
static int png_unfilter(unsigned char *raw, size_t rows, size_t stride, size_t bpp,
                        char *err, size_t errlen)
{
    unsigned char *zero = calloc(stride, 1);
    if (!zero)
        return kit_fail(err, errlen, "out of memory while reading a PNG");
    for (size_t j = 0; j < rows; j++) {
        unsigned char *line = raw + j * (stride + 1);
        unsigned char *row = line + 1;
        const unsigned char *prev = j > 0 ? row - (stride + 1) : zero;
        int type = line[0];
        if (type > 4) {
            free(zero);
            return kit_fail(err, errlen,
                            "PNG data is corrupt (filter type %d in row %zu)", type, j);
        }
        png_unfilter_row(type, row, prev, stride, bpp);
    }
    free(zero);
    return 0;
}

/* Signature, chunks, inflate, unfilter, then conversion to RGB.
 * Returns 0, or -1 with a reason. */
int png_decode(const void *data, size_t n, int *width, int *height, unsigned char **rgb,
               char *err, size_t errlen)
{
    const unsigned char *p = data;
    PngHeader h = {0, 0, 0};
    KitBuf idat = {0}, raw = {0};
    *width = *height = 0;
    *rgb = NULL;
    if (!png_has_signature(p, n))
        return kit_fail(err, errlen, "not a PNG file (bad signature)");
    if (png_read_chunks(p, n, &h, &idat, err, errlen) != 0) {
        kit_buf_free(&idat);
        return -1;
    }
    if (idat.len == 0) {
        kit_buf_free(&idat);
        return kit_fail(err, errlen, "PNG data has no IDAT chunk");
    }
    size_t stride = (size_t)h.width * (size_t)h.channels;
    size_t rows = (size_t)h.height, want = rows * (stride + 1);
    char why[200];
    /* The whole image's room at once, rather than doubling up to it. */
    int rc = kit_buf_reserve(&raw, want) == 0
                 ? kit_zlib_uncompress(idat.data, idat.len, want, &raw, why, sizeof why)
                 : (snprintf(why, sizeof why, "out of memory"), -1);
    kit_buf_free(&idat);
    if (rc != 0 || raw.len != want) {
        if (rc == 0)
            snprintf(why, sizeof why, "%zu bytes of image data, not %zu", raw.len, want);
        kit_buf_free(&raw);
        return kit_fail(err, errlen, "PNG image data is corrupt: %s", why);
    }
    if (png_unfilter(raw.data, rows, stride, (size_t)h.channels, err, errlen) != 0) {
        kit_buf_free(&raw);
        return -1;
    }
    if (h.channels == 3) {
        /* RGB already: the rows close up over their filter bytes, in place,
         * and the buffer becomes the image's. */
        for (size_t j = 0; j < rows; j++)
            memmove(raw.data + j * stride, raw.data + j * (stride + 1) + 1, stride);
        *width = h.width;
        *height = h.height;
        *rgb = raw.data;
        return 0;
    }
    unsigned char *out = malloc(3 * (size_t)h.width * rows);
    if (!out) {
        kit_buf_free(&raw);
        return kit_fail(err, errlen, "out of memory for a %d x %d image", h.width, h.height);
    }
    for (size_t j = 0; j < rows; j++) {
        const unsigned char *src = raw.data + j * (stride + 1) + 1;
        unsigned char *dst = out + j * 3 * (size_t)h.width;
        for (size_t i = 0; i < (size_t)h.width; i++, src += h.channels, dst += 3) {
            int grey = h.channels < 3;
            dst[0] = src[0];
            dst[1] = grey ? src[0] : src[1];
            dst[2] = grey ? src[0] : src[2];
        }
    }
    kit_buf_free(&raw);
    *width = h.width;
    *height = h.height;
    *rgb = out;
    return 0;
}
