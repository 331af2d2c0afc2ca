/*
 * shortest.h - a double as the grader shows it to students: in the fewest
 * significant digits that read back as the same double, as Python's repr
 * and JavaScript print numbers.  0.48 reads "0.48", where %.17g writes
 * "0.47999999999999998"; a value that needs 17 digits gets them, so two
 * doubles that differ never print alike.  Header only, as decimal.h.
 */
#ifndef SHORTEST_H
#define SHORTEST_H

#include <stdio.h>
#include <stdlib.h>

enum { SHORTEST_LEN = 32 };

/* v into buf, returned.  %.15g, %.16g, %.17g, the first that reads back as
 * v: for a normal double no shorter text does (%g drops trailing zeros,
 * and 15 digits are fewer than a double holds, so %.15g gives any number
 * of 15 digits or fewer that reads back as v).  NaN prints as %g does. */
static inline const char *shortest(double v, char buf[SHORTEST_LEN])
{
    for (int p = 15; p <= 17; p++) {
        snprintf(buf, SHORTEST_LEN, "%.*g", p, v);
        if (strtod(buf, NULL) == v)
            break;
    }
    return buf;
}

#endif
