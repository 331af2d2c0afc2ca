/*
 * The test files' reader (tests/grader/cases.c): a file that tests_write
 * wrote reads back to the same tests, number for number; a bad line is
 * refused with the file, its line and what was wrong, and never read as
 * something else (a negative or fractional flag, a weight that is not a
 * finite positive number, an image width that is not a whole number in
 * range: found by fuzzing the reader, which once took them all).  And
 * points as people read them (points_text): two decimals at most.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/grader.h"

static char dir[64];

/* Writes text to a file of dir; its path in path. */
static void write_file(const char *name, const char *text, char *path, size_t size)
{
    snprintf(path, size, "%s/%s", dir, name);
    check_write_file(path, text, strlen(text));
}

/* A good test, with one line replaced: "LINE" in good is where. */
static const char good[] =
    "# a comment\n"
    "test 3b image core 2\n"
    "name Part 3b: a small image\n"
    "note two pixels\n"
    "background 0.5 0.25 1\n"
    "sphere 0 0 -5 1 1 0 0\n"
    "LINE\n"
    "case 0 0 1 | 1 0 0 | 1e-9 1e-9 1e-9 | 0 0 0 | 0\n"
    "case 1 0 1 | 0.5 0.25 1 | 1e-9 1e-9 1e-9 | 0 0 0 | 1\n"
    "hint 0 0 0 | the background is not black\n"
    "end\n";

/* Reads good with LINE replaced by line: 0, or -1 with the message in err. */
static int read_with(const char *line, TestList *list, char *err, size_t errlen)
{
    char text[sizeof good + 400], path[128];
    const char *at = strstr(good, "LINE");
    snprintf(text, sizeof text, "%.*s%s%s", (int)(at - good), good, line, at + 4);
    write_file("one.tests", text, path, sizeof path);
    memset(list, 0, sizeof *list);
    err[0] = '\0';
    return tests_read(list, path, false, err, errlen);
}

/* Rounded to two decimals, trailing zeros dropped: the want column is the
 * decimal rounding of each number, worked out by hand. */
static void test_points_text(void)
{
    static const struct { double points; const char *want; } cases[] = {
        { 20, "20" },           { 100, "100" },        { 0, "0" },
        { -0.0, "0" },          { 2.5, "2.5" },        { 12.5, "12.5" },
        { 120.0 / 7, "17.14" }, { 22.9412, "22.94" },  { 80.084, "80.08" },
        { 9.19643, "9.2" },     { 0.004, "0" },        { 0.996, "1" },
        { 100.0 / 3, "33.33" }, { 200.0 / 3, "66.67" }, { 0.5 / 16, "0.03" },
        { -1.25, "-1.25" },     { 1e300, "1e+300" },
    };
    for (int k = 0; k < CHECK_COUNT(cases); k++) {
        PointsText got = points_text(cases[k].points);
        CHECK_MSG(strcmp(got.s, cases[k].want) == 0, "points_text(%.17g) is \"%s\", want \"%s\"",
                  cases[k].points, got.s, cases[k].want);
    }
}

static void setup(void)
{
    check_temp_dir(dir, sizeof dir, "cases");
}

static void test_good_file(void)
{
    TestList list;
    char err[300];
    CHECK_MSG(read_with("nx 2", &list, err, sizeof err) == 0, "refused: %s", err);
    CHECK_EQ_INT(list.n, 1);
    if (list.n != 1) {
        testlist_free(&list);
        return;
    }
    const Test *t = &list.tests[0];
    CHECK_EQ_INT(t->part, PART3B);
    CHECK_EQ_INT(t->kind, KIND_IMAGE);
    CHECK_EQ_INT(t->hard, 0);
    CHECK_EQ_DOUBLE(t->weight, 2);
    CHECK(strcmp(t->name, "Part 3b: a small image") == 0);
    CHECK_EQ_INT(t->image_nx, 2);
    CHECK_EQ_INT(t->nspheres, 1);
    CHECK_EQ_INT(t->ncases, 2);
    CHECK_EQ_DOUBLE(t->background[1], 0.25);
    CHECK_EQ_INT(t->cases[0].flags, 0);
    CHECK_EQ_INT(t->cases[1].flags, CASE_EITHER_HIT);
    CHECK_EQ_DOUBLE(t->cases[1].want[1], 0.25);
    CHECK_EQ_INT(t->cases[1].nhints, 1);
    testlist_free(&list);
}

