/*
 * json.c - the streaming JSON writer.  See json.h.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */

#include "json.h"
#include "utf8.h"
#include "../../labs/kit/numtext.h"
#include "../../labs/kit/savefile.h"
#include "../../labs/kit/textfile.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Makes w fail with reason why (the first failure is kept).  Returns -1
 * for the caller to pass on. */
static int json_fail(JsonWriter *w, const char *why)
{
    if (!w->error)
        w->error = why;
    return -1;
}

/* Appends n bytes, failing the writer if memory runs out. */
static void json_put(JsonWriter *w, const void *s, size_t n)
{
    if (!w->error && kit_buf_append(&w->out, s, n) != 0)
        json_fail(w, "out of memory");
}

/* Appends a NUL-terminated string. */
static void json_puts(JsonWriter *w, const char *s)
{
    json_put(w, s, strlen(s));
}

/* A line break and the indentation of the current depth (nothing when
 * writing on one line). */
static void json_newline(JsonWriter *w)
{
    if (w->indent <= 0)
        return;
    json_put(w, "\n", 1);
    for (int k = 0; k < w->depth * w->indent; k++)
        json_put(w, " ", 1);
}

/* Starts an empty document. */
void json_init(JsonWriter *w, int indent)
{
    memset(w, 0, sizeof *w);
    kit_buf_init(&w->out);
    w->indent = indent < 0 ? 0 : indent > 8 ? 8 : indent;
}

/* Frees the text; w may be used again after json_init. */
void json_free(JsonWriter *w)
{
    kit_buf_free(&w->out);
}

/* Checks that a value may come now and writes the comma and line break
 * before it.  Returns 0, or -1 (the writer then fails) if it may not. */
static int json_before_value(JsonWriter *w)
{
    if (w->error)
        return -1;
    if (w->depth == 0) {
        return w->done ? json_fail(w, "a second top-level value") : 0;
    }
    int level = w->depth - 1;
    if (w->is_object[level]) {
        if (!w->key_pending)
            return json_fail(w, "a value in an object without a key");
        w->key_pending = false;
        return 0;
    }
    if (w->has_items[level])
        json_put(w, ",", 1);
    json_newline(w);
    return 0;
}

/* Notes that a value was completed at the current depth. */
static void json_after_value(JsonWriter *w)
{
    if (w->depth == 0)
        w->done = true;
    else
        w->has_items[w->depth - 1] = 1;
}

/* Opens an object (is_object) or array. */
static void json_begin(JsonWriter *w, bool is_object)
{
    if (json_before_value(w) != 0)
        return;
    if (w->depth >= JSON_MAX_DEPTH) {
        json_fail(w, "nested too deeply");
        return;
    }
    json_put(w, is_object ? "{" : "[", 1);
    w->is_object[w->depth] = is_object;
    w->has_items[w->depth] = 0;
    w->depth++;
}

/* Closes the innermost container, which must be an object (is_object) or
 * an array as said. */
static void json_end(JsonWriter *w, bool is_object)
{
    if (w->error)
        return;
    if (w->depth == 0 || w->is_object[w->depth - 1] != is_object || w->key_pending) {
        json_fail(w, is_object ? "an object end that matches no object"
                               : "an array end that matches no array");
        return;
    }
    bool items = w->has_items[w->depth - 1];
    w->depth--;
    if (items)
        json_newline(w);
    json_put(w, is_object ? "}" : "]", 1);
    json_after_value(w);
}

/* The four container calls of json.h; misuse makes the writer fail. */
void json_begin_object(JsonWriter *w) { json_begin(w, true); }
void json_end_object(JsonWriter *w) { json_end(w, true); }
void json_begin_array(JsonWriter *w) { json_begin(w, false); }
void json_end_array(JsonWriter *w) { json_end(w, false); }

/* Writes s[0 .. n-1] as a quoted, escaped string of valid UTF-8. */
static void json_put_string(JsonWriter *w, const unsigned char *s, size_t n)
{
    static const char hex[] = "0123456789abcdef";
    json_put(w, "\"", 1);
    for (size_t k = 0; k < n && !w->error;) {
        unsigned char c = s[k];
        int len = c >= 0x80 ? utf8_sequence(s + k, n - k) : 1;
        if (c == '"' || c == '\\') {
            char esc[2] = {'\\', (char)c};
            json_put(w, esc, 2);
        } else if (c < 0x20) {
            char esc[6] = {'\\', 'u', '0', '0', hex[c >> 4], hex[c & 15]};
            json_put(w, esc, 6);
        } else if (len > 0) {
            json_put(w, s + k, (size_t)len);
        } else {
            json_put(w, "\xEF\xBF\xBD", 3);     /* U+FFFD */
        }
        k += (size_t)(len > 0 ? len : -len);
    }
    json_put(w, "\"", 1);
}

