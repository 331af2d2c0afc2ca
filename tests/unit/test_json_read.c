/* The JSON reader (tests/tools/json_read.h): what the kit's writer writes
 * reads back exactly, escapes and UTF-8 decode as RFC 8259 says, and text
 * outside the grammar is refused. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include "../tools/json.h"
#include "../tools/json_read.h"

static int parse(const char *text, JsonValue *v)
{
    char err[256];
    int status = json_parse(text, strlen(text), v, err, sizeof err);
    if (status != 0)
        printf("    json_parse(%s): %s\n", text, err);
    return status;
}

/* A document of every kind of value, written by the kit's writer, read
 * back: the same numbers (bit for bit), strings, booleans and shape. */
static void test_reads_what_the_writer_writes(void)
{
    static const double numbers[] = { 0, -0.0, 1, -1, 0.1, 1.0 / 3, 2.0 / 3 * 20, 1e300, -2.5e-308,
                                      4.9406564584124654e-324, 100, 3.3333333333333335 };
    const int nn = (int)(sizeof numbers / sizeof numbers[0]);
    static const char odd[] = "quote \" backslash \\ slash / tab \t newline \n bell \a "
                              "e-acute \xc3\xa9 euro \xe2\x82\xac emoji \xf0\x9f\x98\x80";
    JsonWriter w;
    json_init(&w, 2);
    json_begin_object(&w);
    json_key(&w, "numbers");
    json_begin_array(&w);
    for (int k = 0; k < nn; k++)
        json_number(&w, numbers[k]);
    json_end_array(&w);
    json_key(&w, "odd");
    json_string(&w, odd);
    json_key(&w, "nul");
    json_string_bytes(&w, "a\0b", 3);
    json_key(&w, "yes");
    json_bool(&w, true);
    json_key(&w, "no");
    json_bool(&w, false);
    json_key(&w, "nothing");
    json_null(&w);
    json_key(&w, "empty");
    json_begin_object(&w);
    json_end_object(&w);
    json_key(&w, "nested");
    json_begin_array(&w);
    json_begin_array(&w);
    json_end_array(&w);
    json_int(&w, -42);
    json_end_array(&w);
    json_end_object(&w);
    size_t len;
    const char *text = json_text(&w, &len);
    CHECK(text != NULL);
    JsonValue v;
    char err[256];
    CHECK_MSG(json_parse(text, len, &v, err, sizeof err) == 0, "%s", err);
    CHECK_EQ_INT(v.type, JSON_OBJECT);
    CHECK_EQ_INT(v.n, 8);
    const JsonValue *a = json_member(&v, "numbers");
    CHECK(a && a->type == JSON_ARRAY && a->n == nn);
    for (int k = 0; a && k < a->n && k < nn; k++) {
        CHECK_EQ_INT(a->items[k].type, JSON_NUMBER);
        CHECK_EQ_DOUBLE(a->items[k].number, numbers[k]);
    }
    const JsonValue *s = json_member(&v, "odd");
    CHECK(s && s->type == JSON_STRING && s->length == strlen(odd) && strcmp(s->string, odd) == 0);
    s = json_member(&v, "nul");
    CHECK(s && s->type == JSON_STRING && s->length == 3 && memcmp(s->string, "a\0b", 3) == 0);
    CHECK(json_member(&v, "yes") && json_member(&v, "yes")->type == JSON_BOOL && json_member(&v, "yes")->boolean);
    CHECK(json_member(&v, "no") && json_member(&v, "no")->type == JSON_BOOL && !json_member(&v, "no")->boolean);
    CHECK(json_member(&v, "nothing") && json_member(&v, "nothing")->type == JSON_NULL);
    CHECK(json_member(&v, "empty") && json_member(&v, "empty")->type == JSON_OBJECT && json_member(&v, "empty")->n == 0);
    const JsonValue *nested = json_member(&v, "nested");
    CHECK(nested && nested->n == 2 && nested->items[0].type == JSON_ARRAY && nested->items[0].n == 0 &&
          nested->items[1].number == -42);
    CHECK(json_member(&v, "missing") == NULL);
    CHECK(json_member(&v.items[0], "numbers") == NULL);       /* not an object */
    json_value_free(&v);
    json_free(&w);
}

/* Escapes decode to the code points RFC 8259 gives them, written as UTF-8
 * by hand: U+00E9 is C3 A9, U+20AC is E2 82 AC, and the surrogate pair
 * D83D DE00 is U+1F600, F0 9F 98 80. */
static void test_escapes(void)
{
    JsonValue v;
    CHECK(parse("\"\\u00e9\\u20AC\\ud83d\\ude00\\\"\\\\\\/\\b\\f\\n\\r\\t\\u0000\"", &v) == 0);
    static const char want[] = "\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80\"\\/\b\f\n\r\t";
    CHECK_EQ_INT(v.type, JSON_STRING);
    CHECK_EQ_INT(v.length, sizeof want);           /* with the decoded NUL */
    CHECK(memcmp(v.string, want, sizeof want) == 0);
    json_value_free(&v);
}

static void test_numbers_by_the_grammar(void)
{
    static const struct { const char *text; double want; } good[] = {
        { "0", 0 }, { "-0", -0.0 }, { "12", 12 }, { "1.5", 1.5 }, { "-1.5e3", -1500 },
        { "2E-2", 0.02 }, { "1e+2", 100 }, { "0.1", 0.1 },
    };
    for (size_t k = 0; k < sizeof good / sizeof good[0]; k++) {
        JsonValue v;
        CHECK(parse(good[k].text, &v) == 0);
        CHECK_EQ_INT(v.type, JSON_NUMBER);
        CHECK_EQ_DOUBLE(v.number, good[k].want);
        json_value_free(&v);
    }
}

static void test_refuses_what_is_not_json(void)
{
    static const char *const bad[] = {
        "", "   ", "[1,]", "[,1]", "{\"a\":1,}", "{\"a\" 1}", "{a:1}", "{\"a\":1 \"b\":2}",
        "{\"a\":1,\"a\":2}",                /* a repeated name */
        "01", "+1", ".5", "1.", "1e", "-", "0x10", "NaN", "Infinity", "1 2",
        "\"abc", "\"tab\there\"", "\"\\x\"", "\"\\u12\"", "\"\\ud83d\"", "\"\\ude00\"",
        "\"\xc3\"", "\"\xc0\xaf\"", "\"\xed\xa0\x80\"", "\"\xf4\x90\x80\x80\"", "\"\xff\"",
        "tru", "nul", "True", "[1]]", "{}{}",
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        JsonValue v;
        char err[256] = "";
        CHECK_MSG(json_parse(bad[k], strlen(bad[k]), &v, err, sizeof err) != 0, "accepted: %s", bad[k]);
        CHECK_MSG(strstr(err, "offset ") == err, "no reason given for: %s", bad[k]);
    }
    /* Nesting deeper than 64 levels is refused; 64 levels are read. */
    char deep[200];
    memset(deep, '[', 65);
    memset(deep + 65, ']', 65);
    deep[130] = '\0';
    JsonValue v;
    char err[256];
    CHECK(json_parse(deep, strlen(deep), &v, err, sizeof err) != 0);
    CHECK(json_parse(deep + 1, strlen(deep + 1) - 1, &v, err, sizeof err) == 0);
    json_value_free(&v);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_reads_what_the_writer_writes),
    CHECK_TEST(test_escapes),
    CHECK_TEST(test_numbers_by_the_grammar),
    CHECK_TEST(test_refuses_what_is_not_json),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