/* What tests_write writes, tests_read reads back, to the same numbers. */
static void test_round_trip(void)
{
    TestList out = { 0 }, in = { 0 };
    Test *t = testlist_add(&out, PART3A, KIND_SPHERE, "Part 3a: round trip");
    t->weight = 0.1;
    t->hard = true;
    const double odd[] = { 0.1, 1.0 / 3, -0.0, 5e-324, 1.7976931348623157e308, 2.5e-9 };
    for (int k = 0; k < 6; k++) {
        Case *c = test_add_case(t);
        for (int i = 0; i < kind_nin(KIND_SPHERE); i++)
            c->in[i] = odd[(k + i) % 6];
        c->want[0] = 1;
        c->want[1] = odd[k];
        c->tol[1] = 1e-9;
        c->flags = (unsigned)(k % 2);
    }
    char path[128], err[300] = "";
    snprintf(path, sizeof path, "%s/trip.tests", dir);
    CHECK_MSG(tests_write(&out, path, "# written by test_cases", err, sizeof err) == 0, "%s", err);
    CHECK_MSG(tests_read(&in, path, false, err, sizeof err) == 0, "refused: %s", err);
    CHECK_EQ_INT(in.n, 1);
    if (in.n == 1) {
        const Test *u = &in.tests[0];
        CHECK_EQ_INT(u->ncases, 6);
        CHECK(u->hard);
        CHECK_EQ_DOUBLE(u->weight, 0.1);
        for (int k = 0; k < u->ncases && k < 6; k++) {
            CHECK_MSG(memcmp(u->cases[k].in, t->cases[k].in, sizeof u->cases[k].in) == 0,
                      "case %d: the inputs read back differ", k);
            CHECK_MSG(memcmp(&u->cases[k].want[1], &odd[k], sizeof odd[k]) == 0,
                      "case %d: want[1] read back differs", k);
            CHECK_EQ_INT(u->cases[k].flags, k % 2);
        }
    }
    testlist_free(&out);
    testlist_free(&in);
}

/* Each line in place of LINE (line 7), or in place of a line of its own
 * kind, is refused, naming the file, the line and the trouble. */
