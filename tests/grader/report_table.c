/*
 * report_table.c - the grader's table for humans, in the manner of xv6's
 * `make grade`: per part a subtotal, each test PASS or FAIL, and under each
 * failure what went wrong.
 *
 * Short by default, so that the first failures are read and not scrolled
 * past: a part not written yet is one line; a part shows at most
 * SHOWN_IN_FULL failing tests in full, the others by name; its hard cases
 * (the extra credit) come after its core tests, as one line while a core
 * test fails; a hint that the answers of several tests of Parts 4 and 5
 * give is said once, at the top of the part.  Every failure is in full on
 * the report page, and here with every_failure (grade --all-failures).
 */
#include "report.h"
#include "terminal.h"

#include <string.h>

#define SHOWN_IN_FULL 3            /* failing tests of a group shown in full */
#define HINTS_ON_TOP 6             /* distinct hints said at a part's top    */
#define HINT_LINE "    hint:      "

/* text under its heading (if not NULL), each line indented by four
 * spaces (it is indented by two already: this keeps it tidy); with
 * strip_hints, without its hint lines (said at the part's top). */
static void print_indented(FILE *f, const char *heading, const char *text, bool strip_hints)
{
    const char *p = text;
    if (heading)
        fprintf(f, "  %s:\n", heading);
    while (*p) {
        const char *nl = strchr(p, '\n');
        size_t n = nl ? (size_t)(nl - p) : strlen(p);
        if (!strip_hints || strncmp(p, HINT_LINE, strlen(HINT_LINE)) != 0) {
            fputs("    ", f);
            term_put(f, p, n);
            fputc('\n', f);
        }
        p += n + (nl ? 1 : 0);
    }
}

/* A part whose file did not build, when none of its tests passed: one
 * line for them all and the compiler's (or the grader's) words once, where
 * each test's own line would only repeat that it could not run.  Returns
 * false, printing nothing, when some test passed. */
static bool unbuilt(FILE *f, const Grade *g, int p)
{
    int n = 0, hard = 0;
    for (int k = 0; k < g->tests->n; k++) {
        const Test *t = &g->tests->tests[k];
        if (t->part != p)
            continue;
        if (g->results[k].passed)
            return false;
        n++;
        hard += t->hard;
    }
    char why[200];
    grade_unbuilt_why(g, p, false, why, sizeof why);
    fprintf(f, "  FAIL  all %d tests (%d core, %d hard cases): %s, so none could run:\n", n, n - hard,
            hard, why);
    if (g->build_messages[p])
        print_indented(f, NULL, g->build_messages[p], false);
    return true;
}

/* The end of the number that starts at s (digits, a point, an exponent). */
static const char *past_number(const char *s, const char *end)
{
    while (s < end && ((*s >= '0' && *s <= '9') || *s == '.' ||
                       ((*s == 'e' || *s == '-' || *s == '+') && s + 1 < end && s[1] >= '0' && s[1] <= '9')))
        s++;
    return s;
}

/* Whether two hints say the same but for their numbers ("t = 0.67 is a
 * float" and "t = 34.1 is a float"). */
static bool same_hint(const char *a, size_t la, const char *b, size_t lb)
{
    const char *ea = a + la, *eb = b + lb;
    while (a < ea && b < eb) {
        bool na = *a >= '0' && *a <= '9', nb = *b >= '0' && *b <= '9';
        if (na && nb) {
            a = past_number(a, ea);
            b = past_number(b, eb);
        } else if (*a++ != *b++) {
            return false;
        }
    }
    return a == ea && b == eb;
}

/* The hint lines of the part's failed tests (Parts 4 and 5 give one per
 * test), of the core tests and, with hard, the hard cases', each said once
 * (the first of those that differ only in their numbers) with the number of
 * tests that give it, at the top of the part.  Returns whether there were
 * any. */
static bool hints_on_top(FILE *f, const Grade *g, int p, bool hard)
{
    const char *text[HINTS_ON_TOP];
    size_t len[HINTS_ON_TOP];
    int count[HINTS_ON_TOP], n = 0, more = 0;
    for (int k = 0; k < g->tests->n; k++) {
        const TestResult *r = &g->results[k];
        if (g->tests->tests[k].part != p || r->passed || !r->output || (g->tests->tests[k].hard && !hard))
            continue;
        for (const char *h = strstr(r->output, HINT_LINE); h; h = strstr(h + 1, HINT_LINE)) {
            const char *at = h + strlen(HINT_LINE);
            size_t l = strcspn(at, "\n");
            int q = 0;
            while (q < n && !same_hint(text[q], len[q], at, l))
                q++;
            if (q < n)
                count[q]++;
            else if (n < HINTS_ON_TOP)
                text[n] = at, len[n] = l, count[n++] = 1;
            else
                more++;
        }
    }
    if (n == 0)
        return false;
    fprintf(f, "  What the answers show (each hint once; under the failed tests on the report page):\n");
    for (int q = 0; q < n; q++) {
        fputs("    - ", f);
        term_put(f, text[q], len[q]);
        fprintf(f, " (%d test%s)\n", count[q], count[q] == 1 ? "" : "s");
    }
    if (more)
        fprintf(f, "    and %d more (the report page)\n", more);
    return true;
}

