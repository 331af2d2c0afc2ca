/*
 * base64.c - base64 encoding.  See base64.h.
 */
#include "base64.h"

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
