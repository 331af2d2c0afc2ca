/*
 * textfile.c - see textfile.h.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "textfile.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int text_error(char *err, size_t errlen, const char *name, int line, const char *fmt, ...)
{
    if (!err || errlen == 0)
        return -1;
    int used = line > 0 ? snprintf(err, errlen, "%s:%d: ", name, line)
                        : snprintf(err, errlen, "%s: ", name);
    if (used < 0 || (size_t)used >= errlen)
        return -1;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + used, errlen - (size_t)used, fmt, ap);
    va_end(ap);
    return -1;
}

int kit_fail(char *err, size_t errlen, const char *fmt, ...)
{
    if (err && errlen > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

const char *text_quote(const char *word, char *buf)
{
    size_t n = 0;
    for (; word[n] && n < TEXT_QUOTE_SIZE - 4; n++)
        buf[n] = word[n] > ' ' && word[n] < 127 ? word[n] : '?';
    strcpy(buf + n, word[n] ? "..." : "");
    return buf;
}

/* True for the characters that separate words (a '\r' of a CRLF file too). */
static int text_is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

int text_split(char *buf, char **words)
{
    char *hash = strchr(buf, '#');
    if (hash)
        *hash = '\0';
    int n = 0;
    char *p = buf;
    for (;;) {
        while (*p && text_is_space(*p))
            p++;
        if (!*p)
            return n;
        if (n < TEXT_MAX_WORDS)
            words[n] = p;
        n++;
        while (*p && !text_is_space(*p))
            p++;
        if (*p)
            *p++ = '\0';
    }
}

int text_number(const TextLine *ln, int k, double *value, char *err, size_t errlen)
{
    const char *word = ln->words[k];
    char quoted[TEXT_QUOTE_SIZE], *end;
    errno = 0;
    double v = strtod(word, &end);
    if (end == word || *end != '\0')
        return text_error(err, errlen, ln->name, ln->line, "%s: '%s' is not a number",
                          ln->words[0], text_quote(word, quoted));
    if (isnan(v))
        return text_error(err, errlen, ln->name, ln->line,
                          "%s: '%s' is not a number (NaN is refused)",
                          ln->words[0], text_quote(word, quoted));
    if (isinf(v))
        return text_error(err, errlen, ln->name, ln->line,
                          "%s: '%s' is %s (numbers must be finite)",
                          ln->words[0], text_quote(word, quoted),
                          errno == ERANGE ? "out of range" : "infinite");
    *value = v;
    return 0;
}

/* Reads the whole of f into a fresh NUL-terminated buffer stored in *text.
 * Returns 0, or -1 with a message (read error, file too large, NUL byte,
 * out of memory); *text is then NULL. */
static int text_read_all(FILE *f, const char *path, char **text, char *err, size_t errlen)
{
    size_t size = 0, capacity = 4096;
    char *buf = malloc(capacity);
    *text = NULL;
    if (!buf)
        return text_error(err, errlen, path, 0, "out of memory");
    for (;;) {
        if (size + 1 == capacity) {
            if (capacity >= (size_t)TEXT_MAX_BYTES) {
                free(buf);
                return text_error(err, errlen, path, 0,
                                  "larger than %ld MiB: too large for this kit",
                                  TEXT_MAX_BYTES / (1024 * 1024));
            }
            char *more = realloc(buf, 2 * capacity);
            if (!more) {
                free(buf);
                return text_error(err, errlen, path, 0, "out of memory");
            }
            buf = more;
            capacity *= 2;
        }
        size_t got = fread(buf + size, 1, capacity - 1 - size, f);
        size += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        text_error(err, errlen, path, 0, "%s", strerror(errno ? errno : EIO));
        free(buf);
        return -1;
    }
    buf[size] = '\0';
    const char *nul = memchr(buf, '\0', size);
    if (nul) {
        int line = 1;
        for (const char *q = buf; q < nul; q++)
            line += *q == '\n';
        free(buf);
        return text_error(err, errlen, path, line, "contains a NUL byte: not a text file");
    }
    *text = buf;
    return 0;
}

int text_read_file(const char *path, char **text, char *err, size_t errlen)
{
    *text = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return text_error(err, errlen, path, 0, "%s", strerror(errno));
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        text_error(err, errlen, path, 0, "%s", strerror(EISDIR));
        fclose(f);
        return -1;
    }
    errno = 0;
    int status = text_read_all(f, path, text, err, errlen);
    fclose(f);
    return status;
}

size_t text_bom_length(const char *s, size_t n)
{
    return n >= 3 && memcmp(s, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
}

int text_next_line(const char **pos, char *buf, TextLine *ln, char *err, size_t errlen)
{
    const char *p = *pos;
    if (!*p)
        return 0;
    ln->line++;
    if (ln->line == 1)
        p += text_bom_length(p, strnlen(p, 3));   /* not text */
    size_t len = strcspn(p, "\n");
    if (len > TEXT_MAX_LINE)
        return text_error(err, errlen, ln->name, ln->line,
                          "line is longer than %d characters", TEXT_MAX_LINE);
    memcpy(buf, p, len);
    buf[len] = '\0';
    p += len;
    if (*p == '\n')
        p++;
    *pos = p;
    ln->nwords = text_split(buf, ln->words);
    return 1;
}
