/*
 * json_read.h - a small JSON reader (RFC 8259) into a tree, for the kit's
 * tests: they read back what the grader wrote for GitHub Classroom and
 * PrairieLearn and check its fields.
 *
 *     JsonValue v;
 *     if (json_parse(text, len, &v, err, sizeof err) != 0) ...
 *     const JsonValue *score = json_member(&v, "score");
 *     if (score && score->type == JSON_NUMBER) ... score->number ...
 *     json_value_free(&v);
 *
 * The whole text must be one value, with white space around it only.
 * Strings must be valid UTF-8 and their escapes are decoded (\u escapes,
 * surrogate pairs included, into UTF-8; a lone surrogate is refused).
 * Numbers follow the grammar exactly (no leading zeros, no "+", no "."
 * without digits) and are read with strtod in the C locale.  Duplicate
 * names in an object are refused, so a member has one value.
 */
#ifndef TOOLS_JSON_READ_H
#define TOOLS_JSON_READ_H

#include <stdbool.h>
#include <stddef.h>

typedef enum { JSON_NULL, JSON_BOOL, JSON_NUMBER, JSON_STRING, JSON_ARRAY, JSON_OBJECT } JsonType;

typedef struct JsonValue {
    JsonType type;
    bool boolean;              /* JSON_BOOL                                   */
    double number;             /* JSON_NUMBER                                 */
    char *string;              /* JSON_STRING: decoded, NUL-terminated        */
    size_t length;             /* its length in bytes (it may hold NUL)       */
    int n;                     /* JSON_ARRAY, JSON_OBJECT: items or members   */
    struct JsonValue *items;   /* the items, or the members' values           */
    char **names;              /* JSON_OBJECT: the members' names             */
} JsonValue;

/* Parses text[0 .. n-1]; 0, or -1 with "offset N: reason" in err (then v
 * holds nothing to free). */
int json_parse(const char *text, size_t n, JsonValue *v, char *err, size_t errlen);
void json_value_free(JsonValue *v);

/* The value of member name of an object, or NULL (not an object, or no
 * such member). */
const JsonValue *json_member(const JsonValue *object, const char *name);

/* The name of a type, for messages: "null", "boolean", ... */
const char *json_type_name(JsonType type);

#endif
