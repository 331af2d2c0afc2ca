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
#include <stdlib.h>
#include <string.h>

#define SUMMARY_MAX 16383

static void test_entry(JsonWriter *j, const Test *t, const TestResult *r)
{
    json_begin_object(j);
    json_member_string(j, "name", t->name);
    json_member_number(j, "score", r->score);
    json_member_number(j, "max_score", r->max_score);
    json_member_string(j, "status", r->passed ? "passed" : "failed");
    json_member_string(j, "output", r->passed ? "" : (r->output ? r->output : ""));
    json_key(j, "tags");
    json_begin_array(j);
    char tag[16];
    snprintf(tag, sizeof tag, "part%s", part_label(t->part));
    json_string(j, tag);
    if (t->hard)
        json_string(j, "hard");
    json_end_array(j);
    json_member_string(j, "visibility", t->hidden ? "after_published" : "visible");
    json_end_object(j);
}

int report_json(const char *path, const Grade *g, char *err, size_t errlen)
{
    JsonWriter j;
    json_init(&j, 2);
    json_begin_object(&j);
    json_member_number(&j, "score", g->total + g->bonus);
    json_member_number(&j, "execution_time", g->seconds);
    /* The output is cut to SUMMARY_MAX bytes.  It names no folder: on
     * Gradescope the submission's is a temporary one, meaningless to the
     * student who reads this. */
    char *summary = NULL;
    appendf(&summary, "Score: %s / %s", points_text(g->total).s,
            points_text(g->total_max).s);
    if (g->bonus_max > 0)
        appendf(&summary, ", hard-case bonus %s / %s", points_text(g->bonus).s,
                points_text(g->bonus_max).s);
    for (int p = 0; p < NPARTS; p++)
        if (g->graded[p])
            appendf(&summary, "\nPart %s: %s / %s", part_label(p), points_text(g->core[p]).s,
                    points_text(g->core_max[p]).s);
    /* A part that did not build: why, once, above its tests (each of which
     * says only that it could not run). */
    for (int p = 0; p < NPARTS; p++) {
        if (!g->graded[p] || g->built[p])
            continue;
        char why[200];
        grade_unbuilt_why(g, p, false, why, sizeof why);
        appendf(&summary, "\n\nPart %s: %s, so none of its tests could run:\n%s", part_label(p), why,
                g->build_messages[p] ? g->build_messages[p] : "");
    }
    for (int p = 0; p < NPARTS; p++)
        if (g->diagnosis[p] && g->core[p] < g->core_max[p])
            appendf(&summary, "\n\nPart %s, what went wrong (probes run on your code confirmed it):\n%s",
                    part_label(p), g->diagnosis[p]);
    for (int p = 0; p < NPARTS; p++)
        if (g->diagnosis_hard[p])
            appendf(&summary, "\n\nPart %s, the hard cases (extra credit; probes run on your code "
                    "confirmed it):\n%s", part_label(p), g->diagnosis_hard[p]);
    for (int p = 0; p < NPARTS; p++)
        if (grade_warned(g, p))
            appendf(&summary, "\n\nPart %s, the compiler warned (a warning often points at a "
                    "mistake):\n%s", part_label(p), g->build_messages[p]);
    size_t n = summary ? strlen(summary) : 0;
    json_key(&j, "output");
    json_string_bytes(&j, summary ? summary : "", n < SUMMARY_MAX ? n : SUMMARY_MAX);
    free(summary);
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
    json_member_string(&j, "jail", jail_describe());
    json_end_object(&j);
    json_key(&j, "tests");
    json_begin_array(&j);
    for (int k = 0; k < g->tests->n; k++)
        if (g->graded[g->tests->tests[k].part])
            test_entry(&j, &g->tests->tests[k], &g->results[k]);
    json_end_array(&j);
    json_end_object(&j);
    return json_write_file(&j, path, err, errlen);
}

int report_json_error(const char *path, const char *message, char *err, size_t errlen)
{
    JsonWriter j;
    json_init(&j, 2);
    json_begin_object(&j);
    json_member_number(&j, "score", 0);
    return report_json_error_end(&j, path, message, err, errlen);
}

int report_json_error_end(JsonWriter *j, const char *path, const char *message, char *err, size_t errlen)
{
    json_member_string(j, "output", message);
    json_key(j, "tests");
    json_begin_array(j);
    json_end_array(j);
    json_end_object(j);
    return json_write_file(j, path, err, errlen);
}
