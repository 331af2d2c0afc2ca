/*
 * decimal.h - strtod for the test files' decimal numbers, faster.
 *
 * The test files (tests/public, written with "%.17g") hold some 30,000
 * numbers for Parts 1 to 3b, and the grader reads them at every grading.
 * Most are short ("0", "-1", "0.53"): at most 2^53 once the point is
 * taken out, and a power of ten no larger than 10^22 from their value.
 * Both of those are doubles exactly, so one multiplication or division,
 * rounded once, gives the correctly rounded value, as strtod does
 * (Clinger's fast path: W. D. Clinger, "How to read floating point numbers
 * accurately", PLDI 1990).  Every other text, the 17-digit numbers among
 * them, is left to strtod.  Header only, as hexfloat.h.
 */
#ifndef DECIMAL_H
#define DECIMAL_H

#include <float.h>
#include <stdint.h>
#include <stdlib.h>

/* strtod(s, end), bit for bit and with the same *end, for any text. */
static inline double decimal_read(const char *s, char **end)
{
    static const double tens[23] = { 1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                     1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
#if FLT_EVAL_METHOD != 0
    return strtod(s, end);              /* wider arithmetic would round twice */
#endif
    const char *p = s;
    while (*p == ' ' || *p == '\t')
        p++;
    int negative = *p == '-';
    if (*p == '-' || *p == '+')
        p++;
    uint64_t m = 0;                     /* the digits, the point taken out */
    int digits = 0, scale = 0, seen = 0;    /* value = m 10^scale */
    for (; *p >= '0' && *p <= '9'; p++) {
        seen = 1;
        if (m || *p != '0') {
            if (++digits > 17)
                return strtod(s, end);
            m = 10 * m + (uint64_t)(*p - '0');
        }
    }
    if (*p == '.')
        for (p++; *p >= '0' && *p <= '9'; p++) {
            seen = 1;
            if (m || *p != '0') {
                if (++digits > 17)
                    return strtod(s, end);
                m = 10 * m + (uint64_t)(*p - '0');
            }
            scale--;
        }
    if (!seen || *p == 'x' || *p == 'X')
        return strtod(s, end);          /* no digits (inf, nan), or hex */
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        int eneg = *q == '-';
        if (*q == '-' || *q == '+')
            q++;
        if (*q < '0' || *q > '9')
            return strtod(s, end);      /* "1e": strtod stops before the e */
        int e = 0, edigits = 0;
        for (; *q >= '0' && *q <= '9'; q++)
            if (++edigits > 4)
                return strtod(s, end);
            else
                e = 10 * e + (*q - '0');
        scale += eneg ? -e : e;
        p = q;
    }
    double x;
    if (m == 0)
        x = 0;
    else if (m > (UINT64_C(1) << 53) || scale < -22 || scale > 22)
        return strtod(s, end);
    else if (scale >= 0)
        x = (double)m * tens[scale];
    else
        x = (double)m / tens[-scale];
    if (end)
        *end = (char *)p;
    return negative ? -x : x;
}

#endif
