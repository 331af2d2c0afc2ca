/*
 * hexfloat.h - a double as printf's "%a" writes it (C11 7.21.6.1, as the
 * GNU C library spells it: "0x1.8p+1", "-0x0p+0", "0x0.0000000000001p-1022"
 * for the smallest subnormal, "inf", "-nan"), without printf: the test
 * protocol between the grader and its runner writes one for every number
 * that crosses, and printf's parsing of its format is most of their cost.
 * strtod reads the text back to the same double, bit for bit.  Header only:
 * the runner links no library of the kit.
 */
#ifndef HEXFLOAT_H
#define HEXFLOAT_H

#include <stdint.h>
#include <string.h>

#define HEXFLOAT_MAX 32   /* room for the longest text, "-0x1.fffffffffffffp+1023"
                             (24 characters), and its NUL */

/* Writes x into out (at least HEXFLOAT_MAX bytes) with a NUL after it;
 * returns the length. */
static inline size_t hexfloat_format(char *out, double x)
{
    static const char digits[] = "0123456789abcdef";
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    size_t n = 0;
    if (bits >> 63)
        out[n++] = '-';
    int e = (int)((bits >> 52) & 0x7ff);
    uint64_t m = bits & ((UINT64_C(1) << 52) - 1);
    if (e == 0x7ff) {
        memcpy(out + n, m ? "nan" : "inf", 4);
        return n + 3;
    }
    out[n++] = '0';
    out[n++] = 'x';
    out[n++] = e ? '1' : '0';
    if (m) {
        out[n++] = '.';
        int last = 13;                  /* the 13 hex digits, trailing zeros dropped */
        while (((m >> (4 * (13 - last))) & 15) == 0)
            last--;
        for (int k = 1; k <= last; k++)
            out[n++] = digits[(m >> (4 * (13 - k))) & 15];
    }
    int p = e ? e - 1023 : (m ? -1022 : 0);
    out[n++] = 'p';
    out[n++] = p < 0 ? '-' : '+';
    unsigned a = (unsigned)(p < 0 ? -p : p);
    char rev[5];
    int r = 0;
    do {
        rev[r++] = (char)('0' + a % 10);
        a /= 10;
    } while (a);
    while (r)
        out[n++] = rev[--r];
    out[n] = '\0';
    return n;
}

#endif
