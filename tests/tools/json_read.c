/*
 * json_read.c - the JSON reader.  See json_read.h.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "json_read.h"
#include "utf8.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define READ_MAX_DEPTH 64

typedef struct {
    const unsigned char *p;
    size_t n, at;
    int depth;
    char *err;
    size_t errlen;
} Reader;

static int read_value(Reader *r, JsonValue *v);

/* Records why reading stopped (the first reason is kept); returns -1. */
static int refuse(Reader *r, const char *why)
{
    if (r->err && r->errlen && !r->err[0])
        snprintf(r->err, r->errlen, "offset %zu: %s", r->at, why);
    return -1;
}

static void skip_space(Reader *r)
{
    while (r->at < r->n && (r->p[r->at] == ' ' || r->p[r->at] == '\t' || r->p[r->at] == '\n' ||
                            r->p[r->at] == '\r'))
        r->at++;
}

/* Consumes the literal word if it comes next; 1 if it did. */
static int take_word(Reader *r, const char *word)
{
    size_t len = strlen(word);
    if (r->n - r->at >= len && memcmp(r->p + r->at, word, len) == 0) {
        r->at += len;
        return 1;
    }
    return 0;
}

/* Appends code point cp as UTF-8 to buf (which has room for 4 more). */
static size_t put_utf8(unsigned char *buf, size_t at, uint32_t cp)
{
    if (cp < 0x80) {
        buf[at++] = (unsigned char)cp;
    } else if (cp < 0x800) {
        buf[at++] = (unsigned char)(0xC0 | cp >> 6);
        buf[at++] = (unsigned char)(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        buf[at++] = (unsigned char)(0xE0 | cp >> 12);
        buf[at++] = (unsigned char)(0x80 | ((cp >> 6) & 0x3F));
        buf[at++] = (unsigned char)(0x80 | (cp & 0x3F));
    } else {
        buf[at++] = (unsigned char)(0xF0 | cp >> 18);
        buf[at++] = (unsigned char)(0x80 | ((cp >> 12) & 0x3F));
        buf[at++] = (unsigned char)(0x80 | ((cp >> 6) & 0x3F));
        buf[at++] = (unsigned char)(0x80 | (cp & 0x3F));
    }
    return at;
}

/* Four hex digits of a \u escape; -1 if they are not. */
static long hex4(Reader *r)
{
    if (r->n - r->at < 4)
        return -1;
    long v = 0;
    for (int k = 0; k < 4; k++) {
        unsigned char c = r->p[r->at + (size_t)k];
        int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10
              : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
        if (d < 0)
            return -1;
        v = v * 16 + d;
    }
    r->at += 4;
    return v;
}

/* A string (the opening quote next) into a malloc'd, NUL-terminated buffer:
 * escapes decoded, raw bytes checked to be UTF-8 with no control
 * characters. */
static int read_string(Reader *r, char **out, size_t *outlen)
{
    r->at++;                                    /* the opening quote */
    /* The decoded text is never longer than the encoded one. */
    size_t start = r->at;
    while (r->at < r->n && r->p[r->at] != '"')
        r->at += r->p[r->at] == '\\' && r->at + 1 < r->n ? 2 : 1;
    if (r->at >= r->n)
        return refuse(r, "a string without its closing quote");
    size_t end = r->at;
    r->at = start;
    unsigned char *buf = malloc(end - start + 1);
    if (!buf)
        return refuse(r, "out of memory");
    size_t len = 0;
    while (r->at < end) {
        unsigned char c = r->p[r->at];
        if (c < 0x20) {
            free(buf);
            return refuse(r, "a control character in a string (it must be escaped)");
        }
        if (c >= 0x80) {
            int k = utf8_sequence(r->p + r->at, end - r->at);
            if (k < 0) {
                free(buf);
                return refuse(r, "a string that is not valid UTF-8");
            }
            memcpy(buf + len, r->p + r->at, (size_t)k);
            len += (size_t)k;
            r->at += (size_t)k;
            continue;
        }
        if (c != '\\') {
            buf[len++] = c;
            r->at++;
            continue;
        }
        r->at++;
        c = r->p[r->at++];
        const char *simple = strchr("\"\\/bfnrt", c);
        if (c && simple) {
            static const char decoded[] = "\"\\/\b\f\n\r\t";
            buf[len++] = (unsigned char)decoded[simple - "\"\\/bfnrt"];
            continue;
        }
        if (c != 'u') {
            free(buf);
            return refuse(r, "an unknown escape in a string");
        }
        long cp = hex4(r);
        if (cp < 0) {
            free(buf);
            return refuse(r, "a \\u escape without four hex digits");
        }
        if (cp >= 0xDC00 && cp <= 0xDFFF) {
            free(buf);
            return refuse(r, "a low surrogate without its high one");
        }
        if (cp >= 0xD800 && cp <= 0xDBFF) {
            long lowpart = -1;
            if (r->at + 1 < end && r->p[r->at] == '\\' && r->p[r->at + 1] == 'u') {
                r->at += 2;
                lowpart = hex4(r);
            }
            if (lowpart < 0xDC00 || lowpart > 0xDFFF) {
                free(buf);
                return refuse(r, "a high surrogate without its low one");
            }
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lowpart - 0xDC00);
        }
        len = put_utf8(buf, len, (uint32_t)cp);
    }
    r->at = end + 1;                            /* the closing quote */
    buf[len] = '\0';
    *out = (char *)buf;
    *outlen = len;
    return 0;
}