/* Writes the key and the colon; the next call must write its value. */
void json_key(JsonWriter *w, const char *key)
{
    if (w->error)
        return;
    if (w->depth == 0 || !w->is_object[w->depth - 1] || w->key_pending) {
        json_fail(w, "a key outside an object or after another key");
        return;
    }
    if (!key) {
        json_fail(w, "a NULL key");
        return;
    }
    if (w->has_items[w->depth - 1])
        json_put(w, ",", 1);
    json_newline(w);
    json_put_string(w, (const unsigned char *)key, strlen(key));
    json_puts(w, w->indent > 0 ? ": " : ":");
    w->key_pending = true;
}

/* n bytes as a string; fails the writer if no value may come here. */
void json_string_bytes(JsonWriter *w, const void *s, size_t n)
{
    if (json_before_value(w) != 0)
        return;
    json_put_string(w, s ? s : (const void *)"", s ? n : 0);
    json_after_value(w);
}

/* A NUL-terminated string, or null for NULL. */
void json_string(JsonWriter *w, const char *s)
{
    if (!s)
        json_null(w);
    else
        json_string_bytes(w, s, strlen(s));
}

/* The shortest %.Ng (N = 1 .. 17) that reads back as x (17 digits always
 * do); null for NaN and infinities.  Fails the writer if misplaced. */
void json_number(JsonWriter *w, double x)
{
    if (!isfinite(x)) {
        json_null(w);
        return;
    }
    if (json_before_value(w) != 0)
        return;
    char text[40];
    json_puts(w, kit_shortest_double(text, sizeof text, x));
    json_after_value(w);
}

/* An integer, exactly.  Fails the writer if misplaced. */
void json_int(JsonWriter *w, long long x)
{
    if (json_before_value(w) != 0)
        return;
    char text[32];
    snprintf(text, sizeof text, "%lld", x);
    json_puts(w, text);
    json_after_value(w);
}

/* true or false.  Fails the writer if misplaced. */
void json_bool(JsonWriter *w, bool b)
{
    if (json_before_value(w) != 0)
        return;
    json_puts(w, b ? "true" : "false");
    json_after_value(w);
}

/* null.  Fails the writer if misplaced. */
void json_null(JsonWriter *w)
{
    if (json_before_value(w) != 0)
        return;
    json_puts(w, "null");
    json_after_value(w);
}

void json_member_string(JsonWriter *w, const char *key, const char *s)
{
    json_key(w, key);
    json_string(w, s);
}

void json_member_number(JsonWriter *w, const char *key, double x)
{
    json_key(w, key);
    json_number(w, x);
}

void json_member_int(JsonWriter *w, const char *key, long long x)
{
    json_key(w, key);
    json_int(w, x);
}

/* Why the writer failed, or NULL. */
const char *json_error(const JsonWriter *w)
{
    return w->error;
}

/* The text, NUL-terminated, once complete.  Returns NULL on failure or
 * while the top-level value is unfinished. */
const char *json_text(JsonWriter *w, size_t *len)
{
    if (w->error || !w->done)
        return NULL;
    if (kit_buf_reserve(&w->out, 1) != 0) {
        json_fail(w, "out of memory");
        return NULL;
    }
    w->out.data[w->out.len] = '\0';
    if (len)
        *len = w->out.len;
    return (const char *)w->out.data;
}

/* The text and a newline into a temporary file beside path (created by
 * mkstemp, then given the mode a new file would get), closed, then renamed
 * over path; w freed.  Returns 0, or -1 with "path: reason" in err. */
int json_write_file(JsonWriter *w, const char *path, char *err, size_t errlen)
{
    size_t len;
    const char *text = json_text(w, &len);
    char *copy = text ? malloc(len + 1) : NULL;
    int status = -1;
    if (copy) {
        memcpy(copy, text, len);
        copy[len] = '\n';
        status = kit_save_file(path, copy, len + 1, err, errlen);
    } else if (text) {
        snprintf(err, errlen, "%s: out of memory", path);
    } else {
        snprintf(err, errlen, "%s: cannot write JSON: %s", path,
                 w->error ? w->error : "the document is not finished");
    }
    free(copy);
    json_free(w);
    return status;
}
