/*
 * csv.c - see csv.h.
 */
#include "csv.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

static bool formula_start(char c)
{
    return c && strchr("=+-@\t\r", c) != NULL;
}

void csv_field(FILE *f, const char *s)
{
    bool formula = formula_start(s[0]);
    bool quoted = formula || strpbrk(s, ",\"");
    if (quoted)
        fputs(formula ? "\"'" : "\"", f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c < 0x20 || c == 0x7f || c == '\\')
            fprintf(f, "\\x%02x", c);
        else if (c == '"')
            fputs("\"\"", f);
        else
            fputc(c, f);
    }
    if (quoted)
        fputc('"', f);
}

/* The byte of the escape \xHH at s (csv_field's), or -1 when s is none. */
static int escaped_byte(const char *s)
{
    static const char hex[] = "0123456789abcdef";
    const char *hi = s[0] == '\\' && s[1] == 'x' && s[2] ? strchr(hex, s[2]) : NULL;
    const char *lo = hi && s[3] ? strchr(hex, s[3]) : NULL;
    return lo ? (int)((hi - hex) * 16 + (lo - hex)) : -1;
}

char *csv_read_field(const char **p, int *end)
{
    const char *s = *p;
    char *out = malloc(strlen(s) + 1);
    size_t n = 0;
    if (!out)
        return NULL;
    if (*s == '"') {
        for (s++; *s; s++) {
            int byte = escaped_byte(s);
            if (byte >= 0) {
                out[n++] = (char)byte;
                s += 3;
                continue;
            }
            if (*s == '"' && s[1] == '"')
                s++;
            else if (*s == '"') {
                s++;
                break;
            }
            out[n++] = *s;
        }
        /* A quoted field that starts with an apostrophe before a formula's
         * first character is csv_field's guard: the name is the rest. */
        if (n >= 2 && out[0] == '\'' && formula_start(out[1])) {
            memmove(out, out + 1, n - 1);
            n--;
        }
    }
    while (*s && *s != ',' && *s != '\n' && *s != '\r') {
        int byte = escaped_byte(s);
        out[n++] = byte >= 0 ? (char)byte : *s;
        s += byte >= 0 ? 4 : 1;
    }
    out[n] = '\0';
    *end = *s != ',';
    if (*s == ',')
        s++;
    *p = s;
    return out;
}
