/*
 * compare_main.c - the `compare` program: how far a render is from the
 * reference render.
 *
 *     compare SUBMISSION_IMAGE REFERENCE_IMAGE [-o SIDE_BY_SIDE.png]
 *
 * Prints how many pixels differ, the largest and the mean channel error and
 * the PSNR, and can write the two images side by side with a heat map of
 * their difference.  Exit status: 0 identical, 1 different, 2 error.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"

#define COMPARE_GAP  4           /* grey pixels between the panels   */
#define COMPARE_GREY 128         /* the gap's grey level             */

/* What differs between two images of the same size. */
typedef struct {
    long long pixels;            /* width * height                       */
    long long differing;         /* pixels with any channel different    */
    int max_error;               /* largest channel difference, 0..255   */
    double mean_error;           /* mean channel difference, 0..255      */
    double psnr;                 /* dB; INFINITY when identical          */
} CompareStats;

/* Prints the usage to f. */
static void compare_usage(FILE *f)
{
    fprintf(f,
            "usage: compare SUBMISSION_IMAGE REFERENCE_IMAGE [-o SIDE_BY_SIDE.png]\n"
            "  compares two images of the same size (PNG or binary PPM)\n"
            "  -o FILE   also write submission | reference | difference side by side;\n"
            "            in the difference black is equal, then dark blue, red, yellow\n"
            "            and white for ever larger differences\n"
            "exit status: 0 identical, 1 the images differ, 2 error or bad usage\n");
}

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

/* Measures the differences of a and b, which have the same size.
 * Never fails. */
static CompareStats compare_measure(const Image *a, const Image *b)
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
    st.mean_error = (double)sum / channels;
    if (sum_sq > 0)
        st.psnr = 10 * log10(255.0 * 255.0 / ((double)sum_sq / channels));
    return st;
}

/* The heat-map colour of a pixel whose largest channel difference is m
 * (0..255), stored in rgb: black for 0, then along dark blue, red, yellow
 * and white.  The square root spreads out the small differences (1 or 2,
 * the usual rounding) so that they still show. */
static void compare_heat(int m, unsigned char *rgb)
{
    static const double stops[4][3] = {
        { 0, 0, 110 },            /* the smallest difference: dark blue */
        { 210, 0, 0 },            /* red    */
        { 255, 220, 0 },          /* yellow */
        { 255, 255, 255 },        /* the largest: white */
    };
    if (m == 0) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return;
    }
    double t = 3 * sqrt((m - 1) / 254.0);     /* 0 .. 3 along the stops */
    int k = t >= 3 ? 2 : (int)t;
    double f = t - k;
    for (int c = 0; c < 3; c++)
        rgb[c] = (unsigned char)lround(stops[k][c] + f * (stops[k + 1][c] - stops[k][c]));
}

/* Copies src into dst with its top-left corner at column x0.
 * dst is at least as tall as src and wide enough.  Never fails. */
static void compare_paste(Image *dst, const Image *src, int x0)
{
    size_t row = (size_t)3 * (size_t)src->width;
    for (int j = 0; j < src->height; j++)
        memcpy(dst->rgb + 3 * ((size_t)j * (size_t)dst->width + (size_t)x0),
               src->rgb + row * (size_t)j, row);
}

/* Writes submission | reference | heat map, with grey gaps, to path.
 * Returns 0, or -1 with a message in err (too wide, out of memory, write). */
static int compare_write_side_by_side(const Image *sub, const Image *ref, const char *path,
                                      char *err, size_t errlen)
{
    int width = sub->width, height = sub->height;
    if (width > (IMAGE_MAX_SIDE - 2 * COMPARE_GAP) / 3) {
        snprintf(err, errlen, "%s: the images are too wide to put side by side (at most %d pixels)",
                 path, (IMAGE_MAX_SIDE - 2 * COMPARE_GAP) / 3);
        return -1;
    }
    Image out;
    if (image_alloc(&out, 3 * width + 2 * COMPARE_GAP, height, err, errlen) < 0)
        return -1;
    memset(out.rgb, COMPARE_GREY, (size_t)3 * (size_t)out.width * (size_t)height);
    compare_paste(&out, sub, 0);
    compare_paste(&out, ref, width + COMPARE_GAP);
    int x0 = 2 * (width + COMPARE_GAP);
    for (int j = 0; j < height; j++) {
        for (int i = 0; i < width; i++) {
            size_t k = (size_t)j * (size_t)width + (size_t)i;
            unsigned char *px = out.rgb + 3 * ((size_t)j * (size_t)out.width + (size_t)(x0 + i));
            compare_heat(compare_pixel_error(sub, ref, k), px);
        }
    }
    int status = image_write(&out, path, err, errlen);
    image_free(&out);
    return status;
}

/* Prints the measures of st for the two files. */
static void compare_report(const CompareStats *st, const char *sub, const char *ref,
                           int width, int height)
{
    printf("compared %s with %s (%dx%d)\n", sub, ref, width, height);
    printf("  pixels that differ:    %.3f%% (%lld of %lld)\n",
           100.0 * (double)st->differing / (double)st->pixels, st->differing, st->pixels);
    printf("  largest channel error: %d (of 255)\n", st->max_error);
    printf("  mean channel error:    %.4f (of 255)\n", st->mean_error);
    if (st->differing == 0)
        printf("  PSNR:                  infinite\nidentical\n");
    else
        printf("  PSNR:                  %.2f dB\nthe images differ\n", st->psnr);
}

/* Compares as the command line says.  Returns the exit status: 0 identical,
 * 1 different (or of different sizes), 2 error or bad usage. */
int main(int argc, char **argv)
{
    const char *paths[2] = { NULL, NULL }, *out_path = NULL;
    int npaths = 0;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            compare_usage(stdout);
            return 0;
        } else if (strcmp(a, "-o") == 0) {
            if (k + 1 == argc || argv[k + 1][0] == '\0') {
                fprintf(stderr, "compare: -o needs a file name\n");
                compare_usage(stderr);
                return 2;
            }
            out_path = argv[++k];
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "compare: unknown option '%.40s'\n", a);
            compare_usage(stderr);
            return 2;
        } else if (npaths == 2) {
            fprintf(stderr, "compare: more than two images given\n");
            compare_usage(stderr);
            return 2;
        } else {
            paths[npaths++] = a;
        }
    }
    if (npaths != 2) {
        fprintf(stderr, "compare: give two images, the submission's and the reference\n");
        compare_usage(stderr);
        return 2;
    }

    char err[512];
    Image sub, ref;
    if (image_read(&sub, paths[0], err, sizeof err) < 0) {
        fprintf(stderr, "compare: %s\n", err);
        return 2;
    }
    if (image_read(&ref, paths[1], err, sizeof err) < 0) {
        fprintf(stderr, "compare: %s\n", err);
        image_free(&sub);
        return 2;
    }
    int status;
    if (sub.width != ref.width || sub.height != ref.height) {
        fprintf(stderr, "compare: the images differ in size: %s is %dx%d, %s is %dx%d\n",
                paths[0], sub.width, sub.height, paths[1], ref.width, ref.height);
        status = 1;
    } else {
        CompareStats st = compare_measure(&sub, &ref);
        compare_report(&st, paths[0], paths[1], sub.width, sub.height);
        status = st.differing ? 1 : 0;
        if (out_path) {
            if (compare_write_side_by_side(&sub, &ref, out_path, err, sizeof err) < 0) {
                fprintf(stderr, "compare: %s\n", err);
                status = 2;
            } else {
                printf("wrote %s\n", out_path);
            }
        }
    }
    image_free(&sub);
    image_free(&ref);
    return status;
}
