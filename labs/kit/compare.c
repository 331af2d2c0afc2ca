/*
 * compare.c - see compare.h.
 */
#include "compare.h"
#include "textfile.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The largest of the three channel differences of pixel k of a and b. */
static int compare_pixel_error(const Image *a, const Image *b, size_t k)
{
    int worst = 0;
    for (int c = 0; c < 3; c++) {
        int diff = abs(a->rgb[3 * k + c] - b->rgb[3 * k + c]);
        if (diff > worst)
            worst = diff;
    }
    return worst;
}

CompareStats compare_measure(const Image *a, const Image *b)
{
    CompareStats st = { 0, 0, 0, 0, INFINITY };
    size_t n = (size_t)a->width * (size_t)a->height;
    uint64_t sum = 0, sum_sq = 0;
    st.pixels = (long long)n;
    for (size_t k = 0; k < n; k++) {
        int differs = 0;
        for (int c = 0; c < 3; c++) {
            int diff = abs(a->rgb[3 * k + c] - b->rgb[3 * k + c]);
            sum += (uint64_t)diff;
            sum_sq += (uint64_t)(diff * diff);
            if (diff > st.max_error)
                st.max_error = diff;
            differs |= diff;
        }
        st.differing += differs != 0;
    }
    double channels = 3.0 * (double)n;
    st.mean_error = n ? (double)sum / channels : 0;
    if (sum_sq > 0)
        st.psnr = 10 * log10(255.0 * 255.0 / ((double)sum_sq / channels));
    return st;
}

/* The square root spreads out the small differences (1 or 2, the usual
 * rounding) so that they still show. */
void compare_heat(int m, unsigned char *rgb)
{
    static const double stops[4][3] = {
        { 0, 0, 110 },            /* the smallest difference: dark blue */
        { 210, 0, 0 },            /* red    */
        { 255, 220, 0 },          /* yellow */
        { 255, 255, 255 },        /* the largest: white */
    };
    if (m <= 0) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return;
    }
    if (m > 255)
        m = 255;
    double t = 3 * sqrt((m - 1) / 254.0);     /* 0 .. 3 along the stops */
    int k = t >= 3 ? 2 : (int)t;
    double f = t - k;
    for (int c = 0; c < 3; c++)
        rgb[c] = (unsigned char)lround(stops[k][c] + f * (stops[k + 1][c] - stops[k][c]));
}

int compare_heat_map(const Image *a, const Image *b, Image *heat, char *err, size_t errlen)
{
    if (image_alloc(heat, a->width, a->height, err, errlen) < 0)
        return -1;
    size_t n = (size_t)a->width * (size_t)a->height;
    for (size_t k = 0; k < n; k++)
        compare_heat(compare_pixel_error(a, b, k), heat->rgb + 3 * k);
    return 0;
}

/* Copies src into dst with its top-left corner at column x0, row y0.
 * dst is large enough.  Never fails. */
static void compare_paste(Image *dst, const Image *src, int x0, int y0)
{
    size_t row = (size_t)3 * (size_t)src->width;
    for (int j = 0; j < src->height; j++)
        memcpy(dst->rgb + 3 * ((size_t)(y0 + j) * (size_t)dst->width + (size_t)x0),
               src->rgb + row * (size_t)j, row);
}

/* A 5 x 7 font for the panels' labels: each glyph's rows, top first, its
 * five columns in the low bits (the leftmost in bit 4). */
static const struct {
    char c;
    unsigned char rows[7];
} compare_font[] = {
    { 'C', { 0x0e, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0e } },
    { 'D', { 0x1e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1e } },
    { 'E', { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f } },
    { 'F', { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x10 } },
    { 'I', { 0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e } },
    { 'N', { 0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0x11 } },
    { 'O', { 0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e } },
    { 'R', { 0x1e, 0x11, 0x11, 0x1e, 0x14, 0x12, 0x11 } },
    { 'U', { 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e } },
    { 'Y', { 0x11, 0x11, 0x0a, 0x04, 0x04, 0x04, 0x04 } },
};

static int compare_label_scale(int width)
{
    return width >= COMPARE_LABEL_BIG ? 2 : 1;
}

int compare_label_band(int width)
{
    return 11 * compare_label_scale(width);         /* the glyphs' 7 rows and a margin */
}

/* Writes text in white, centred over the panel of width pixels whose left
 * edge is column x0, in the band at the top of img; nothing when it is
 * wider than the panel.  Characters the font lacks are spaces. */
static void compare_label(Image *img, int x0, int width, const char *text)
{
    int scale = compare_label_scale(width), n = (int)strlen(text);
    int text_width = (6 * n - 1) * scale;
    if (text_width > width)
        return;
    int left = x0 + (width - text_width) / 2, top = 2 * scale;
    for (int k = 0; k < n; k++) {
        const unsigned char *rows = NULL;
        for (size_t g = 0; g < sizeof compare_font / sizeof compare_font[0]; g++)
            if (compare_font[g].c == text[k])
                rows = compare_font[g].rows;
        for (int r = 0; rows && r < 7 * scale; r++)
            for (int c = 0; c < 5 * scale; c++)
                if (rows[r / scale] & (0x10 >> (c / scale)))
                    memset(img->rgb + 3 * ((size_t)(top + r) * (size_t)img->width +
                                           (size_t)(left + 6 * scale * k + c)), 255, 3);
    }
}

int compare_side_by_side(const Image *a, const Image *b, Image *out, char *err, size_t errlen)
{
    int width = a->width, height = a->height;
    if (width > (IMAGE_MAX_SIDE - 2 * COMPARE_GAP) / 3)
        return kit_fail(err, errlen,
                        "the images are too wide to put side by side (at most %d pixels)",
                        (IMAGE_MAX_SIDE - 2 * COMPARE_GAP) / 3);
    Image heat;
    if (compare_heat_map(a, b, &heat, err, errlen) < 0)
        return -1;
    int band = compare_label_band(width);
    if (height > IMAGE_MAX_SIDE - band) {
        image_free(&heat);
        return kit_fail(err, errlen,
                        "the images are too tall to label (at most %d pixels)",
                        IMAGE_MAX_SIDE - band);
    }
    if (image_alloc(out, 3 * width + 2 * COMPARE_GAP, height + band, err, errlen) < 0) {
        image_free(&heat);
        return -1;
    }
    memset(out->rgb, COMPARE_GREY, (size_t)3 * (size_t)out->width * (size_t)out->height);
    static const char *const labels[3] = { "YOUR RENDER", "REFERENCE", "DIFFERENCE" };
    const Image *panels[3] = { a, b, &heat };
    for (int k = 0; k < 3; k++) {
        compare_paste(out, panels[k], k * (width + COMPARE_GAP), band);
        compare_label(out, k * (width + COMPARE_GAP), width, labels[k]);
    }
    image_free(&heat);
    return 0;
}
