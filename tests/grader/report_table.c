/*
 * report_table.c - the grader's table for humans, in the manner of xv6's
 * `make grade`: per part a subtotal, each test PASS or FAIL, and under each
 * failure what went wrong.
 */
#include "report.h"
#include "terminal.h"

#include <string.h>

static void print_indented(FILE *f, const char *text)
{
    /* text is already indented by two spaces per line; keep it tidy */
    const char *p = text;
    while (*p) {
        const char *nl = strchr(p, '\n');
        size_t n = nl ? (size_t)(nl - p) : strlen(p);
        fputs("    ", f);
        term_put(f, p, n);
        fputc('\n', f);
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
        print_indented(f, g->build_messages[p]);
    return true;
}

void report_table(FILE *f, const Grade *g, const GradeConfig *cfg, const char *submission)
{
    fputs("Grading ", f);
    term_put(f, submission, strlen(submission));
    fputc('\n', f);
    for (int p = 0; p < NPARTS; p++) {
        if (!g->graded[p])
            continue;
        fprintf(f, "\n%s   %s / %s", part_title(p), points_text(g->core[p]).s, points_text(g->core_max[p]).s);
        if (g->hard_max[p] > 0)
            fprintf(f, "   (hard cases: %s / %s%s)", points_text(g->hard[p]).s, points_text(g->hard_max[p]).s,
                    cfg->hard_is_bonus ? " bonus" : "");
        fprintf(f, "\n");
        if (g->diagnosis[p]) {
            fprintf(f, "  What went wrong (probes run on your code confirmed it):\n");
            print_indented(f, g->diagnosis[p]);
        }
        if (grade_warned(g, p)) {
            fprintf(f, "  The compiler warned (a warning often points at a mistake):\n");
            print_indented(f, g->build_messages[p]);
        }
        if (!g->built[p] && unbuilt(f, g, p))
            continue;
        for (int group = 0; group < 2; group++)
            for (int k = 0; k < g->tests->n; k++) {
                const Test *t = &g->tests->tests[k];
                const TestResult *r = &g->results[k];
                if (t->part != p || t->hard != group)
                    continue;
                fprintf(f, "  %s  ", r->passed ? "PASS" : "FAIL");
                term_put(f, t->name, strlen(t->name));
                fprintf(f, "%s%s\n", t->hard ? "  [hard]" : "", t->hidden ? "  [hidden]" : "");
                if (!r->passed && r->output && *r->output)
                    print_indented(f, r->output);
            }
    }
    fprintf(f, "\nScore: %s / %s", points_text(g->total).s, points_text(g->total_max).s);
    if (g->bonus_max > 0)
        fprintf(f, "   hard-case bonus: %s / %s", points_text(g->bonus).s, points_text(g->bonus_max).s);
    fprintf(f, "   (%.1f s)\n", g->seconds);
    if (g->total >= g->total_max && g->bonus < g->bonus_max)
        fprintf(f, "All the core points. Some hard cases failed, which count only as extra credit:\n"
                   "that is why the grader exits with status 1 (make says Error 1).\n");
}
