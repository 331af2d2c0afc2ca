/*
 * report_table.c - the grader's table for humans, in the manner of xv6's
 * `make grade`: per part a subtotal, each test PASS or FAIL, and under each
 * failure what went wrong.
 */
#include "report.h"
#include "markup.h"

#include <string.h>

/* Writes n bytes of text for a terminal.  What a student's code printed,
 * and the compiler's and linker's words about it (a symbol's name, say),
 * are the student's to choose, escape sequences and all (which set the
 * window's title, write the clipboard, move the cursor...): a control
 * character other than newline and tab is shown as ^X (ESC as ^[, DEL as
 * ^?), and a byte that is not valid UTF-8 or a C1 control (U+0080 to
 * U+009F, which some terminals obey too) as '?'. */
static void put_text(FILE *f, const char *text, size_t n)
{
    const unsigned char *s = (const unsigned char *)text;
    size_t k = 0;
    while (k < n) {
        unsigned char c = s[k];
        size_t len = 1;
        if (c == 0x7F) {
            fputs("^?", f);
        } else if (c < 0x20 && c != '\n' && c != '\t') {
            fputc('^', f);
            fputc(c + 64, f);
        } else if (c < 0x80) {
            fputc(c, f);
        } else {
            int u = utf8_length(s + k, n - k);
            bool c1 = u == 2 && c == 0xC2 && s[k + 1] < 0xA0;
            if (u > 0 && !c1)
                fwrite(s + k, 1, (size_t)u, f);
            else
                fputc('?', f);
            len = u > 0 ? (size_t)u : 1;
        }
        k += len;
    }
}

static void print_indented(FILE *f, const char *text)
{
    /* text is already indented by two spaces per line; keep it tidy */
    const char *p = text;
    while (*p) {
        const char *nl = strchr(p, '\n');
        size_t n = nl ? (size_t)(nl - p) : strlen(p);
        fputs("    ", f);
        put_text(f, p, n);
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
    grade_unbuilt_why(g, p, why, sizeof why);
    fprintf(f, "  FAIL  all %d tests (%d core, %d hard cases): %s, so none could run:\n", n, n - hard,
            hard, why);
    if (g->build_messages[p])
        print_indented(f, g->build_messages[p]);
    return true;
}

void report_table(FILE *f, const Grade *g, const GradeConfig *cfg, const char *submission)
{
    fputs("Grading ", f);
    put_text(f, submission, strlen(submission));
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
                put_text(f, t->name, strlen(t->name));
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
