/*
 * numtext.c - see numtext.h.
 */
#include "numtext.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

char *kit_shortest_double(char *buf, size_t size, double x)
{
    if (x == floor(x) && fabs(x) < 1e15) {
        snprintf(buf, size, "%.0f", x);
        return buf;
    }
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(buf, size, "%.*g", digits, x);
        if (strtod(buf, NULL) == x || isnan(x))
            break;
    }
    return buf;
}