/* A number by the grammar: -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)? */
static int read_number(Reader *r, double *x)
{
    size_t start = r->at;
    const unsigned char *p = r->p;
#define DIGIT(k) ((k) < r->n && p[k] >= '0' && p[k] <= '9')
    if (r->at < r->n && p[r->at] == '-')
        r->at++;
    if (r->at < r->n && p[r->at] == '0') {
        r->at++;
    } else if (DIGIT(r->at)) {
        while (DIGIT(r->at))
            r->at++;
    } else {
        return refuse(r, "a number without digits");
    }
    if (r->at < r->n && p[r->at] == '.') {
        r->at++;
        if (!DIGIT(r->at))
            return refuse(r, "a number with no digit after its point");
        while (DIGIT(r->at))
            r->at++;
    }
    if (r->at < r->n && (p[r->at] == 'e' || p[r->at] == 'E')) {
        r->at++;
        if (r->at < r->n && (p[r->at] == '+' || p[r->at] == '-'))
            r->at++;
        if (!DIGIT(r->at))
            return refuse(r, "a number with no digit in its exponent");
        while (DIGIT(r->at))
            r->at++;
    }
#undef DIGIT
    char text[400];
    size_t len = r->at - start;
    if (len >= sizeof text)
        return refuse(r, "a number too long to read");
    memcpy(text, p + start, len);
    text[len] = '\0';
    *x = strtod(text, NULL);
    return 0;
}

/* An array or object (its opening bracket next); items or members are
 * gathered into growing arrays. */
static int read_container(Reader *r, JsonValue *v, bool object)
{
    if (++r->depth > READ_MAX_DEPTH)
        return refuse(r, "nested too deeply");
    r->at++;
    v->type = object ? JSON_OBJECT : JSON_ARRAY;
    int cap = 0;
    skip_space(r);
    if (r->at < r->n && r->p[r->at] == (object ? '}' : ']')) {
        r->at++;
        r->depth--;
        return 0;
    }
    for (;;) {
        if (v->n == cap) {
            cap = cap ? 2 * cap : 8;
            JsonValue *items = realloc(v->items, (size_t)cap * sizeof *items);
            if (!items)
                return refuse(r, "out of memory");
            v->items = items;
            if (object) {
                char **names = realloc(v->names, (size_t)cap * sizeof *names);
                if (!names)
                    return refuse(r, "out of memory");
                v->names = names;
            }
        }
        JsonValue *item = &v->items[v->n];
        memset(item, 0, sizeof *item);
        if (object) {
            skip_space(r);
            if (r->at >= r->n || r->p[r->at] != '"')
                return refuse(r, "an object member without a name");
            char *name;
            size_t namelen;
            if (read_string(r, &name, &namelen) != 0)
                return -1;
            if (strlen(name) != namelen || json_member(v, name)) {
                free(name);
                return refuse(r, "a member name that repeats another or holds NUL");
            }
            v->names[v->n] = name;
            skip_space(r);
            if (r->at >= r->n || r->p[r->at] != ':') {
                v->n++;                         /* its name is freed with v */
                return refuse(r, "a member name without a colon");
            }
            r->at++;
        }
        v->n++;
        if (read_value(r, item) != 0)
            return -1;
        skip_space(r);
        if (r->at < r->n && r->p[r->at] == ',') {
            r->at++;
            continue;
        }
        if (r->at < r->n && r->p[r->at] == (object ? '}' : ']')) {
            r->at++;
            r->depth--;
            return 0;
        }
        return refuse(r, object ? "an object member followed by neither , nor }"
                                : "an array item followed by neither , nor ]");
    }
}

/* Any value, white space before it allowed. */
static int read_value(Reader *r, JsonValue *v)
{
    skip_space(r);
    if (r->at >= r->n)
        return refuse(r, "the text ends where a value is due");
    unsigned char c = r->p[r->at];
    if (c == '{' || c == '[')
        return read_container(r, v, c == '{');
    if (c == '"') {
        v->type = JSON_STRING;
        return read_string(r, &v->string, &v->length);
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
        v->type = JSON_NUMBER;
        return read_number(r, &v->number);
    }
    if (take_word(r, "true") || take_word(r, "false")) {
        v->type = JSON_BOOL;
        v->boolean = c == 't';
        return 0;
    }
    if (take_word(r, "null")) {
        v->type = JSON_NULL;
        return 0;
    }
    return refuse(r, "not a JSON value");
}

int json_parse(const char *text, size_t n, JsonValue *v, char *err, size_t errlen)
{
    Reader r = { .p = (const unsigned char *)text, .n = n, .err = err, .errlen = errlen };
    if (err && errlen)
        err[0] = '\0';
    memset(v, 0, sizeof *v);
    int status = read_value(&r, v);
    if (status == 0) {
        skip_space(&r);
        if (r.at != r.n)
            status = refuse(&r, "more text after the value");
    }
    if (status != 0)
        json_value_free(v);
    return status;
}

void json_value_free(JsonValue *v)
{
    for (int k = 0; k < v->n; k++) {
        if (v->items)
            json_value_free(&v->items[k]);
        if (v->names)
            free(v->names[k]);
    }
    free(v->items);
    free(v->names);
    free(v->string);
    memset(v, 0, sizeof *v);
}

const JsonValue *json_member(const JsonValue *object, const char *name)
{
    if (!object || object->type != JSON_OBJECT)
        return NULL;
    for (int k = 0; k < object->n; k++)
        if (object->names && object->names[k] && strcmp(object->names[k], name) == 0)
            return &object->items[k];
    return NULL;
}

const char *json_type_name(JsonType type)
{
    static const char *names[] = { "null", "boolean", "number", "string", "array", "object" };
    return (unsigned)type < 6 ? names[type] : "?";
}
