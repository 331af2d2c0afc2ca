/*
 * linkmsg.c - see linkmsg.h.
 */
#include "linkmsg.h"

#include <stdbool.h>
#include <string.h>

/* Adds the n bytes at name to names unless there already, or too long. */
static void add(char names[][LINKMSG_NAME_MAX], int *count, int max, const char *name, size_t n)
{
    if (*count >= max || n == 0 || n >= LINKMSG_NAME_MAX)
        return;
    for (int k = 0; k < *count; k++)
        if (strncmp(names[k], name, n) == 0 && names[k][n] == '\0')
            return;
    memcpy(names[*count], name, n);
    names[(*count)++][n] = '\0';
}

/* The identifier at p: its length (0 when none). */
static size_t identifier(const char *p)
{
    size_t n = 0;
    while ((p[n] >= 'a' && p[n] <= 'z') || (p[n] >= 'A' && p[n] <= 'Z') ||
           (p[n] >= '0' && p[n] <= '9') || p[n] == '_')
        n++;
    return n;
}

int linkmsg_undefined(const char *text, char names[][LINKMSG_NAME_MAX], int max)
{
    int count = 0;
    for (const char *line = text; line && *line && count < max;) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        const char *at;
        char copy[512];
        size_t n = len < sizeof copy - 1 ? len : sizeof copy - 1;
        memcpy(copy, line, n);
        copy[n] = '\0';
        if ((at = strstr(copy, "undefined reference to ")) &&               /* GNU ld, gold */
            (at[strlen("undefined reference to ")] == '`' || at[strlen("undefined reference to ")] == '\'')) {
            at += strlen("undefined reference to ") + 1;
            const char *q = strchr(at, '\'');
            if (q && identifier(at) == (size_t)(q - at))
                add(names, &count, max, at, (size_t)(q - at));
        } else if ((at = strstr(copy, "undefined symbol: "))) {            /* lld */
            at += strlen("undefined symbol: ");
            add(names, &count, max, at, identifier(at));
        } else if ((at = strstr(copy, "\", referenced from"))) {           /* Apple's ld */
            const char *q = at;
            while (q > copy && q[-1] != '"')
                q--;
            if (q > copy && *q == '_' && identifier(q) == (size_t)(at - q))
                add(names, &count, max, q + 1, (size_t)(at - q - 1));
        }
        line = end ? end + 1 : NULL;
    }
    return count;
}
