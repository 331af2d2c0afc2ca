/*
 * compare.h - how far one image is from another, and the pictures that show
 * it: the heat map of their difference, and the two images beside it.
 *
 * `make compare` (compare_main.c) and the grader's report page draw the
 * same heat map with these functions.
 */
#ifndef KIT_COMPARE_H
#define KIT_COMPARE_H

#include <stddef.h>
#include "image.h"

#define COMPARE_GAP  4           /* grey pixels between side-by-side panels */
#define COMPARE_GREY 128         /* the gap's grey level                    */

/* What differs between two images of the same size. */
typedef struct {
    long long pixels;            /* width * height                       */
    long long differing;         /* pixels with any channel different    */
    int max_error;               /* largest channel difference, 0..255   */
    double mean_error;           /* mean channel difference, 0..255      */
    double psnr;                 /* dB; INFINITY when identical          */
} CompareStats;

/* Measures the differences of a and b, which must have the same size.
 * Never fails. */
CompareStats compare_measure(const Image *a, const Image *b);

/* The heat-map colour of a pixel whose largest channel difference is m
 * (0..255), stored in rgb[0..2]: black for 0, then along dark blue, red,
 * yellow and white for ever larger differences.  Never fails. */
void compare_heat(int m, unsigned char *rgb);

/* Allocates heat (a->width x a->height) and draws the heat map of a and b,
 * which must have the same size.  Returns 0, or -1 with a reason in err
 * (out of memory). */
int compare_heat_map(const Image *a, const Image *b, Image *heat, char *err, size_t errlen);

/* The band above the side-by-side panels that holds their labels: its
 * height for panels width pixels wide (a 5 x 7 font, twice as large from
 * COMPARE_LABEL_BIG pixels on). */
#define COMPARE_LABEL_BIG 400
int compare_label_band(int width);

/* Allocates out and draws a | b | heat map of their difference, with grey
 * gaps of COMPARE_GAP pixels, under a grey band (compare_label_band) that
 * labels them "YOUR RENDER", "REFERENCE" and "DIFFERENCE" (a label wider
 * than its panel is left out).  Returns 0, or -1 with a reason in err (the
 * images are too wide to put side by side, or memory ran out). */
int compare_side_by_side(const Image *a, const Image *b, Image *out, char *err, size_t errlen);

#endif
