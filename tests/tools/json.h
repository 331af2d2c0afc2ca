/*
 * json.h - a small streaming JSON writer (RFC 8259) into a growable buffer.
 *
 *     JsonWriter w;
 *     json_init(&w, 2);                      indent by 2 (0: all on one line)
 *     json_begin_object(&w);
 *     json_key(&w, "score");  json_number(&w, 7.5);
 *     json_key(&w, "tests");  json_begin_array(&w); ... json_end_array(&w);
 *     json_end_object(&w);
 *     if (json_write_file(&w, "results.json", err, sizeof err) != 0) ...
 *
 * The writer places the commas and colons itself.  Strings may hold any
 * bytes (such as the output of untrusted programs): quotes, backslashes and
 * control characters are escaped, and every invalid UTF-8 sequence becomes
 * U+FFFD, so the text is always valid JSON in valid UTF-8.  Numbers are
 * written in the shortest form that reads back as the same double (the
 * C locale's decimal point is assumed); NaN and infinities become null.
 *
 * Misuse (a value where a key is due, an end that does not match, more than
 * JSON_MAX_DEPTH levels, a second top-level value) or running out of memory
 * makes the writer fail: later calls do nothing, json_error says why, and
 * json_text and json_write_file refuse.
 */
#ifndef TOOLS_JSON_H
#define TOOLS_JSON_H

#include <stdbool.h>
#include <stddef.h>
#include "../../labs/kit/zlib.h"

#define JSON_MAX_DEPTH 64

typedef struct {
    KitBuf out;
    int indent;                                 /* spaces per level; 0 = one line */
    int depth;                                  /* open objects and arrays        */
    unsigned char is_object[JSON_MAX_DEPTH];    /* per level: object or array     */
    unsigned char has_items[JSON_MAX_DEPTH];    /* per level: a comma is due      */
    bool key_pending;                           /* a key waits for its value      */
    bool done;                                  /* the top-level value is written */
    const char *error;                          /* NULL, or why the writer failed */
} JsonWriter;

/* Starts an empty document; indent is the number of spaces per level of
 * nesting (0 writes everything on one line). */
void json_init(JsonWriter *w, int indent);
void json_free(JsonWriter *w);

void json_begin_object(JsonWriter *w);
void json_end_object(JsonWriter *w);
void json_begin_array(JsonWriter *w);
void json_end_array(JsonWriter *w);

/* The name of the next member of the current object (a NUL-terminated string). */
void json_key(JsonWriter *w, const char *key);

/* A NUL-terminated string (NULL writes null). */
void json_string(JsonWriter *w, const char *s);
/* n arbitrary bytes as a string (NUL bytes included, as \u0000). */
void json_string_bytes(JsonWriter *w, const void *s, size_t n);
/* A double; NaN and infinities are written as null. */
void json_number(JsonWriter *w, double x);
void json_int(JsonWriter *w, long long x);
void json_bool(JsonWriter *w, bool b);
void json_null(JsonWriter *w);
/* A member of the current object: its key, then its value. */
void json_member_string(JsonWriter *w, const char *key, const char *s);
void json_member_number(JsonWriter *w, const char *key, double x);
void json_member_int(JsonWriter *w, const char *key, long long x);

/* NULL while all is well, else a short description of the failure. */
const char *json_error(const JsonWriter *w);

/* The finished document (NUL-terminated, without a final newline) and its
 * length in *len (if len is not NULL).  Returns NULL if the writer failed
 * or the top-level value is not complete. */
const char *json_text(JsonWriter *w, size_t *len);

/* Writes the finished document and a newline to path, through a temporary
 * file in the same directory renamed over path, and frees w.  Returns 0, or
 * -1 with "path: reason" in err (and no temporary file left behind). */
int json_write_file(JsonWriter *w, const char *path, char *err, size_t errlen);

#endif
