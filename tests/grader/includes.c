/*
 * includes.c - see includes.h.
 *
 * The scan follows the first phases of translation (C11 5.1.1.2) far
 * enough to find directives as the compiler does: trigraphs (gcc's
 * -std=c11 honours them), backslash-newline splices, comments, and the
 * digraph %: for #.  It does not expand macros.
 */
#include "includes.h"

#include <stdlib.h>
#include <string.h>

/* Phases 1-2: trigraphs replaced and lines spliced, into a new buffer. */
static char *splice(const char *src, size_t len, size_t *outlen)
{
    static const char from[] = "=(/)'<!>-", to[] = "#[\\]^{|}~";
    char *out = malloc(len + 1);
    if (!out)
        return NULL;
    size_t n = 0;
    for (size_t k = 0; k < len; k++) {
        char c = src[k];
        if (c == '?' && k + 2 < len && src[k + 1] == '?') {
            const char *p = memchr(from, src[k + 2], sizeof from - 1);
            if (p) {
                c = to[p - from];
                k += 2;
            }
        }
        out[n++] = c;
        /* A backslash before a newline (a \r\n too) joins the lines. */
        if (c == '\\' && n > 0) {
            size_t j = k + 1;
            if (j < len && src[j] == '\r')
                j++;
            if (j < len && src[j] == '\n') {
                n--;
                k = j;
            }
        }
    }
    out[n] = '\0';
    *outlen = n;
    return out;
}

/* Phase 3, as far as it matters here: comments become one space, string
 * and character literals are kept whole. */
static void strip_comments(char *s, size_t len)
{
    size_t r = 0, w = 0;
    while (r < len) {
        if (s[r] == '/' && r + 1 < len && s[r + 1] == '*') {
            size_t e = r + 2;
            while (e + 1 < len && !(s[e] == '*' && s[e + 1] == '/'))
                e++;
            for (size_t k = r; k < e + 2 && k < len; k++)   /* keep the newlines */
                if (s[k] == '\n')
                    s[w++] = '\n';
            s[w++] = ' ';
            r = e + 2 < len ? e + 2 : len;
        } else if (s[r] == '/' && r + 1 < len && s[r + 1] == '/') {
            while (r < len && s[r] != '\n')
                r++;
            s[w++] = ' ';
        } else if (s[r] == '"' || s[r] == '\'') {
            char q = s[r];
            s[w++] = s[r++];
            while (r < len && s[r] != q && s[r] != '\n') {
                if (s[r] == '\\' && r + 1 < len)
                    s[w++] = s[r++];
                s[w++] = s[r++];
            }
            if (r < len && s[r] == q)
                s[w++] = s[r++];
        } else {
            s[w++] = s[r++];
        }
    }
    s[w] = '\0';
}

static const char *skip_blanks(const char *p)
{
    while (*p == ' ' || *p == '\t' || *p == '\f' || *p == '\v' || *p == '\r')
        p++;
    return p;
}

int includes_scan(const char *src, size_t len, IncludeVisit visit, void *ctx)
{
    size_t n;
    char *s = splice(src, len, &n);
    if (!s)
        return -1;
    strip_comments(s, n);
    int found = 0;
    for (char *line = s; line && *line; ) {
        char *next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        const char *p = skip_blanks(line);
        if (*p == '#')
            p++;
        else if (p[0] == '%' && p[1] == ':')
            p += 2;
        else
            p = NULL;
        if (p) {
            p = skip_blanks(p);
            if (strncmp(p, "include", 7) == 0) {
                p = skip_blanks(p + 7);
                char close = *p == '"' ? '"' : *p == '<' ? '>' : 0;
                const char *end = close ? strchr(p + 1, close) : NULL;
                if (end) {
                    char path[4096];
                    size_t k = (size_t)(end - p - 1);
                    if (k < sizeof path) {
                        memcpy(path, p + 1, k);
                        path[k] = '\0';
                        found++;
                        if (visit(path, close == '>', ctx) != 0)
                            break;
                    }
                }
            }
        }
        line = next;
    }
    free(s);
    return found;
}
