/*
 * Judging a child's answers (tests/grader/check.c): batch_split, which
 * cuts a batch's answers (every test of a part, run in one child) after
 * each "end N" line.  The child shares its process with the student's
 * code, which may write anything there, so the split must take exactly
 * the pieces the harness wrote, refuse everything else (the tests then run
 * alone), and read no byte past the answers' end.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/grader.h"

/* The answers in a buffer of exactly len bytes, no NUL after them: a read
 * past the end is the sanitizers' to see. */
static int split(const char *text, size_t len, int ntests, const char **from, size_t *size,
                 char **buf)
{
    *buf = malloc(len ? len : 1);
    if (!*buf)
        return -2;
    memcpy(*buf, text, len);
    return batch_split(*buf, len, ntests, from, size);
}

static void test_pieces(void)
{
    const char text[] = "0x1p+0 0x0p+0\nend 1\n\nend 0\n0x1p+1\n0x1p+2\nend 2\n";
    const char *from[3];
    size_t size[3];
    char *buf;
    CHECK_EQ_INT(split(text, sizeof text - 1, 3, from, size, &buf), 3);
    CHECK_EQ_INT((int)(from[0] - buf), 0);
    CHECK_EQ_INT((int)size[0], 20);
    CHECK_EQ_INT((int)(from[1] - buf), 20);
    CHECK_EQ_INT((int)size[1], 7);
    CHECK_EQ_INT((int)(from[2] - buf), 27);
    CHECK_EQ_INT((int)size[2], (int)(sizeof text - 1) - 27);
    free(buf);
}

/* Anything but exactly ntests pieces, each ending in an "end " line, with
 * nothing after the last, is refused. */
static void test_refused(void)
{
    static const struct {
        const char *text;
        int ntests;
        const char *why;
    } bad[] = {
        { "end 1\nend 1\n", 3, "fewer pieces than tests" },
        { "end 1\nend 1\nend 1\n", 2, "more pieces than tests" },
        { "end 1\nend 1\nstray\n", 2, "a line after the last piece" },
        { "end 1\nend 1", 2, "the last end line without its newline" },
        { "end 1\n0x1p+0\n", 2, "a last piece without its end line" },
        { "endless 1\nend 1\n", 2, "\"endless\" is not an end line" },
        { "end\nend 1\n", 2, "\"end\" alone is not an end line" },
        { "", 1, "no answers" },
        { "x\n", 0, "answers for no tests" },
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        const char *from[4];
        size_t size[4];
        char *buf;
        int got = split(bad[k].text, strlen(bad[k].text), bad[k].ntests, from, size, &buf);
        CHECK_MSG(got == -1, "%s: %d, not -1", bad[k].why, got);
        free(buf);
    }
}

/* NUL bytes are answers like any others (the split is by length, not by
 * C string), and an "end " line must start a line. */
static void test_bytes(void)
{
    const char text[] = "a\0b end 9\nend 1\n\0\nend 1\n";
    const char *from[2];
    size_t size[2];
    char *buf;
    CHECK_EQ_INT(split(text, sizeof text - 1, 2, from, size, &buf), 2);
    CHECK_EQ_INT((int)size[0], 16);
    CHECK_EQ_INT((int)size[1], (int)(sizeof text - 1) - 16);
    free(buf);
    /* The same answers cut short, mid-line: refused, and nothing read past. */
    CHECK_EQ_INT(split(text, 12, 2, from, size, &buf), -1);
    free(buf);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_pieces),
    CHECK_TEST(test_refused),
    CHECK_TEST(test_bytes),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
