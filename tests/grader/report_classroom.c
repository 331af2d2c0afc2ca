/*
 * report_classroom.c - GitHub Classroom's runner results: one NAME=BASE64
 * line per runner, appended to a file ($GITHUB_OUTPUT in a workflow).
 * See report_classroom.h for the runners and why their totals are the
 * kit's core score.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "report_classroom.h"
#include "../tools/base64.h"
#include "../tools/json.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Bytes of the grader's message kept per test: a runner's results reach
 * the reporter in one environment variable, which Linux limits to 128 KB,
 * and the runner "hard" holds every hard case. */
#define MESSAGE_MAX 1000
#define HARD_MESSAGE_MAX 200

/* The reporter's word for a test: pass, fail, or error when the test did
 * not run (its file is missing or did not build, or it was skipped). */
static const char *status_word(const TestResult *r)
{
    return r->passed ? "pass" : r->ran ? "fail" : "error";
}

/* One test of a runner.  The reporter prints the message of an "error"
 * test and the test_code of any test: a test that did not pass gets the
 * command that shows its details. */
static void test_entry(JsonWriter *j, const Test *t, const TestResult *r, bool counted, size_t max)
{
    json_begin_object(j);
    json_member_string(j, "name", t->name);
    json_member_string(j, "status", status_word(r));
    json_member_number(j, "score", counted ? r->score : 0);
    json_key(j, "message");
    if (r->passed)
        json_string(j, "");
    else if (t->hidden)
        json_string(j, "a hidden test: its details are not shown");
    else {
        const char *out = r->output ? r->output : "";
        size_t n = strlen(out);
        json_string_bytes(j, out, n < max ? n : max);
    }
    json_member_int(j, "line_no", 0);     /* 0: the reporter prints no line number */
    if (!r->passed) {
        char code[64];
        snprintf(code, sizeof code, "make grade PART=%s", part_label(t->part));
        json_member_string(j, "test_code", code);
    }
    json_end_object(j);
}

/* Appends "name=" and the base64 of the runner's JSON, and a newline. */
static int add_line(KitBuf *out, const char *name, JsonWriter *j)
{
    size_t len;
    const char *text = json_text(j, &len);
    if (!text)
        return -1;
    size_t n = base64_encoded_length(len);
    char *coded = malloc(n + 1);
    if (!coded)
        return -1;
    base64_encode(text, len, coded);
    int status = kit_buf_append(out, name, strlen(name)) || kit_buf_push(out, '=') ||
                 kit_buf_append(out, coded, n) || kit_buf_push(out, '\n') ? -1 : 0;
    free(coded);
    return status;
}

/* A runner's JSON up to its list of tests, which runner_end ends. */
static void runner_begin(JsonWriter *j, const char *status, double max_score)
{
    json_init(j, 0);
    json_begin_object(j);
    json_member_int(j, "version", 1);
    json_member_string(j, "status", status);
    json_member_number(j, "max_score", max_score);
    json_key(j, "tests");
    json_begin_array(j);
}

/* Ends the runner's JSON and appends its line (add_line). */
static int runner_end(KitBuf *out, const char *name, JsonWriter *j)
{
    json_end_array(j);
    json_end_object(j);
    int status = add_line(out, name, j);
    json_free(j);
    return status;
}

/* The runner "hard": every hard-case test of the graded parts, worth 0
 * here (the reporter would otherwise divide by no tests, so an empty list
 * gets one line saying so). */
static int hard_runner(KitBuf *out, const Grade *g)
{
    JsonWriter j;
    runner_begin(&j, "pass", 0);          /* extra credit never fails the workflow */
    int n = 0;
    for (int k = 0; k < g->tests->n; k++) {
        const Test *t = &g->tests->tests[k];
        if (g->graded[t->part] && t->hard) {
            test_entry(&j, t, &g->results[k], false, HARD_MESSAGE_MAX);
            n++;
        }
    }
    if (n == 0) {
        json_begin_object(&j);
        json_member_string(&j, "name", "no hard cases are graded");
        json_member_string(&j, "status", "pass");
        json_member_int(&j, "score", 0);
        json_member_int(&j, "line_no", 0);
        json_end_object(&j);
    }
    return runner_end(out, "hard", &j);
}

int report_classroom(const char *path, const Grade *g, char *err, size_t errlen)
{
    KitBuf out;
    kit_buf_init(&out);
    int status = 0;
    for (int p = 0; p < NPARTS && status == 0; p++) {
        if (!g->graded[p])
            continue;
        int index = 0;
        for (int k = 0; k < g->tests->n && status == 0; k++) {
            const Test *t = &g->tests->tests[k];
            if (t->part != p || t->hard)
                continue;
            /* The runner of one core test. */
            char name[32];
            JsonWriter j;
            snprintf(name, sizeof name, "part%stest%d", part_label(p), ++index);
            runner_begin(&j, status_word(&g->results[k]), g->results[k].max_score);
            test_entry(&j, t, &g->results[k], true, MESSAGE_MAX);
            status = runner_end(&out, name, &j);
        }
    }
    if (status == 0)
        status = hard_runner(&out, g);
    /* One write of every line, appended: the file may hold other steps'
     * outputs already. */
    int fd = status == 0 ? open(path, O_WRONLY | O_APPEND | O_CREAT, 0666) : -1;
    const char *why = status != 0 ? "out of memory" : fd < 0 ? strerror(errno) : NULL;
    for (size_t done = 0; !why && done < out.len;) {
        ssize_t w = write(fd, out.data + done, out.len - done);
        if (w > 0)
            done += (size_t)w;
        else if (w == 0 || errno != EINTR)
            why = w < 0 ? strerror(errno) : "nothing written";
    }
    if (fd >= 0 && close(fd) != 0 && !why)
        why = strerror(errno);
    kit_buf_free(&out);
    if (!why)
        return 0;
    snprintf(err, errlen, "%s: %s", path, why);
    return -1;
}