static void test_bad_lines(void)
{
    static const struct {
        const char *line, *want;
    } bad[] = {
        { "nx 0", "nx needs a whole number from 1 to 16384" },
        { "nx -3", "nx needs a whole number from 1 to 16384" },
        { "nx 16385", "nx needs a whole number from 1 to 16384" },
        { "nx 2.5", "nx needs a whole number from 1 to 16384" },
        { "nx 12abc", "nx needs a whole number from 1 to 16384" },
        { "nx 99999999999999999999999", "nx needs a whole number from 1 to 16384" },
        { "nx", "unknown line" },
        { "case 0 0 1 | 1 0 0 | 0 0 0 | 0 0 0 | -1", "case flags must be 0, or 1" },
        { "case 0 0 1 | 1 0 0 | 0 0 0 | 0 0 0 | 2", "case flags must be 0, or 1" },
        { "case 0 0 1 | 1 0 0 | 0 0 0 | 0 0 0 | 0.5", "case flags must be 0, or 1" },
        { "case 0 0 1 | 1 0 0 | 0 0 0 | 0 0 0 | nan", "case flags must be 0, or 1" },
        { "case 0 0 1 | 1 0 0 | 0 0 0 | 0 0 0 | 4294967297", "case flags must be 0, or 1" },
        { "case 0 0 1 | 1 0 0 | 0 0 0 | 0 0 0", "case needs: inputs" },
        { "whatever 1 2 3", "unknown line" },
        { "name Part 3b: a name of 128 bytes, one more than a test's name may have, "
          "which the grader would otherwise cut short, so it refuses it", "name longer than 127 bytes" },
        { "note a note of 160 bytes, one more than a test's note may have: the grader "
          "shows it as it is, so a note it cut would tell the student something else, so it's refused",
          "note longer than 159 bytes" },
    };
    for (int k = 0; k < CHECK_COUNT(bad); k++) {
        TestList list;
        char err[300];
        int r = read_with(bad[k].line, &list, err, sizeof err);
        CHECK_MSG(r != 0, "'%s' was read", bad[k].line);
        CHECK_MSG(r == 0 || (strstr(err, "one.tests:7: ") && strstr(err, bad[k].want)),
                  "'%s': the message is '%s', not 'one.tests:7: %s...'", bad[k].line, err, bad[k].want);
        testlist_free(&list);
    }
    /* The test line itself (line 2): the weight must be a finite number
     * above 0, at most 1000000. */
    static const char *const weights[] = { "0", "-1", "nan", "inf", "1e300", "1000001" };
    for (int k = 0; k < CHECK_COUNT(weights); k++) {
        char text[sizeof good + 40], path[128], err[300] = "";
        snprintf(text, sizeof text,
                 "# line 1\ntest 1 plane core %s\nname x\ncase 90 2 1 | 4 2 | 0 0 | 0 0 | 0\nend\n", weights[k]);
        write_file("weight.tests", text, path, sizeof path);
        TestList list = { 0 };
        int r = tests_read(&list, path, false, err, sizeof err);
        CHECK_MSG(r != 0, "weight %s was read", weights[k]);
        CHECK_MSG(r == 0 || (strstr(err, "weight.tests:2: ") && strstr(err, "weight")),
                  "weight %s: the message is '%s'", weights[k], err);
        testlist_free(&list);
    }
    /* A hint's text: 159 bytes are read whole, 160 refused (line 5). */
    for (int len = 159; len <= 160; len++) {
        char text[600], path[128], err[300] = "", hint[200];
        memset(hint, 'x', (size_t)len);
        hint[len] = '\0';
        snprintf(text, sizeof text, "# line 1\ntest 1 plane core 1\nname x\n"
                 "case 90 2 1 | 4 2 | 0 0 | 0 0 | 0\nhint 1 1 | %s\nend\n", hint);
        write_file("hint.tests", text, path, sizeof path);
        TestList list = { 0 };
        int r = tests_read(&list, path, false, err, sizeof err);
        if (len == 159)
            CHECK_MSG(r == 0 && strlen(list.tests[0].cases[0].hints[0].text) == 159,
                      "a hint of 159 bytes was not read whole: %s", err);
        else
            CHECK_MSG(r != 0 && strstr(err, "hint.tests:5: hint text longer than 159 bytes"),
                      "a hint of 160 bytes: the message is '%s'", err);
        testlist_free(&list);
    }
    /* At the limits, they are read. */
    TestList list;
    char err[300];
    CHECK_MSG(read_with("nx 16384", &list, err, sizeof err) == 0, "nx 16384 refused: %s", err);
    testlist_free(&list);
    CHECK_MSG(read_with("nx 1", &list, err, sizeof err) == 0, "nx 1 refused: %s", err);
    testlist_free(&list);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_good_file),
    CHECK_TEST(test_round_trip),
    CHECK_TEST(test_bad_lines),
    CHECK_TEST(test_points_text),
};

int main(int argc, char **argv)
{
    setup();
    int status = check_main(argc, argv, tests, CHECK_COUNT(tests));
    if (dir[0] && check_remove_tree(dir) != 0)
        printf("    (could not remove %s)\n", dir);
    return status;
}
