/*
 * The fields of the kit's CSV files (tests/grader/csv.c): how a name is
 * written (quoted where it must be, after an apostrophe where a
 * spreadsheet would take it for a formula), and that reading it back
 * gives the name as it was, for the names a class's folders may have.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/csv.h"

/* What csv_field writes for s between before and after, in out (n bytes). */
static void written(const char *before, const char *s, const char *after, char *out, size_t n)
{
    FILE *f = tmpfile();
    out[0] = '\0';
    CHECK(f != NULL);
    if (!f)
        return;
    fputs(before, f);
    csv_field(f, s);
    fputs(after, f);
    rewind(f);
    size_t got = fread(out, 1, n - 1, f);
    out[got] = '\0';
    fclose(f);
}

static void test_written(void)
{
    static const struct {
        const char *name, *field;
    } cases[] = {
        { "plain", "plain" },
        { "a,b", "\"a,b\"" },
        { "say \"hi\"", "\"say \"\"hi\"\"\"" },
        { "=SUM(A1)", "\"'=SUM(A1)\"" },
        { "-rf", "\"'-rf\"" },
        { "@me", "\"'@me\"" },
        { "+1", "\"'+1\"" },
        { "'=x", "'=x" },               /* an apostrophe first: no formula */
        { "two\nlines", "two\\x0alines" },             /* control bytes as \\xHH */
        { "esc\033[31m", "esc\\x1b[31m" },
        { "\tTab", "\"'\\x09Tab\"" },
        { "back\\slash", "back\\x5cslash" },          /* and the backslash, to read back */
        { "", "" },
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char out[256];
        written("", cases[k].name, "", out, sizeof out);
        CHECK_MSG(strcmp(out, cases[k].field) == 0, "%s: written %s, want %s", cases[k].name, out,
                  cases[k].field);
    }
}

/* A line of three fields, the name between two others, read back. */
static void test_read_back(void)
{
    static const char *const names[] = {
        "plain", "a,b", "say \"hi\"", "=SUM(A1)", "-rf", "@me", "+1", "\tTab", "\rCR", "'=x",
        "'plain", "two\nlines", "p1 <b>\"q'&amp;\001x", "=50% <i>", "", "back\\slash\\x41",
        "esc\033[31m",
    };
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        char line[512];
        written("first,", names[k], ",last\r\nnext\n", line, sizeof line);
        const char *p = line;
        int end = 0;
        char *a = csv_read_field(&p, &end), *b = a && !end ? csv_read_field(&p, &end) : NULL;
        int end_b = end;
        char *c = b && !end ? csv_read_field(&p, &end) : NULL;
        CHECK_MSG(a && strcmp(a, "first") == 0, "name %zu: the first field", k);
        CHECK_MSG(b && strcmp(b, names[k]) == 0 && !end_b, "name %zu: read back as '%s'", k, b ? b : "");
        CHECK_MSG(c && strcmp(c, "last") == 0 && end, "name %zu: the last field", k);
        CHECK_MSG(*p == '\r' || *p == '\n', "name %zu: it stops at the line's end", k);
        free(a);
        free(b);
        free(c);
    }
}

static const CheckTest tests[] = {
    CHECK_TEST(test_written),
    CHECK_TEST(test_read_back),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
