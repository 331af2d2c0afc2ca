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
    if (formula || strpbrk(s, ",\"\n\r")) {
        fputc('"', f);
        if (formula)
            fputc('\'', f);
        for (; *s; s++) {
            if (*s == '"')
                fputc('"', f);
            fputc(*s, f);
        }
        fputc('"', f);
    } else {
        fputs(s, f);
    }
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
    while (*s && *s != ',' && *s != '\n' && *s != '\r')
        out[n++] = *s++;
    out[n] = '\0';
    *end = *s != ',';
    if (*s == ',')
        s++;
    *p = s;
    return out;
}
