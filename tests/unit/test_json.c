/* The JSON writer of tests/tools/json.h.  Its text is compared whole with
 * what it must be; where the input is random, a checker of JSON's strings
 * and numbers (RFC 8259) reads the text instead. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include "../tools/json.h"

/* ---- an independent checker: strings in valid UTF-8, numbers (RFC 8259) ---- */

typedef struct {
    const unsigned char *p;
    size_t n, at;
} Checker;

/* Whether the next byte is ch; if so it is consumed. */
static int jc_eat(Checker *c, char ch)
{
    if (c->at < c->n && c->p[c->at] == (unsigned char)ch) {
        c->at++;
        return 1;
    }
    return 0;
}

/* One UTF-8 encoded code point (not a surrogate, not overlong, at most
 * U+10FFFF), decoded from first principles.  Returns 1 if valid. */
static int jc_utf8(Checker *c)
{
    unsigned char b = c->p[c->at];
    int extra = b >= 0xF0 && b <= 0xF7 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : -1;
    if (b >= 0xF8 || extra < 0 || c->n - c->at <= (size_t)extra)
        return 0;
    uint32_t cp = b & (0x3Fu >> extra);
    for (int k = 1; k <= extra; k++) {
        unsigned char t = c->p[c->at + k];
        if ((t & 0xC0) != 0x80)
            return 0;
        cp = (cp << 6) | (t & 0x3Fu);
    }
    static const uint32_t min[4] = {0, 0x80, 0x800, 0x10000};
    if (cp < min[extra] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    c->at += 1 + (size_t)extra;
    return 1;
}

static int jc_string(Checker *c)
{
    if (!jc_eat(c, '"'))
        return 0;
    while (c->at < c->n) {
        unsigned char b = c->p[c->at];
        if (b == '"') {
            c->at++;
            return 1;
        }
        if (b < 0x20)
            return 0;
        if (b == '\\') {
            c->at++;
            if (c->at >= c->n)
                return 0;
            unsigned char e = c->p[c->at++];
            if (e == 'u') {
                for (int k = 0; k < 4; k++, c->at++)
                    if (c->at >= c->n || !strchr("0123456789abcdefABCDEF", c->p[c->at]) ||
                        c->p[c->at] == 0)
                        return 0;
            } else if (!strchr("\"\\/bfnrt", e) || e == 0) {
                return 0;
            }
        } else if (b >= 0x80) {
            if (!jc_utf8(c))
                return 0;
        } else {
            c->at++;
        }
    }
    return 0;
}

static int jc_digits(Checker *c)
{
    size_t start = c->at;
    while (c->at < c->n && c->p[c->at] >= '0' && c->p[c->at] <= '9')
        c->at++;
    return c->at > start;
}

static int jc_number(Checker *c)
{
    jc_eat(c, '-');
    if (jc_eat(c, '0')) {
        if (c->at < c->n && c->p[c->at] >= '0' && c->p[c->at] <= '9')
            return 0;                                   /* no leading zeros */
    } else if (!jc_digits(c)) {
        return 0;
    }
    if (jc_eat(c, '.') && !jc_digits(c))
        return 0;
    if (jc_eat(c, 'e') || jc_eat(c, 'E')) {
        if (!jc_eat(c, '+'))
            jc_eat(c, '-');
        if (!jc_digits(c))
            return 0;
    }
    return 1;
}

/* Whether text[0 .. n-1] is exactly one JSON string, or one number. */
static int string_valid(const char *text, size_t n)
{
    Checker c = {(const unsigned char *)text, n, 0};
    return jc_string(&c) && c.at == n;
}

static int number_valid(const char *text, size_t n)
{
    Checker c = {(const unsigned char *)text, n, 0};
    return jc_number(&c) && c.at == n;
}

static void test_checker_itself(void)
{
    static const char *good[] = {"\"a\\u00e9\\n\"", "\"\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80\"", "\"\"", "\"\\/\""};
    static const char *bad[] = {"", "\"\x01\"", "\"\xFF\"", "\"\xC0\xAF\"", "\"\xED\xA0\x80\"", "\"\xF4\x90\x80\x80\"",
                                "\"\\x\"", "\"abc", "\"a\" ", "\"\\u12g4\""};
    static const char *good_numbers[] = {"0", "-0.5e+3", "12", "1E9"};
    static const char *bad_numbers[] = {"01", "1.", "-", ".5", "1e", "+1", "0x10", "1 "};
    for (size_t k = 0; k < sizeof good / sizeof good[0]; k++)
        CHECK_MSG(string_valid(good[k], strlen(good[k])), "valid JSON string refused: %s", good[k]);
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
        CHECK_MSG(!string_valid(bad[k], strlen(bad[k])), "invalid JSON string accepted: %s", bad[k]);
    for (size_t k = 0; k < sizeof good_numbers / sizeof good_numbers[0]; k++)
        CHECK_MSG(number_valid(good_numbers[k], strlen(good_numbers[k])), "valid number refused: %s", good_numbers[k]);
    for (size_t k = 0; k < sizeof bad_numbers / sizeof bad_numbers[0]; k++)
        CHECK_MSG(!number_valid(bad_numbers[k], strlen(bad_numbers[k])), "invalid number accepted: %s", bad_numbers[k]);
}

/* ---- helpers ------------------------------------------------------------------------------ */

/* Checks that w's text is exactly want, then frees w. */
static void check_text(JsonWriter *w, const char *want)
{
    size_t len = 0;
    const char *text = json_text(w, &len);
    CHECK_MSG(text != NULL, "writer failed: %s", json_error(w) ? json_error(w) : "unfinished");
    if (text) {
        CHECK_MSG(strcmp(text, want) == 0, "wrote   %s\n        want    %s", text, want);
        CHECK_EQ_INT(len, strlen(text));
    }
    json_free(w);
}

/* The text of one string value holding bytes s[0 .. n-1]. */
static void check_string(const char *s, size_t n, const char *want)
{
    JsonWriter w;
    json_init(&w, 0);
    json_string_bytes(&w, s, n);
    check_text(&w, want);
}

static uint64_t rng_state = 88172645463325252ull;

static uint64_t rng_next(void)
{
    return check_xorshift64(&rng_state);
}

/* Makes on w the calls script names, a word each (words apart by a space):
 * { } [ ] begin and end an object or an array, null, true and false are
 * those values, kNAME is a key, sTEXT a string, iN an integer, nX a
 * number. */
static void run(JsonWriter *w, const char *script)
{
    static const struct { const char *word; void (*call)(JsonWriter *); } plain[] = {
        { "{", json_begin_object }, { "}", json_end_object }, { "[", json_begin_array },
        { "]", json_end_array }, { "null", json_null },
    };
    char word[64];
    for (const char *p = script; *p; p += *p == ' ') {
        size_t n = strcspn(p, " ");
        snprintf(word, sizeof word, "%.*s", (int)n, p);
        p += n;
        for (int k = 0; k < CHECK_COUNT(plain); k++)
            if (strcmp(word, plain[k].word) == 0)
                plain[k].call(w);
        if (word[0] == 'k')
            json_key(w, word + 1);
        else if (word[0] == 's')
            json_string(w, word + 1);
        else if (word[0] == 'i')
            json_int(w, strtoll(word + 1, NULL, 10));
        else if (word[0] == 'n' && word[1] != 'u')
            json_number(w, strtod(word + 1, NULL));
        else if (word[0] == 't' || word[0] == 'f')
            json_bool(w, word[0] == 't');
    }
}

/* The text of script run on a writer indented by indent is want; with want
 * NULL, the writer has failed (json_text NULL, an error set). */
static void check_script(int indent, const char *script, const char *want)
{
    JsonWriter w;
    json_init(&w, indent);
    run(&w, script);
    if (want) {
        check_text(&w, want);
        return;
    }
    CHECK_MSG(json_text(&w, NULL) == NULL, "%s: accepted", script);
    CHECK_MSG(json_error(&w) != NULL || !w.done, "%s: no error", script);
    json_free(&w);
}

/* ---- strings --------------------------------------------------------------------------------- */

static void test_escaping(void)
{
    check_string("plain", 5, "\"plain\"");
    check_string("", 0, "\"\"");
    check_string("a\"b\\c/d", 7, "\"a\\\"b\\\\c/d\"");
    check_string("\n\t\r\x01\x1f\x7f", 6, "\"\\u000a\\u0009\\u000d\\u0001\\u001f\x7f\"");
    check_string("nul\0byte", 8, "\"nul\\u0000byte\"");
    JsonWriter w;
    json_init(&w, 0);
    json_string(&w, NULL);
    check_text(&w, "null");
}

static void test_utf8_kept_and_replaced(void)
{
    /* valid sequences pass through unchanged */
    check_string("\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80 \xF4\x8F\xBF\xBF", 16,
                 "\"\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80 \xF4\x8F\xBF\xBF\"");
    check_string("\xE2\x80\xA8", 3, "\"\xE2\x80\xA8\"");     /* U+2028 is fine in JSON */
#define FFFD "\xEF\xBF\xBD"
    check_string("\xFF", 1, "\"" FFFD "\"");
    check_string("a\x80z", 3, "\"a" FFFD "z\"");                 /* lone continuation byte */
    check_string("\xC3", 1, "\"" FFFD "\"");                     /* cut short at the end */
    check_string("\xC3(", 2, "\"" FFFD "(\"");                   /* cut short by ASCII */
    check_string("\xE2\x82", 2, "\"" FFFD "\"");                 /* one U+FFFD for the prefix */
    check_string("\xE2\x82z", 3, "\"" FFFD "z\"");
    check_string("\xC0\xAF", 2, "\"" FFFD FFFD "\"");            /* overlong '/' */
    check_string("\xE0\x80\xAF", 3, "\"" FFFD FFFD FFFD "\"");   /* overlong */
    check_string("\xED\xA0\x80", 3, "\"" FFFD FFFD FFFD "\"");   /* a surrogate */
    check_string("\xF4\x90\x80\x80", 4, "\"" FFFD FFFD FFFD FFFD "\"");   /* past U+10FFFF */
    check_string("\xF0\x9F\x98", 3, "\"" FFFD "\"");
    check_string("\xF8\x88\x80\x80\x80", 5, "\"" FFFD FFFD FFFD FFFD FFFD "\"");
    check_string("ok\xC3\xA9\xFE\"", 6, "\"ok\xC3\xA9" FFFD "\\\"\"");
#undef FFFD
}

static void test_random_bytes_always_valid(void)
{
    unsigned char buf[64];
    for (int k = 0; k < 20000; k++) {
        size_t n = rng_next() % sizeof buf;
        for (size_t i = 0; i < n; i++) {
            uint64_t r = rng_next();
            /* mostly high bytes and controls, where the trouble is */
            buf[i] = (unsigned char)(r % 4 == 0 ? 0x80 + (r >> 8) % 0x80 : r % 4 == 1 ? (r >> 8) % 0x20
                                     : r % 4 == 2 ? 0xC0 + (r >> 8) % 0x40 : (r >> 8) & 0xFF);
        }
        JsonWriter w;
        json_init(&w, 0);
        json_string_bytes(&w, buf, n);
        size_t len = 0;
        const char *text = json_text(&w, &len);
        CHECK(text != NULL);
        if (text && !string_valid(text, len)) {
            CHECK_MSG(0, "invalid JSON for %zu random bytes", n);
            json_free(&w);
            return;
        }
        json_free(&w);
    }
}

/* ---- numbers ------------------------------------------------------------------------------- */

static void test_numbers(void)
{
    static const struct { double x; const char *want; } numbers[] = {
        { 0, "0" }, { -0.0, "-0" }, { 1, "1" }, { -2.5, "-2.5" }, { 0.1, "0.1" },
        { 1.0 / 3, "0.3333333333333333" }, { 2.0 / 3, "0.6666666666666666" }, { 1e300, "1e+300" },
        { 1.5e-7, "1.5e-07" }, { 123456789, "123456789" }, { 0x1p-1074, "5e-324" },
        { 1.7976931348623157e308, "1.7976931348623157e+308" },
        { NAN, "null" }, { INFINITY, "null" }, { -INFINITY, "null" },
    };
    JsonWriter w;
    for (int k = 0; k < CHECK_COUNT(numbers); k++) {
        json_init(&w, 0);
        json_number(&w, numbers[k].x);
        check_text(&w, numbers[k].want);
    }
    check_script(0, "[ i-9223372036854775808 i42 true false null ]",
                 "[-9223372036854775808,42,true,false,null]");
}

static void test_numbers_round_trip(void)
{
    /* random bits, then every power of two and the doubles on either side
     * of it (where those below lie twice as close as those above) */
    for (int k = 0; k < 100000 + 3 * 2098; k++) {
        uint64_t bits = rng_next();
        double x;
        memcpy(&x, &bits, sizeof x);
        if (k >= 100000) {
            double p = ldexp(1.0, (k - 100000) / 3 - 1074);
            x = (k - 100000) % 3 == 0 ? p : nextafter(p, (k - 100000) % 3 == 1 ? 0 : INFINITY);
        }
        JsonWriter w;
        json_init(&w, 0);
        json_number(&w, x);
        size_t len;
        const char *text = json_text(&w, &len);
        if (!isfinite(x)) {
            CHECK(text && strcmp(text, "null") == 0);
        } else if (text) {
            double back = strtod(text, NULL);
            CHECK_MSG(memcmp(&back, &x, sizeof x) == 0, "%a written as %s", x, text);
            CHECK_MSG(len <= 24 && number_valid(text, len), "%a written as %s", x, text);
            /* shortest: one significant digit fewer does not read back */
            char shorter[400];
            int digits = 0;
            for (const char *p = text; *p && *p != 'e'; p++)
                digits += *p >= '0' && *p <= '9';
            if (digits > 1) {
                snprintf(shorter, sizeof shorter, "%.*g", digits - 1, x);
                CHECK_MSG(strtod(shorter, NULL) != x || strlen(shorter) >= len,
                          "%s is not the shortest for %a", text, x);
            }
        }
        json_free(&w);
    }
    /* decimals with few digits are written as they were read */
    for (int k = 0; k < 3000; k++) {
        char decimal[40];
        snprintf(decimal, sizeof decimal, "%d.%03d", (int)(rng_next() % 2001) - 1000,
                 (int)(rng_next() % 1000));
        double x = strtod(decimal, NULL);
        JsonWriter w;
        json_init(&w, 0);
        json_number(&w, x);
        const char *text = json_text(&w, NULL);
        CHECK_MSG(text && strlen(text) <= strlen(decimal), "%s written as %s", decimal, text);
        json_free(&w);
    }
}

/* ---- structure ------------------------------------------------------------------------------ */

/* Objects and arrays, nested and empty, written compact and indented; a
 * value alone; and what a writer refuses. */
static void test_structure(void)
{
    check_script(0, "{ kscore n7.5 ktests [ { kname sa ktags [ ] kextra { } } "
                    "{ kname sb ktags [ ] kextra { } } ] kok true }",
                 "{\"score\":7.5,\"tests\":[{\"name\":\"a\",\"tags\":[],\"extra\":{}},"
                 "{\"name\":\"b\",\"tags\":[],\"extra\":{}}],\"ok\":true}");
    check_script(2, "{ ka [ i1 { kb\n null } [ ] ] kc sd }",
                 "{\n  \"a\": [\n    1,\n    {\n      \"b\\u000a\": null\n    },\n    []\n  ],\n"
                 "  \"c\": \"d\"\n}");
    check_script(0, "i5", "5");
    static const char *const misuse[] = {
        "{ i1 }",               /* a value without a key */
        "[ kk ]",               /* a key in an array */
        "{ kk }",               /* a key without a value */
        "[ }",                  /* mismatched end */
        "]",                    /* end of nothing */
        "i1 i2",                /* two top-level values */
        "[",                    /* unfinished */
        "",                     /* empty */
    };
    for (int k = 0; k < CHECK_COUNT(misuse); k++)
        check_script(0, misuse[k], NULL);
}

/* JSON_MAX_DEPTH arrays, one in another, are written; one more is too deep. */
static void test_deep_nesting(void)
{
    char script[4 * JSON_MAX_DEPTH + 5], want[2 * JSON_MAX_DEPTH + 3];
    for (int d = JSON_MAX_DEPTH; d <= JSON_MAX_DEPTH + 1; d++) {
        for (int k = 0; k < d; k++) {
            memcpy(script + 2 * k, "[ ", 2);
            memcpy(script + 2 * (d + k), "] ", 2);
            want[k] = '[';
            want[d + k] = ']';
        }
        script[4 * d] = want[2 * d] = '\0';
        check_script(0, script, d > JSON_MAX_DEPTH ? NULL : want);
    }
}

/* ---- files --------------------------------------------------------------------------------- */

static void test_write_file(void)
{
    char dir[512], path[700], err[1000] = "";
    check_temp_dir(dir, sizeof dir, "json");
    snprintf(path, sizeof path, "%s/results.json", dir);
    JsonWriter w;
    json_init(&w, 0);
    run(&w, "{ kscore i3 }");
    CHECK_MSG(json_write_file(&w, path, err, sizeof err) == 0, "%s", err);
    json_init(&w, 0);                           /* json_write_file freed it */
    run(&w, "{ kscore i3 }");
    CHECK_MSG(json_write_file(&w, path, err, sizeof err) == 0, "%s", err);   /* replaces it */
    CHECK(check_file_is(path, "{\"score\":3}\n", 12, -1));
    /* failures: a missing directory, an unfinished document */
    char bad[800];
    snprintf(bad, sizeof bad, "%s/missing/results.json", dir);
    json_init(&w, 0);
    run(&w, "{ kscore i3 }");
    CHECK_EQ_INT(json_write_file(&w, bad, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, bad);
    json_init(&w, 0);
    json_begin_object(&w);
    snprintf(bad, sizeof bad, "%s/unfinished.json", dir);
    CHECK_EQ_INT(json_write_file(&w, bad, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, bad);
    CHECK_EQ_INT(check_count_entries(dir), 1);        /* nothing but results.json is left */
    check_remove_tree(dir);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_checker_itself),
    CHECK_TEST(test_escaping),
    CHECK_TEST(test_utf8_kept_and_replaced),
    CHECK_TEST(test_random_bytes_always_valid),
    CHECK_TEST(test_numbers),
    CHECK_TEST(test_numbers_round_trip),
    CHECK_TEST(test_structure),
    CHECK_TEST(test_deep_nesting),
    CHECK_TEST(test_write_file),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
