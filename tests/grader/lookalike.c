/*
 * lookalike.c - characters that look like C's but are not (lookalike.h).
 */
#include "lookalike.h"
#include "kit/textfile.h"
#include "../tools/utf8.h"

#include <stdbool.h>
#include <stdio.h>
#include <string.h>

/* The code points copied code brings most, each with what to type. */
static const struct {
    unsigned long cp;
    const char *name, *instead;
} known[] = {
    { 0x00A0, "a non-breaking space", "an ordinary space" },
    { 0x2002, "an en space", "an ordinary space" },
    { 0x2003, "an em space", "an ordinary space" },
    { 0x2009, "a thin space", "an ordinary space" },
    { 0x202F, "a narrow non-breaking space", "an ordinary space" },
    { 0x200B, "a zero-width space", "nothing (delete it)" },
    { 0xFEFF, "a zero-width no-break space (a byte order mark inside the file)", "nothing (delete it)" },
    { 0x201C, "a curly opening double quote", "a straight \"" },
    { 0x201D, "a curly closing double quote", "a straight \"" },
    { 0x2018, "a curly opening single quote", "a straight '" },
    { 0x2019, "a curly closing single quote", "a straight '" },
    { 0x2212, "a minus sign", "a hyphen-minus -" },
    { 0x2013, "an en dash", "a hyphen-minus -" },
    { 0x2014, "an em dash", "a hyphen-minus -" },
    { 0x00D7, "a multiplication sign", "*" },
    { 0x2217, "an asterisk operator", "*" },
    { 0x00F7, "a division sign", "/" },
    { 0x2264, "a less-than-or-equal sign", "<=" },
    { 0x2265, "a greater-than-or-equal sign", ">=" },
    { 0x2260, "a not-equal sign", "!=" },
};

/* A character found: its line, which of known[] it is, how many times on
 * that line. */
typedef struct {
    int line, which, times;
} Found;

/* Writes the findings into out, at most three lines, then how many more. */
static void write_found(const Found *f, int nfound, int more, const char *file, char *out, size_t outlen)
{
    size_t at = 0;
    for (int k = 0; k < nfound && k < 3 && at < outlen; k++) {
        char times[32] = "";
        if (f[k].times > 1)
            snprintf(times, sizeof times, ", %d times", f[k].times);
        int w = snprintf(out + at, outlen - at, "%s:%d: %s (U+%04lX)%s: type %s\n", file, f[k].line,
                         known[f[k].which].name, known[f[k].which].cp, times, known[f[k].which].instead);
        at += w > 0 ? (size_t)w : 0;
    }
    int left = more;
    for (int k = 3; k < nfound; k++)
        left += f[k].times;
    if (left > 0 && at < outlen)
        snprintf(out + at, outlen - at, "(and %d more such characters)\n", left);
}

int lookalike_explain(const char *text, size_t len, const char *file, char *out, size_t outlen)
{
    const unsigned char *s = (const unsigned char *)text;
    enum { CODE, LINE_COMMENT, BLOCK_COMMENT, STRING, CHAR } state = CODE;
    enum { MAX_FOUND = 8 };
    Found f[MAX_FOUND];
    int nfound = 0, more = 0, total = 0, line = 1;
    if (outlen)
        out[0] = '\0';
    /* From after a byte-order mark, which the compiler skips. */
    for (size_t i = text_bom_length(text, len); i < len; i++) {
        unsigned char c = s[i];
        if (c == '\n')
            line++;
        switch (state) {
        case LINE_COMMENT:
            if (c == '\n' && !(i > 0 && s[i - 1] == '\\'))
                state = CODE;
            continue;
        case BLOCK_COMMENT:
            if (c == '*' && i + 1 < len && s[i + 1] == '/')
                state = CODE, i++;
            continue;
        case STRING:
        case CHAR:
            if (c == '\\' && i + 1 < len) {
                line += s[i + 1] == '\n';
                i++;
            } else if (c == (state == STRING ? '"' : '\'') || c == '\n') {
                state = CODE;
            }
            continue;
        case CODE:
            break;
        }
        if (c == '/' && i + 1 < len && s[i + 1] == '/') {
            state = LINE_COMMENT, i++;
        } else if (c == '/' && i + 1 < len && s[i + 1] == '*') {
            state = BLOCK_COMMENT, i++;
        } else if (c == '"') {
            state = STRING;
        } else if (c == '\'') {
            state = CHAR;
        } else if (c >= 0x80) {
            int used = utf8_sequence(s + i, len - i);
            unsigned long cp = used > 0 ? utf8_code_point(s + i, used) : 0;
            for (int k = 0; cp && k < (int)(sizeof known / sizeof known[0]); k++) {
                if (known[k].cp != cp)
                    continue;
                total++;
                bool seen = false;             /* the same character on the same line */
                for (int j = 0; j < nfound && !seen; j++)
                    if (f[j].line == line && f[j].which == k)
                        seen = ++f[j].times > 0;
                if (!seen && nfound < MAX_FOUND)
                    f[nfound++] = (Found){ line, k, 1 };
                else if (!seen)
                    more++;
            }
            i += (size_t)(used > 0 ? used : -used) - 1;
        }
    }
    write_found(f, nfound, more, file, out, outlen);
    return total;
}

bool lookalike_utf16(const char *text, size_t n)
{
    const unsigned char *u = (const unsigned char *)text;
    if (n >= 2 && ((u[0] == 0xff && u[1] == 0xfe) || (u[0] == 0xfe && u[1] == 0xff)))
        return true;
    size_t zeros[2] = { 0, 0 }, m = n < 512 ? n : 512;
    for (size_t k = 0; k < m; k++)
        zeros[k % 2] += u[k] == 0;
    return m >= 16 && (zeros[0] == m / 2 || zeros[1] == m / 2);
}
