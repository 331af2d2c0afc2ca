/*
 * Text the student chose, shown on a terminal (tests/grader/terminal.c):
 * control characters as ^X, invalid UTF-8 and C1 controls as '?', valid
 * UTF-8 as it is; and term_append keeps whole characters only.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/terminal.h"

static const struct {
    const char *text, *shown;
} cases[] = {
    { "plain name_1", "plain name_1" },
    { "\033]0;title\007", "^[]0;title^G" },
    { "a\177b", "a^?b" },
    { "line\nand\ttab", "line\nand\ttab" },
    { "caf\xc3\xa9", "caf\xc3\xa9" },                   /* é, valid UTF-8       */
    { "\xc2\x9b" "31m", "?31m" },                       /* C1 CSI               */
    { "x\xff" "y\xc3", "x?y?" },                        /* invalid, cut short   */
    { "\xe2\x82" "z\xed\xa0\x80", "?z???" },             /* a maximal subpart is one '?'; a surrogate's 3 bytes are 3 */
    { "\xe2\x82\xac\xf0\x9f\x98\x80", "\xe2\x82\xac\xf0\x9f\x98\x80" },   /* € and an emoji */
};

static void test_append(void)
{
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char buf[64] = "> ";
        term_append(buf, sizeof buf, cases[k].text);
        CHECK_MSG(strncmp(buf, "> ", 2) == 0 && strcmp(buf + 2, cases[k].shown) == 0,
                  "case %zu: \"%s\"", k, buf);
    }
}

static void test_put(void)
{
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        FILE *f = tmpfile();
        CHECK(f != NULL);
        if (!f)
            return;
        term_put(f, cases[k].text, strlen(cases[k].text));
        char got[64] = "";
        rewind(f);
        size_t n = fread(got, 1, sizeof got - 1, f);
        got[n] = '\0';
        fclose(f);
        CHECK_MSG(strcmp(got, cases[k].shown) == 0, "case %zu: \"%s\"", k, got);
    }
}

/* A full buffer takes whole characters only: never half of "^[" or of a
 * UTF-8 sequence, and always ends in NUL. */
static void test_append_fits(void)
{
    static const struct {
        size_t size;
        const char *text, *shown;
    } fits[] = {
        { 4, "ab\033c", "ab" },          /* "^[" would need 5 bytes         */
        { 5, "ab\033c", "ab^[" },
        { 4, "ab\xc3\xa9", "ab" },       /* é would need 5                  */
        { 5, "ab\xc3\xa9", "ab\xc3\xa9" },
        { 1, "abc", "" },
    };
    for (size_t k = 0; k < sizeof fits / sizeof fits[0]; k++) {
        char buf[8];
        memset(buf, 'Z', sizeof buf);
        buf[0] = '\0';
        term_append(buf, fits[k].size, fits[k].text);
        CHECK_MSG(strcmp(buf, fits[k].shown) == 0, "case %zu: \"%s\"", k, buf);
        CHECK_MSG(buf[fits[k].size - 1] == '\0' || strlen(buf) < fits[k].size, "case %zu: no NUL", k);
    }
    char full[4] = "abc";                /* already full: unchanged       */
    term_append(full, sizeof full, "d");
    CHECK(strcmp(full, "abc") == 0);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_append),
    CHECK_TEST(test_put),
    CHECK_TEST(test_append_fits),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
