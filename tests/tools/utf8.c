/*
 * utf8.c - reading UTF-8 (utf8.h).
 */
#include "utf8.h"

int utf8_sequence(const unsigned char *s, size_t n)
{
    unsigned char c = s[0];
    int need;
    unsigned char lo = 0x80, hi = 0xBF;     /* the range of the second byte */
    if (c >= 0xC2 && c <= 0xDF) {
        need = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
        need = 3;
        if (c == 0xE0)
            lo = 0xA0;                      /* no overlong forms */
        if (c == 0xED)
            hi = 0x9F;                      /* no surrogates */
    } else if (c >= 0xF0 && c <= 0xF4) {
        need = 4;
        if (c == 0xF0)
            lo = 0x90;                      /* no overlong forms */
        if (c == 0xF4)
            hi = 0x8F;                      /* nothing past U+10FFFF */
    } else {
        return -1;                          /* 0x80..0xC1, 0xF5..0xFF */
    }
    for (int k = 1; k < need; k++) {
        if ((size_t)k >= n || s[k] < lo || s[k] > hi)
            return -k;
        lo = 0x80;
        hi = 0xBF;
    }
    return need;
}

unsigned long utf8_code_point(const unsigned char *s, int len)
{
    static const unsigned char lead_bits[5] = { 0, 0, 0x1F, 0x0F, 0x07 };
    unsigned long cp = s[0] & lead_bits[len];
    for (int k = 1; k < len; k++)
        cp = cp << 6 | (s[k] & 0x3F);
    return cp;
}
