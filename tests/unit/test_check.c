/*
 * Judging a child's answers (tests/grader/check.c): batch_split, which
 * cuts a batch's answers (every test of a part, run in one child) after
 * each "end N" line.  The child shares its process with the student's
 * code, which may write anything there, so the split must take exactly
 * the pieces the harness wrote, refuse everything else (the tests then run
 * alone), and read no byte past the answers' end.  And what the judgement
 * of Parts 4 and 5 tells: which known mistake it names when two explain a
 * test's answers, and a hit at t <= 0, NaN or infinity where none does.
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

/* Answers cut into ntests pieces, each ending in its "end " line, found
 * where they are.  NUL bytes are answers like any others (the split is by
 * length, not by C string), and an "end " line must start a line.  The
 * same answers cut short, mid-line: refused, and nothing read past. */
static void test_pieces(void)
{
    static const struct {
        const char *text;
        int ntests;
        size_t size[3];
    } good[] = {
        { "0x1p+0 0x0p+0\nend 1\n" "\nend 0\n" "0x1p+1\n0x1p+2\nend 2\n", 3, { 20, 7, 20 } },
        { "a\0b end 9\nend 1\n" "\0\nend 1\n", 2, { 16, 8 } },
    };
    for (int k = 0; k < CHECK_COUNT(good); k++) {
        size_t len = 0;
        for (int p = 0; p < good[k].ntests; p++)
            len += good[k].size[p];
        const char *from[3];
        size_t size[3];
        char *buf;
        CHECK_EQ_INT(split(good[k].text, len, good[k].ntests, from, size, &buf), good[k].ntests);
        for (int p = 0, at = 0; p < good[k].ntests; at += (int)good[k].size[p++]) {
            CHECK_EQ_INT((int)(from[p] - buf), at);
            CHECK_EQ_INT((int)size[p], (int)good[k].size[p]);
        }
        free(buf);
        CHECK_EQ_INT(split(good[k].text, 12, good[k].ntests, from, size, &buf), -1);
        free(buf);
    }
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
    for (int k = 0; k < CHECK_COUNT(bad); k++) {
        const char *from[4];
        size_t size[4];
        char *buf;
        int got = split(bad[k].text, strlen(bad[k].text), bad[k].ntests, from, size, &buf);
        CHECK_MSG(got == -1, "%s: %d, not -1", bad[k].why, got);
        free(buf);
    }
}

/* A triangle case whose answer is a hit at t = 4; with a hint of each
 * text given, a mistake that answers it with a miss. */
static void hit_case(Test *t, const char *const *mistakes, int nmistakes)
{
    Case *c = test_add_case(t);
    c->want[0] = 1;
    c->want[1] = 4;
    c->tol[1] = 1e-9;
    for (int k = 0; k < nmistakes; k++)
        snprintf(case_add_hint(c)->text, sizeof c->hints[0].text, "%s", mistakes[k]);
}

/* Two mistakes, A and B, answer both hit cases of a test with misses, as
 * the code did, and its third case right: the test alone cannot tell them
 * apart.  The part's other tests can: a test passed where A would have
 * failed rules A out, and a mistake named for another failed test is the
 * one named here.  Otherwise neither is named.  A test whose cases the
 * code answered with misses alone shows less: every mistake that misses
 * hits would fit it, so it names only a mistake another test named and
 * none ruled out, never one by elimination.  A case with NaN input rules
 * nothing out (code that turns NaN away early passes it whatever its
 * mistake). */
