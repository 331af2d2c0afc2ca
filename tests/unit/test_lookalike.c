/*
 * Characters that look like C's but are not (tests/grader/lookalike.c):
 * found in code, with their line and what to type instead; passed over in
 * comments, strings and character literals, where C takes them.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/lookalike.h"

static const struct {
    const char *what, *text;
    int found;
    const char *says;           /* in the explanation, or NULL */
} cases[] = {
    { "a non-breaking space in code",
      "double f(void)\n{\n    return 2\xC2\xA0* 3;\n}\n", 1,
      "f.c:3: a non-breaking space (U+00A0): type an ordinary space\n" },
    { "curly double quotes around a string",
      "#include <stdio.h>\nvoid g(void) { printf(\xE2\x80\x9Chi\xE2\x80\x9D); }\n", 2,
      "f.c:2: a curly opening double quote (U+201C): type a straight \"\n"
      "f.c:2: a curly closing double quote (U+201D): type a straight \"\n" },
    { "a minus sign and a multiplication sign",
      "double h(double x)\n{\n    return \xE2\x88\x92x \xC3\x97 2;\n}\n", 2,
      "f.c:3: a minus sign (U+2212): type a hyphen-minus -\nf.c:3: a multiplication sign (U+00D7): type *\n" },
    { "after a comment over lines, and a string with an escaped quote",
      "/* one\n   two */\nconst char *s = \"a \\\" b\";\nint k = 1\xE2\x80\x8B;\n", 1,
      "f.c:4: a zero-width space (U+200B): type nothing (delete it)\n" },
    { "the same on one line: once, with how many times",
      "int a\xC2\xA0=\xC2\xA0" "1\xC2\xA0+\xC2\xA0" "2;\n", 4,
      "f.c:1: a non-breaking space (U+00A0), 4 times: type an ordinary space\n" },
    { "more than three lines: the first three, and how many more characters",
      "int a\xC2\xA0;\nint b\xC2\xA0;\nint c\xC2\xA0;\nint d\xC2\xA0\xC2\xA0;\n", 5,
      "f.c:3: a non-breaking space (U+00A0): type an ordinary space\n(and 2 more such characters)\n" },
    { "in comments, strings and character literals: C takes them",
      "// \xE2\x80\x9Cquoted\xE2\x80\x9D \xC2\xA0\n/* \xE2\x88\x92 */\nconst char *s = \"\xC3\x97\";\n"
      "int c = '\xC2\xA0';\n", 0, NULL },
    { "a byte order mark at the start: the compiler skips it",
      "\xEF\xBB\xBFint x;\n", 0, NULL },
    { "other non-ASCII text in code (not a lookalike): left to the compiler",
      "int caf\xC3\xA9 = 1;\n", 0, NULL },
    { "a line comment continued by a backslash hides the next line too",
      "// note \\\n\xC2\xA0 still the comment\nint y;\n", 0, NULL },
};

static void test_cases(void)
{
    for (int k = 0; k < CHECK_COUNT(cases); k++) {
        char out[1200];
        int n = lookalike_explain(cases[k].text, strlen(cases[k].text), "f.c", out, sizeof out);
        CHECK_MSG(n == cases[k].found, "%s: found %d, not %d", cases[k].what, n, cases[k].found);
        if (cases[k].says)
            CHECK_MSG(strstr(out, cases[k].says) != NULL, "%s: said '%s'", cases[k].what, out);
        else
            CHECK_MSG(out[0] == '\0', "%s: said '%s'", cases[k].what, out);
    }
}

/* A text cut inside a sequence, and an explanation longer than its room:
 * nothing read or written out of bounds (the sanitizer build checks). */
static void test_edges(void)
{
    char small[40];
    const char *text = "int a\xC2\xA0=\xC2\xA0" "1;";
    int n = lookalike_explain(text, strlen(text), "a-long-file-name.c", small, sizeof small);
    CHECK(n == 2 && strlen(small) < sizeof small);
    CHECK(lookalike_explain("int a\xE2\x88", 7, "f.c", small, sizeof small) == 0);
}

/* UTF-16 is told by its byte-order mark, or without one by every other
 * byte of ASCII text being 0; UTF-8 text, with or without its own mark,
 * and a text too short to tell are not UTF-16. */
static void test_utf16(void)
{
    static const char le[] = "\xFF\xFEi\0n\0t\0", be[] = "\xFE\xFF\0i\0n\0t";
    static const char bare[] = "i\0n\0t\0 \0x\0 \0=\0 \0" "1\0;\0\n\0";
    static const char bare_be[] = "\0i\0n\0t\0 \0x\0 \0=\0 \0" "1\0;\0\n";
    const char *utf8 = "\xEF\xBB\xBFint x = 1; /* \xC3\x97 */\n";
    CHECK(lookalike_utf16(le, sizeof le - 1));
    CHECK(lookalike_utf16(be, sizeof be - 1));
    CHECK(lookalike_utf16(bare, sizeof bare - 1));
    CHECK(lookalike_utf16(bare_be, sizeof bare_be - 1));
    CHECK(!lookalike_utf16(utf8, strlen(utf8)));
    CHECK(!lookalike_utf16("int x = 1;\n", 11));
    CHECK(!lookalike_utf16("i\0n\0t\0", 6));                /* too short to tell */
}

static const CheckTest tests[] = {
    CHECK_TEST(test_cases),
    CHECK_TEST(test_edges),
    CHECK_TEST(test_utf16),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
