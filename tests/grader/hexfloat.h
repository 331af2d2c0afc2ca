/*
 * hexfloat.h - a double as printf's "%a" writes it (C11 7.21.6.1, as the
 * GNU C library spells it: "0x1.8p+1", "-0x0p+0", "0x0.0000000000001p-1022"
 * for the smallest subnormal, "inf", "-nan"), without printf: the test
 * protocol between the grader and its runner writes one for every number
 * that crosses, and printf's parsing of its format is most of their cost.
 * strtod reads the text back to the same double, bit for bit, and so does
 * hexfloat_read, some ten times faster (the runner reads every test's
 * numbers, and the grader every answer).  Header only: the runner links
 * no library of the kit.
 */
#ifndef HEXFLOAT_H
#define HEXFLOAT_H

#include <stdint.h>
#include <stdlib.h>
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

/* The digit's value, or -1: the lower-case hex digits hexfloat_format writes. */
static inline int hexfloat_digit(char c)
{
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

/* strtod(s, end), bit for bit and with the same *end, for any text: the
 * text hexfloat_format writes (after blanks and tabs) is read here, and
 * any other is left to strtod. */
static inline double hexfloat_read(const char *s, char **end)
{
    const char *p = s;
    while (*p == ' ' || *p == '\t')
        p++;
    uint64_t sign = 0;
    if (*p == '-') {
        sign = UINT64_C(1) << 63;
        p++;
    }
    uint64_t bits = 0;
    if (p[0] == 'i' && p[1] == 'n' && p[2] == 'f' && p[3] != 'i' && p[3] != 'I') {
        bits = UINT64_C(0x7ff0000000000000);
        p += 3;
    } else if (p[0] == 'n' && p[1] == 'a' && p[2] == 'n' && p[3] != '(') {
        bits = UINT64_C(0x7ff8000000000000);
        p += 3;
    } else if (p[0] == '0' && p[1] == 'x' && (p[2] == '0' || p[2] == '1')) {
        int lead = p[2] - '0', ndigits = 0;
        uint64_t m = 0;
        p += 3;
        if (*p == '.') {
            p++;
            for (int d; ndigits < 14 && (d = hexfloat_digit(*p)) >= 0; p++, ndigits++)
                m = m << 4 | (uint64_t)d;
            if (ndigits == 0 || ndigits > 13)
                return strtod(s, end);
            m <<= 4 * (13 - ndigits);
        }
        if (p[0] != 'p' || (p[1] != '+' && p[1] != '-') || p[2] < '0' || p[2] > '9')
            return strtod(s, end);
        int negative = p[1] == '-';
        int e = 0, edigits = 0;
        for (p += 2; *p >= '0' && *p <= '9' && edigits < 5; p++, edigits++)
            e = 10 * e + (*p - '0');
        if (edigits == 5)
            return strtod(s, end);
        if (negative)
            e = -e;
        if (lead == 1 && e >= -1022 && e <= 1023)
            bits = (uint64_t)(e + 1023) << 52 | m;
        else if (lead == 0 && ((m == 0 && e == 0) || (m != 0 && e == -1022)))
            bits = m;                   /* zero, or a subnormal */
        else
            return strtod(s, end);
    } else {
        return strtod(s, end);
    }
    if (end)
        *end = (char *)p;
    bits |= sign;
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

#endif