static void test_two_mistakes_fit(void)
{
    static const char A[] = "mistake A", B[] = "mistake B";
    const char *both[] = { A, B }, *a_only[] = { A };
    TestList list = { 0 };
    Test *failed = testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: the test failed");
    hit_case(failed, both, 2);
    hit_case(failed, both, 2);
    hit_case(failed, NULL, 0);     /* both mistakes answer it right, a hit */
    Test *hits = testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: a test of plain hits");
    hit_case(hits, NULL, 0);
    Test *rules_a_out = testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: a test A fails");
    hit_case(rules_a_out, a_only, 1);
    Test *failed_misses = testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: misses alone");
    hit_case(failed_misses, both, 2);
    hit_case(failed_misses, both, 2);
    Test *a_fails_on_nan = testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: A fails on NaN input");
    hit_case(a_fails_on_nan, a_only, 1);
    a_fails_on_nan->cases[0].in[0] = NAN;
    const char with_hit[] = "0x0p+0 0x0p+0\n0x0p+0 0x0p+0\n0x1p+0 0x1p+2\nend 3\n";
    const char misses[] = "0x0p+0 0x0p+0\n0x0p+0 0x0p+0\nend 2\n";

    const Test *passed[2] = { &list.tests[1], &list.tests[2] };
    const Test *passed_nan[2] = { &list.tests[1], &list.tests[4] };
    const char *named_a[] = { A }, *named_ab[] = { A, B };
    static const struct {
        int npassed, nnamed, ab, nan;  /* ab: named_ab, not named_a;
                                          nan: A's test passed is the NaN one */
        const char *want, *want_misses;
    } cases[] = {
        { 1, 0, 0, 0, NULL, NULL },    /* nothing tells them apart        */
        { 2, 0, 0, 0, B, NULL },       /* a passed test rules A out       */
        { 1, 1, 0, 0, A, A },          /* A was named for a failed test   */
        { 1, 2, 1, 0, NULL, NULL },    /* both were: name neither         */
        { 2, 1, 0, 0, B, NULL },       /* A ruled out, though named       */
        { 2, 0, 0, 1, NULL, NULL },    /* A's case passed has NaN input   */
    };
    for (int m = 0; m < 2; m++) {
        const char *answers = m ? misses : with_hit;
        for (int k = 0; k < CHECK_COUNT(cases); k++) {
            PartSoFar part = { cases[k].nan ? passed_nan : passed, cases[k].npassed,
                               cases[k].ab ? named_ab : named_a, cases[k].nnamed };
            const char *want = m ? cases[k].want_misses : cases[k].want;
            char *out = NULL;
            Answers a;
            CHECK(!check_answers_in_part(&list.tests[m ? 3 : 0], answers, strlen(answers), &part, &out,
                                         &a));
            if (want) {
                CHECK_MSG(a.named && strcmp(a.named, want) == 0, "%s, case %d: named %s, not %s",
                          m ? "misses alone" : "with a hit", k, a.named ? a.named : "nothing", want);
                CHECK_STR_CONTAINS(out, want);
            } else {
                CHECK_MSG(!a.named, "%s, case %d: named %s", m ? "misses alone" : "with a hit", k,
                          a.named ? a.named : "");
                CHECK_MSG(!strstr(out, A) && !strstr(out, B), "case %d: %s", k, out);
            }
            free(out);
            answers_free(&a);
        }
    }
    testlist_free(&list);
}

/* One mistake, A, alone explains a test.  With a hit among the answers it
 * is named whatever the other tests say, unless it is shown only by the
 * hits it missed and a test the code passed has a case A fails: then it is
 * not, and the hint says why, naming that test.  A shown by an answer of
 * its own (a hit at its t) is named all the same.  Answered with misses
 * alone, A is named only if another test named it (code that misses nearly
 * every hit, for a reason no model has, fits every mistake that misses
 * these hits). */
