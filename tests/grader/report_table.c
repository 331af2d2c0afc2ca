/*
 * report_table.c - the grader's table for humans, in the manner of xv6's
 * `make grade`: per part a subtotal, each test PASS or FAIL, and under each
 * failure what went wrong.
 */
#include "report.h"

#include <string.h>

static void print_indented(FILE *f, const char *text)
{
    /* text is already indented by two spaces per line; keep it tidy */
    const char *p = text;
    while (*p) {
        const char *nl = strchr(p, '\n');
        size_t n = nl ? (size_t)(nl - p) : strlen(p);
        fprintf(f, "    %.*s\n", (int)n, p);
        p += n + (nl ? 1 : 0);
    }
}

void report_table(FILE *f, const Grade *g, const GradeConfig *cfg, const char *submission)
{
    fprintf(f, "Grading %s\n", submission);
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
        for (int group = 0; group < 2; group++)
            for (int k = 0; k < g->tests->n; k++) {
                const Test *t = &g->tests->tests[k];
                const TestResult *r = &g->results[k];
                if (t->part != p || t->hard != group)
                    continue;
                fprintf(f, "  %s  %s%s%s\n", r->passed ? "PASS" : "FAIL", t->name,
                        t->hard ? "  [hard]" : "", t->hidden ? "  [hidden]" : "");
                if (!r->passed && r->output && *r->output)
                    print_indented(f, r->output);
            }
    }
    fprintf(f, "\nScore: %s / %s", points_text(g->total).s, points_text(g->total_max).s);
    if (g->bonus_max > 0)
        fprintf(f, "   hard-case bonus: %s / %s", points_text(g->bonus).s, points_text(g->bonus_max).s);
    fprintf(f, "   (%.1f s)\n", g->seconds);
}
