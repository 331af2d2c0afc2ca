/*
 * report_prairielearn.c - PrairieLearn's results.json.  See
 * report_prairielearn.h for the fields and the choice of "gradable".
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "report_prairielearn.h"
#include "report.h"
#include "../tools/json.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* PrairieLearn refuses results over 1 MB: each test's output is cut to
 * OUTPUT_MAX bytes, and to a quarter of that if the whole is still over
 * RESULTS_MAX. */
#define OUTPUT_MAX 3000
#define RESULTS_MAX (900 * 1024)

/* Whether any test of a graded part ran: the submission could be graded. */
static bool any_test_ran(const Grade *g)
{
    for (int k = 0; k < g->tests->n; k++)
        if (g->graded[g->tests->tests[k].part] && g->results[k].ran)
            return true;
    return false;
}

/* A string cut to at most max bytes, with a note when cut. */
static void cut_string(JsonWriter *j, const char *s, size_t max)
{
    size_t n = s ? strlen(s) : 0;
    if (n <= max) {
        json_string(j, s ? s : "");
        return;
    }
    char *cut = NULL;
    appendf(&cut, "%.*s\n[... the rest cut]", (int)max, s);
    json_string(j, cut ? cut : "[output cut: out of memory]");
    free(cut);
}

static void test_entry(JsonWriter *j, const Test *t, const TestResult *r, size_t output_max)
{
    json_begin_object(j);
    json_member_string(j, "name", t->name);
    json_member_string(j, "description", t->hard ? "a hard case: extra credit, not counted in this "
                                                   "question's score"
                                                 : t->note[0] ? t->note : "");
    json_member_number(j, "points", t->hard ? 0 : r->score);
    json_member_number(j, "max_points", t->hard ? 0 : r->max_score);
    json_member_string(j, "message", r->passed ? "passed" : r->ran ? "failed" : "not run");
    json_key(j, "output");
    if (r->passed)
        json_string(j, "");
    else if (t->hidden)
        json_string(j, "This is a hidden test: its inputs and answers are not shown.");
    else
        cut_string(j, r->output, output_max);
    json_end_object(j);
}

/* The whole document, each test's output cut to output_max bytes. */
static void write_results(JsonWriter *j, const Grade *g, size_t output_max)
{
    double core = 0, core_max = 0, hard = 0, hard_max = 0;
    for (int p = 0; p < NPARTS; p++) {
        if (!g->graded[p])
            continue;
        core += g->core[p];
        core_max += g->core_max[p];
        hard += g->hard[p];
        hard_max += g->hard_max[p];
    }
    double score = core_max > 0 ? core / core_max : 0;
    score = score < 0 ? 0 : score > 1 ? 1 : score;
    bool gradable = any_test_ran(g);

    char *message = NULL, *output = NULL, *format_errors = NULL;
    if (gradable) {
        appendf(&message, "Core points: %s / %s.", points_text(core).s, points_text(core_max).s);
        if (hard_max > 0)
            appendf(&message, " Hard cases: %s / %s (extra credit, not counted here).", points_text(hard).s,
                    points_text(hard_max).s);
    } else {
        appendf(&message, "Nothing could be graded: no file of the graded parts could be built.");
    }
    for (int p = 0; p < NPARTS; p++) {
        if (!g->graded[p])
            continue;
        appendf(&output, "%s%s: %s / %s", output ? "\n" : "", part_title(p), points_text(g->core[p]).s,
                points_text(g->core_max[p]).s);
        if (g->hard_max[p] > 0)
            appendf(&output, "   (hard cases: %s / %s)", points_text(g->hard[p]).s,
                    points_text(g->hard_max[p]).s);
        appendf(&output, "\n");
        if (g->build_messages[p] && g->build_messages[p][0]) {
            if (grade_warned(g, p))
                appendf(&output, "The compiler warned (a warning often points at a mistake):\n");
            else if (!g->built[p]) {
                char why[200];
                grade_unbuilt_why(g, p, true, why, sizeof why);
                appendf(&output, "%s, so none of its tests could run:\n", why);
            }
            appendf(&output, "%s", g->build_messages[p]);
            if (!gradable)
                appendf(&format_errors, "Part %s: %s", part_label(p), g->build_messages[p]);
        }
        if (g->diagnosis[p] && g->core[p] < g->core_max[p])
            appendf(&output, "What went wrong (probes run on your code confirmed it):\n%s\n", g->diagnosis[p]);
        if (g->diagnosis_hard[p])
            appendf(&output, "The hard cases (extra credit; probes run on your code confirmed it):\n%s\n",
                    g->diagnosis_hard[p]);
    }
    appendf(&output, "\nCore points: %s / %s\n", points_text(core).s, points_text(core_max).s);

    json_begin_object(j);
    json_key(j, "gradable");
    json_bool(j, gradable);
    json_member_number(j, "score", gradable ? score : 0);
    json_member_string(j, "message", message ? message : "");
    if (!gradable) {
        json_key(j, "format_errors");
        cut_string(j, format_errors ? format_errors : "no stage file was submitted", 4 * OUTPUT_MAX);
    }
    json_key(j, "output");
    cut_string(j, output, 16 * OUTPUT_MAX);
    json_key(j, "tests");
    json_begin_array(j);
    for (int k = 0; k < g->tests->n; k++)
        if (g->graded[g->tests->tests[k].part])
            test_entry(j, &g->tests->tests[k], &g->results[k], output_max);
    json_end_array(j);
    json_end_object(j);
    free(message);
    free(output);
    free(format_errors);
}

int report_prairielearn(const char *path, const Grade *g, char *err, size_t errlen)
{
    JsonWriter j;
    size_t len = 0;
    json_init(&j, 2);
    write_results(&j, g, OUTPUT_MAX);
    if (json_text(&j, &len) && len > RESULTS_MAX) {
        json_free(&j);
        json_init(&j, 2);
        write_results(&j, g, OUTPUT_MAX / 4);
    }
    return json_write_file(&j, path, err, errlen);
}

int report_prairielearn_error(const char *path, const char *message, char *err, size_t errlen)
{
    JsonWriter j;
    json_init(&j, 2);
    json_begin_object(&j);
    json_key(&j, "gradable");
    json_bool(&j, false);
    json_member_number(&j, "score", 0);
    json_member_string(&j, "message", "The autograder could not grade this submission. Please tell the "
                                      "course staff.");
    json_member_string(&j, "format_errors", message);
    return report_json_error_end(&j, path, message, err, errlen);
}
