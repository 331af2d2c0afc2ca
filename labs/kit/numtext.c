/*
 * numtext.c - see numtext.h.
 */
#include "numtext.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Whether x written with digits significant digits reads back as x (the
 * text is left in buf). */
static int reads_back(char *buf, size_t size, int digits, double x)
{
    snprintf(buf, size, "%.*g", digits, x);
    return strtod(buf, NULL) == x;
}

char *kit_shortest_double(char *buf, size_t size, double x)
{
    if (x == floor(x) && fabs(x) < 1e15) {
        snprintf(buf, size, "%.0f", x);
        return buf;
    }
    int exponent;
    double m = frexp(x, &exponent);
    if (!isfinite(x) || fabs(m) == 0.5) {
        /* NaN, the infinities, and powers of two, where the doubles just
         * below lie twice as close as those above: one digit more at a
         * time. */
        for (int digits = 1; digits <= 17; digits++)
            if (reads_back(buf, size, digits, x) || isnan(x))
                break;
        return buf;
    }
    /* Elsewhere the numbers that read back as x lie within the same
     * distance on either side of it.  Rounded to d + 1 digits, x moves no
     * farther than rounded to d (a d-digit number is a (d + 1)-digit one),
     * so if d digits read back, so do d + 1: the fewest that do are found
     * by halving [1, 17] (17 always do), in five tries instead of up to
     * seventeen. */
    int lo = 1, hi = 17;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (reads_back(buf, size, mid, x))
            hi = mid;
        else
            lo = mid + 1;
    }
    snprintf(buf, size, "%.*g", lo, x);
    return buf;
}
