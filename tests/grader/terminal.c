/*
 * terminal.c - text the student chose, shown safely (terminal.h).
 */
#include "terminal.h"
#include "../tools/utf8.h"

#include <stdbool.h>
#include <string.h>

/* How the character at s[0 .. n-1] is shown: its text in out (NUL-
 * terminated, at most 4 bytes); returns the bytes of s it takes. */
static size_t shown_as(const unsigned char *s, size_t n, char out[5])
{
    unsigned char c = s[0];
    if (c == 0x7F || (c < 0x20 && c != '\n' && c != '\t')) {
        out[0] = '^';
        out[1] = c == 0x7F ? '?' : (char)(c + 64);
        out[2] = '\0';
        return 1;
    }
    if (c < 0x80) {
        out[0] = (char)c;
        out[1] = '\0';
        return 1;
    }
    int u = utf8_sequence(s, n);
    bool c1 = u == 2 && c == 0xC2 && s[1] < 0xA0;
    if (u > 0 && !c1) {
        memcpy(out, s, (size_t)u);
        out[u] = '\0';
        return (size_t)u;
    }
    out[0] = '?';
    out[1] = '\0';
    return (size_t)(u > 0 ? u : -u);
}

void term_put(FILE *f, const char *text, size_t n)
{
    const unsigned char *s = (const unsigned char *)text;
    char out[5];
    for (size_t k = 0; k < n;) {
        k += shown_as(s + k, n - k, out);
        fputs(out, f);
    }
}

void term_append(char *buf, size_t size, const char *text)
{
    const unsigned char *s = (const unsigned char *)text;
    size_t used = strlen(buf), n = strlen(text);
    char out[5];
    for (size_t k = 0; k < n;) {
        k += shown_as(s + k, n - k, out);
        size_t m = strlen(out);
        if (used + m >= size)
            break;
        memcpy(buf + used, out, m + 1);
        used += m;
    }
}
