/*
 * base64.c - base64 encoding and strict decoding.  See base64.h.
 */
#include "base64.h"

#include <stdio.h>
#include <stdlib.h>

static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/* Four characters for every three bytes, the last group padded. */
size_t base64_encoded_length(size_t n)
{
    return (n + 2) / 3 * 4;
}

/* Three bytes at a time into four characters of six bits each; a last
 * group of one or two bytes is padded with "=". */
size_t base64_encode(const void *data, size_t n, char *out)
{
    const unsigned char *s = data;
    size_t at = 0;
    for (size_t k = 0; k < n; k += 3) {
        unsigned long group = (unsigned long)s[k] << 16;
        if (k + 1 < n)
            group |= (unsigned long)s[k + 1] << 8;
        if (k + 2 < n)
            group |= s[k + 2];
        out[at++] = alphabet[(group >> 18) & 63];
        out[at++] = alphabet[(group >> 12) & 63];
        out[at++] = k + 1 < n ? alphabet[(group >> 6) & 63] : '=';
        out[at++] = k + 2 < n ? alphabet[group & 63] : '=';
    }
    out[at] = '\0';
    return at;
}

/* The six-bit value of an alphabet character, or -1. */
static int sextet(char c)
{
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    if (c == '+')
        return 62;
    if (c == '/')
        return 63;
    return -1;
}

/* Four characters at a time back into up to three bytes; anything that is
 * not canonical base64 is refused with the offset of the first bad
 * character. */
unsigned char *base64_decode(const char *text, size_t n, size_t *len, char *err, size_t errlen)
{
    if (n % 4 != 0) {
        snprintf(err, errlen, "base64: %zu characters, not a multiple of 4", n);
        return NULL;
    }
    unsigned char *out = malloc(n / 4 * 3 + 1);
    if (!out) {
        snprintf(err, errlen, "base64: out of memory");
        return NULL;
    }
    size_t at = 0;
    for (size_t k = 0; k < n; k += 4) {
        int last = k + 4 == n;
        int pad = last && text[k + 3] == '=' ? (text[k + 2] == '=' ? 2 : 1) : 0;
        unsigned long group = 0;
        for (int j = 0; j < 4; j++) {
            int v = j >= 4 - pad ? 0 : sextet(text[k + (size_t)j]);
            if (v < 0) {
                snprintf(err, errlen, "base64: character %zu is not of the alphabet", k + (size_t)j);
                free(out);
                return NULL;
            }
            group = group << 6 | (unsigned long)v;
        }
        /* The bits the padding leaves over must be zero (canonical form). */
        if ((pad == 1 && (group & 0xFF)) || (pad == 2 && (group & 0xFFFF))) {
            snprintf(err, errlen, "base64: bits set past the data at character %zu", k);
            free(out);
            return NULL;
        }
        out[at++] = (unsigned char)(group >> 16);
        if (pad < 2)
            out[at++] = (unsigned char)(group >> 8);
        if (pad < 1)
            out[at++] = (unsigned char)group;
    }
    out[at] = '\0';
    *len = at;
    return out;
}