static void test_one_mistake_fits(void)
{
    static const char A[] = "mistake A: its fix";
    const char *a_only[] = { A };
    TestList list = { 0 };
    Test *failed = testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: the test failed");
    hit_case(failed, a_only, 1);
    hit_case(failed, NULL, 0);
    hit_case(testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: a test A fails"), a_only, 1);
    hit_case(testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: plain hits"), NULL, 0);
    const Test *rules_out[] = { &list.tests[1] }, *plain[] = { &list.tests[2] };
    const char *named_a[] = { A };
    static const struct {
        const char *answers;
        bool hit_at_two, ruled, named_before, named;
    } cases[] = {
        /* missed hits, nothing rules A out: named */
        { "0x0p+0 0x0p+0\n0x1p+0 0x1p+2\nend 2\n", false, false, false, true },
        /* missed hits, ruled out: not named */
        { "0x0p+0 0x0p+0\n0x1p+0 0x1p+2\nend 2\n", false, true, false, false },
        /* its own answer, a hit at t = 2 */
        { "0x1p+0 0x1p+1\n0x1p+0 0x1p+2\nend 2\n", true, true, false, true },
        /* misses alone: named only if another test named it */
        { "0x0p+0 0x0p+0\nend 1\n", false, false, false, false },
        { "0x0p+0 0x0p+0\nend 1\n", false, false, true, true },
    };
    for (int k = 0; k < CHECK_COUNT(cases); k++) {
        Hint *h = &list.tests[0].cases[0].hints[0];
        h->out[0] = cases[k].hit_at_two ? 1 : 0;
        h->out[1] = cases[k].hit_at_two ? 2 : 0;
        PartSoFar part = { cases[k].ruled ? rules_out : plain, 1, named_a, cases[k].named_before };
        const char *answers = cases[k].answers;
        char *out = NULL;
        Answers a;
        CHECK(!check_answers_in_part(&list.tests[0], answers, strlen(answers), &part, &out, &a));
        if (cases[k].named)
            CHECK_MSG(a.named && strcmp(a.named, A) == 0, "case %d: named %s", k,
                      a.named ? a.named : "nothing");
        else if (cases[k].ruled)
            CHECK_MSG(!a.named && !strstr(out, A) && strstr(out, "the hits missed here fit one known mistake "
                      "alone (mistake A), but your code passed \"Part 5: a test A fails\", which code with "
                      "that mistake fails: they have another cause"), "case %d: %s", k, out);
        else
            CHECK_MSG(!a.named && !strstr(out, "mistake A"), "case %d: %s", k, out);
        free(out);
        answers_free(&a);
    }
    testlist_free(&list);
}

/* The case of a public test of this kind whose input is in[0 .. nin). */
static const Case *public_case(const TestList *list, Kind kind, const double *in, int nin)
{
    for (int k = 0; k < list->n; k++)
        for (int c = 0; c < list->tests[k].ncases && list->tests[k].kind == kind; c++)
            if (memcmp(list->tests[k].cases[c].in, in, (size_t)nin * sizeof *in) == 0)
                return &list->tests[k].cases[c];
    return NULL;
}

/* The core tests' tolerance, pinned part by part on the worked examples,
 * whose answers are exact: relative 1e-9 (of w and h, of w, h and d for
 * Part 2's x, y and z, of t), absolute 1e-9 for Part 3b's unit direction;
 * an answer 0.9 of it away is right, 1.1 of it away wrong, either side.
 * The rest is exact (a hit's flag, a camera ray's origin, Part 3b's colour,
 * a sphere's unchanged): an answer off by the least double is wrong.  A tolerance made
 * wider or narrower, in the test files (tests/oracle) or in the judging
 * (check.c), fails here. */
static void test_core_tolerances(void)
{
    static const struct {
        const char *file;
        Kind kind;
        int nin;
        double in[CASE_MAX_IN], want[CASE_MAX_OUT], scale[CASE_MAX_OUT];
    } cases[] = {
        { "tests/public/part1.tests", KIND_PLANE, 3, { 90, 2, 1 }, { 4, 2 }, { 4, 2 } },
        { "tests/public/part2.tests", KIND_PIXEL, 7, { 0, 0, 4, 2, 4, 2, 1 }, { -1.5, 0.5, -1 }, { 4, 2, 1 } },
        { "tests/public/part2.tests", KIND_PIXEL, 7, { 6, 3, 7, 9, 1.75, 2.25, 0.5 }, { 0.75, 0.25, -0.5 },
          { 1.75, 2.25, 0.5 } },
        { "tests/public/part3a.tests", KIND_SPHERE, 10, { 0, 0, -5, 1, 0, 0, 0, 0, 0, -2 }, { 1, 2 }, { 0, 2 } },
        { "tests/public/part3b.tests", KIND_CAMERA, 6, { 0, 0, 0, 3, 0, -4 }, { 0, 0, 0, 0.6, 0, -0.8 },
          { 0, 0, 0, 1, 1, 1 } },
        { "tests/public/part3b.tests", KIND_COLOR, 6, { 0, 0, 0, 0, 0, -1 }, { 1, 0, 0 }, { 0, 0, 0 } },
        { "tests/public/part4.tests", KIND_PLANEHIT, 12, { 0, -1, 0, 0, 2, 0, 0, 0, 0, 0, -0.5, -1 }, { 1, 2 },
          { 0, 2 } },
        { "tests/public/part5.tests", KIND_TRIANGLE, 15, { -1, -1, -4, 1, -1, -4, 0, 1, -4, 0, 0, 0, 0, 0, -2 },
          { 1, 2 }, { 0, 2 } },
    };
    for (int q = 0; q < CHECK_COUNT(cases); q++) {
        TestList list = { 0 };
        char err[256];
        CHECK_MSG(tests_read(&list, cases[q].file, false, err, sizeof err) == 0, "%s", err);
        const Case *c = public_case(&list, cases[q].kind, cases[q].in, cases[q].nin);
        char what[80];                                  /* the file and the kind: the row */
        snprintf(what, sizeof what, "%s, kind %d", cases[q].file, (int)cases[q].kind);
        CHECK_MSG(c != NULL, "%s: no case of the worked example's input", what);
        int nout = kind_nout(cases[q].kind);
        for (int k = 0; c && k < nout; k++) {
            CHECK_MSG(c->want[k] == cases[q].want[k], "%s: output %d expected %.17g, not %.17g", what, k,
                      c->want[k], cases[q].want[k]);
            double got[CASE_MAX_OUT];
            memcpy(got, cases[q].want, sizeof got);
            CHECK_MSG(case_is_right(cases[q].kind, c, got), "%s: the exact answer is wrong", what);
            for (int side = -1; side <= 1; side += 2) {
                double unit = side * 1e-9 * cases[q].scale[k], want = cases[q].want[k];
                got[k] = want + 0.9 * unit;
                CHECK_MSG(case_is_right(cases[q].kind, c, got), "%s: output %d off by 0.9 of the tolerance "
                          "(%.3g) is judged wrong", what, k, 0.9 * unit);
                got[k] = unit ? want + 1.1 * unit : nextafter(want, side * INFINITY);
                CHECK_MSG(!case_is_right(cases[q].kind, c, got), "%s: output %d off by %.3g (1.1 of the "
                          "tolerance, or the least double) is judged right", what, k, got[k] - want);
                got[k] = want;
            }
        }
        testlist_free(&list);
    }
}

/* The order of the tests' files does not matter: a failed test that two
 * mistakes fit, judged before the test that names one of them, names it
 * once the part's every test is judged (check_part_again), with the same
 * message as if it had been judged after, and the rest of its output kept.
 * A test named already, or whose mistakes nothing tells apart, is left. */
static void test_part_again(void)
{
    static const char A[] = "mistake A", B[] = "mistake B";
    const char *both[] = { A, B }, *a_only[] = { A };
    TestList list = { 0 };
    hit_case(testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: A or B"), both, 2);
    hit_case(testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: plain hits"), NULL, 0);
    hit_case(testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: A alone"), a_only, 1);
    hit_case(testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: A or B again"), both, 2);
    /* Each failed test's second case a hit that both mistakes get right:
     * answers with a hit among them, which may name a mistake alone. */
    for (int k = 0; k < 4; k++)
        if (k != 1)
            hit_case(&list.tests[k], NULL, 0);
    const char answers[] = "0x0p+0 0x0p+0\n0x1p+0 0x1p+2\nend 2\n";
    const Test *passed[] = { &list.tests[1] };
    const char *named_a[] = { A };

    /* Judged in the files' order: only "A alone" names A. */
    TestResult r[4];
    memset(r, 0, sizeof r);
    r[1].ran = r[1].passed = true;
    for (int k = 0; k < 4; k++) {
        if (k == 1)
            continue;
        PartSoFar so_far = { passed, 1, named_a, k > 2 };
        char *v = NULL;
        check_answers_in_part(&list.tests[k], answers, sizeof answers - 1, &so_far, &v, &r[k].answers);
        r[k].ran = true;
        r[k].verdict_at = strlen("  about: a note\n");
        r[k].verdict_len = strlen(v);
        size_t n = r[k].verdict_at + r[k].verdict_len + 40;
        r[k].output = malloc(n);
        snprintf(r[k].output, n, "  about: a note\n%s  your code printed:\n    hi\n", v);
        free(v);
    }
    CHECK(r[2].answers.named && strcmp(r[2].answers.named, A) == 0);
    CHECK_MSG(!r[0].answers.named, "judged first, A or B named %s", r[0].answers.named);
    CHECK(r[3].answers.named && strcmp(r[3].answers.named, A) == 0);

    /* Judged again: A or B names A, in the words "A or B again" got. */
    char *again = strdup(r[3].output);
    check_part_again(&list, r, PART5);
    CHECK_MSG(r[0].answers.named && strcmp(r[0].answers.named, A) == 0, "judged again, named %s",
              r[0].answers.named ? r[0].answers.named : "nothing");
    CHECK_MSG(strcmp(r[0].output, again) == 0, "the message is\n%s\nnot\n%s", r[0].output, again);
    CHECK_MSG(strcmp(r[3].output, again) == 0, "a test named already changed:\n%s", r[3].output);
    free(again);

    /* Nothing tells A and B apart when no other test names either. */
    for (int k = 0; k < 4; k++) {
        free(r[k].output);
        answers_free(&r[k].answers);
    }
    memset(r, 0, sizeof r);
    r[1].ran = r[1].passed = true;
    PartSoFar alone = { passed, 1, NULL, 0 };
    char *v = NULL;
    check_answers_in_part(&list.tests[0], answers, sizeof answers - 1, &alone, &v, &r[0].answers);
    r[0].ran = true;
    r[0].output = strdup(v);
    r[0].verdict_len = strlen(v);
    check_part_again(&list, r, PART5);
    CHECK(!r[0].answers.named && strcmp(r[0].output, v) == 0);
    free(v);
    free(r[0].output);
    answers_free(&r[0].answers);
    testlist_free(&list);
}

/* Where no known mistake explains a test, a hit at t <= 0, NaN or
 * infinity is told as what it is for the case shown. */
static void test_hit_not_ahead(void)
{
    static const struct {
        const char *answers, *told;
    } cases[] = {
        { "0x1p+0 0x0p+0\nend 1\n", "a hit at t = 0 is at the ray's origin: only t > 0 is a hit" },
        { "0x1p+0 -0x1.8p+1\nend 1\n", "a hit at t = -3 is behind the ray's origin: only t > 0 is a hit" },
        { "0x1p+0 nan\nend 1\n", "a hit at t = NaN: a hit needs t > 0" },
        { "0x1p+0 inf\nend 1\n", "a hit at t = inf is no point of the ray: t must be finite. A division "
                                  "by det = 0 (a ray parallel to the triangle) gives it: that is a miss" },
    };
    TestList list = { 0 };
    hit_case(testlist_add(&list, PART5, KIND_TRIANGLE, "Part 5: a test"), NULL, 0);
    for (int k = 0; k < CHECK_COUNT(cases); k++) {
        char *out = NULL;
        CHECK(!check_answers(&list.tests[0], cases[k].answers, strlen(cases[k].answers), &out, NULL));
        CHECK_STR_CONTAINS(out, cases[k].told);
        free(out);
    }
    testlist_free(&list);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_pieces),
    CHECK_TEST(test_refused),
    CHECK_TEST(test_two_mistakes_fit),
    CHECK_TEST(test_one_mistake_fits),
    CHECK_TEST(test_core_tolerances),
    CHECK_TEST(test_part_again),
    CHECK_TEST(test_hit_not_ahead),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