/* The tests of part p in group hard (core or hard cases): each failure, the
 * first SHOWN_IN_FULL of them in full (all with every_failure), the others
 * by name; and each core test passed, by name (hard cases passed are
 * counted).  Returns how many failures were not shown in full. */
static int tests_of(FILE *f, const Grade *g, int p, bool hard, bool strip_hints, bool every_failure)
{
    int in_full = 0, by_name = 0, passed = 0;
    for (int k = 0; k < g->tests->n; k++) {
        const Test *t = &g->tests->tests[k];
        const TestResult *r = &g->results[k];
        if (t->part != p || t->hard != hard)
            continue;
        if (r->passed && hard && !every_failure) {
            passed++;
            continue;
        }
        fprintf(f, "  %s  ", r->passed ? "PASS" : "FAIL");
        term_put(f, t->name, strlen(t->name));
        fprintf(f, "%s%s\n", t->hard ? "  [hard]" : "", t->hidden ? "  [hidden]" : "");
        if (r->passed || !r->output || !*r->output)
            continue;
        if (in_full < SHOWN_IN_FULL || every_failure) {
            print_indented(f, NULL, r->output, strip_hints);
            in_full++;
        } else {
            by_name++;
        }
    }
    if (passed)
        fprintf(f, "  and %d hard-case test%s passed\n", passed, passed == 1 ? "" : "s");
    return by_name;
}

/* The part's hard cases, after its core tests: their points, and while a
 * core test fails, nothing more; else the causes that explain them alone
 * and their tests.  Returns how many failures were not shown in full. */
static int hard_cases(FILE *f, const Grade *g, const GradeConfig *cfg, int p, bool strip_hints,
                      bool every_failure)
{
    if (g->hard_max[p] <= 0)
        return 0;
    int failed = 0, total = 0;
    for (int k = 0; k < g->tests->n; k++)
        if (g->tests->tests[k].part == p && g->tests->tests[k].hard) {
            total++;
            failed += !g->results[k].passed;
        }
    fprintf(f, "  %s: %s / %s", cfg->hard_is_bonus ? "Hard cases (extra credit)" : "Hard cases",
            points_text(g->hard[p]).s, points_text(g->hard_max[p]).s);
    if (g->core[p] < g->core_max[p] && !every_failure) {
        fprintf(f, ", %d of %d tests failed: shown once the core tests pass\n", failed, total);
        return 0;
    }
    fprintf(f, "%s\n", failed ? "" : ", every test passed");
    if (failed == 0 && !every_failure)
        return 0;
    if (g->diagnosis_hard[p])
        print_indented(f, "About them (probes run on your code confirmed it)", g->diagnosis_hard[p], false);
    return tests_of(f, g, p, true, strip_hints, every_failure);
}

/* One part: its points, what went wrong, its core tests, its hard cases. */
static void part_table(FILE *f, const Grade *g, const GradeConfig *cfg, int p, bool every_failure)
{
    fprintf(f, "\n%s   %s / %s", part_title(p), points_text(g->core[p]).s, points_text(g->core_max[p]).s);
    bool unwritten = g->causes[p] && strcmp(g->causes[p], "unwritten") == 0;
    if (unwritten && !every_failure) {
        fprintf(f, "   not written yet: every answer is the skeleton's, whatever the input\n");
        return;
    }
    fprintf(f, "\n");
    bool core_lost = g->core[p] < g->core_max[p];
    if (g->diagnosis[p] && core_lost)
        print_indented(f, "What went wrong (probes run on your code confirmed it)", g->diagnosis[p], false);
    if (grade_warned(g, p))
        print_indented(f, "The compiler warned (a warning often points at a mistake)", g->build_messages[p],
                       false);
    if (!g->built[p] && unbuilt(f, g, p))
        return;
    bool strip = !every_failure && hints_on_top(f, g, p, !core_lost);
    int more = tests_of(f, g, p, false, strip, every_failure);
    more += hard_cases(f, g, cfg, p, strip, every_failure);
    if (more)
        fprintf(f, "  (%d more failed test%s by name only: each in full on the report page, and with "
                   "make grade FAILURES=all)\n", more, more == 1 ? "" : "s");
}

void report_table(FILE *f, const Grade *g, const GradeConfig *cfg, const char *submission, bool every_failure)
{
    fputs("Grading ", f);
    term_put(f, submission, strlen(submission));
    fputc('\n', f);
    for (int p = 0; p < NPARTS; p++)
        if (g->graded[p])
            part_table(f, g, cfg, p, every_failure);
    fprintf(f, "\nScore: %s / %s", points_text(g->total).s, points_text(g->total_max).s);
    if (g->bonus_max > 0)
        fprintf(f, "   hard-case bonus: %s / %s", points_text(g->bonus).s, points_text(g->bonus_max).s);
    fprintf(f, "   (%.1f s)\n", g->seconds);
    if (g->total >= g->total_max && g->bonus < g->bonus_max)
        fprintf(f, "All the core points. Some hard cases failed, which count only as extra credit:\n"
                   "that is why the grader exits with status 1 (make says Error 1).\n");
}
