/*
 * report_json.c - the Gradescope results.json: top-level score,
 * execution_time, output and tests, each test with name, score, max_score,
 * output, tags and visibility.  Written through a temporary file renamed
 * into place, by the grader alone, after every part is graded.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "report.h"
#include "jail.h"
#include "../tools/json.h"

#include <stdio.h>
#include <string.h>

static void test_entry(JsonWriter *j, const Test *t, const TestResult *r)
{
    json_begin_object(j);
    json_key(j, "name");
    json_string(j, t->name);
    json_key(j, "score");
    json_number(j, r->score);
    json_key(j, "max_score");
    json_number(j, r->max_score);
    json_key(j, "status");
    json_string(j, r->passed ? "passed" : "failed");
    json_key(j, "output");
    json_string(j, r->passed ? "" : (r->output ? r->output : ""));
    json_key(j, "tags");
    json_begin_array(j);
    char tag[16];
    snprintf(tag, sizeof tag, "part%s", part_label(t->part));
    json_string(j, tag);
    if (t->hard)
        json_string(j, "hard");
    json_end_array(j);
    json_key(j, "visibility");
    json_string(j, t->hidden ? "after_published" : "visible");
    json_end_object(j);
}

int report_json(const char *path, const Grade *g, const char *submission, char *err, size_t errlen)
{
    JsonWriter j;
    json_init(&j, 2);
    json_begin_object(&j);
    json_key(&j, "score");
    json_number(&j, g->total + g->bonus);
    json_key(&j, "execution_time");
    json_number(&j, g->seconds);
    char summary[16384];
    int n = snprintf(summary, sizeof summary, "Graded %s: %s / %s", submission, points_text(g->total).s,
                     points_text(g->total_max).s);
    if (g->bonus_max > 0)
        n += snprintf(summary + n, sizeof summary - (size_t)n, ", hard-case bonus %s / %s",
                      points_text(g->bonus).s, points_text(g->bonus_max).s);
    for (int p = 0; p < NPARTS; p++) {
        if (!g->graded[p] || (size_t)n >= sizeof summary)
            continue;
        n += snprintf(summary + n, sizeof summary - (size_t)n, "\nPart %s: %s / %s", part_label(p),
                      points_text(g->core[p]).s, points_text(g->core_max[p]).s);
    }
    /* A part that did not build: why, once, above its tests (each of which
     * says only that it could not run). */
    for (int p = 0; p < NPARTS; p++) {
        if (!g->graded[p] || g->built[p] || (size_t)n >= sizeof summary)
            continue;
        char why[200];
        grade_unbuilt_why(g, p, false, why, sizeof why);
        n += snprintf(summary + n, sizeof summary - (size_t)n, "\n\nPart %s: %s, so none of its tests "
                      "could run:\n%s", part_label(p), why, g->build_messages[p] ? g->build_messages[p] : "");
    }
    for (int p = 0; p < NPARTS; p++) {
        if (!g->diagnosis[p] || g->core[p] >= g->core_max[p] || (size_t)n >= sizeof summary)
            continue;
        n += snprintf(summary + n, sizeof summary - (size_t)n,
                      "\n\nPart %s, what went wrong (probes run on your code confirmed it):\n%s",
                      part_label(p), g->diagnosis[p]);
    }
    for (int p = 0; p < NPARTS; p++) {
        if (!g->diagnosis_hard[p] || (size_t)n >= sizeof summary)
            continue;
        n += snprintf(summary + n, sizeof summary - (size_t)n,
                      "\n\nPart %s, the hard cases (extra credit; probes run on your code confirmed it):\n%s",
                      part_label(p), g->diagnosis_hard[p]);
    }
    for (int p = 0; p < NPARTS; p++) {
        if (!grade_warned(g, p) || (size_t)n >= sizeof summary)
            continue;
        n += snprintf(summary + n, sizeof summary - (size_t)n,
                      "\n\nPart %s, the compiler warned (a warning often points at a mistake):\n%s",
                      part_label(p), g->build_messages[p]);
    }
    json_key(&j, "output");
    json_string(&j, summary);
    /* The causes' keys (tests/selftest/README.md), for instructors' tools. */
    json_key(&j, "extra_data");
    json_begin_object(&j);
    json_key(&j, "causes");
    json_begin_object(&j);
    for (int p = 0; p < NPARTS; p++) {
        if (!g->causes[p])
            continue;
        json_key(&j, part_label(p));
        json_string(&j, g->causes[p]);
    }
    json_end_object(&j);
    /* Where the submission's code ran (jail.h), and what that guarantees. */
    json_key(&j, "jail");
    json_string(&j, jail_describe());
    json_end_object(&j);
    json_key(&j, "tests");
    json_begin_array(&j);
    for (int k = 0; k < g->tests->n; k++)
        if (g->graded[g->tests->tests[k].part])
            test_entry(&j, &g->tests->tests[k], &g->results[k]);
    json_end_array(&j);
    json_end_object(&j);
    int status = json_write_file(&j, path, err, errlen);
    json_free(&j);
    return status;
}

int report_json_error(const char *path, const char *message, char *err, size_t errlen)
{
    JsonWriter j;
    json_init(&j, 2);
    json_begin_object(&j);
    json_key(&j, "score");
    json_number(&j, 0);
    return report_json_error_end(&j, path, message, err, errlen);
}

int report_json_error_end(JsonWriter *j, const char *path, const char *message, char *err, size_t errlen)
{
    json_key(j, "output");
    json_string(j, message);
    json_key(j, "tests");
    json_begin_array(j);
    json_end_array(j);
    json_end_object(j);
    int status = json_write_file(j, path, err, errlen);
    json_free(j);
    return status;
}
