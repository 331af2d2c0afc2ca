/*
 * reporter_totals - GitHub Classroom's grading reporter's totals, worked
 * out from a workflow's runner results the way the reporter works them out,
 * for tests/suites/classroom.sh.
 *
 *   reporter_totals RUNNERS ENVFILE
 *   reporter_totals --dump RUNNERS ENVFILE
 *
 * RUNNERS is the reporter's "runners" input (comma-separated runner ids);
 * ENVFILE holds the environment the reporter's step gets, one NAME=VALUE a
 * line.  Prints one line per runner and then the totals, each number in
 * the shortest form that reads back exactly:
 *
 *   runner ID status S tests N passed P max M shown X counted C
 *   shown_total X          the reporter's table: the sum of the runners' points
 *   shown_max M            ... and of their max_score
 *   counted_total T        what it sends GitHub Classroom: "totalPoints"
 *   counted_max N          ... and "maxPoints"
 *   workflow pass|fail     whether the reporter fails the step
 *
 * With --dump it prints instead each runner's id and its decoded JSON, one
 * runner a line.
 *
 * The rules, as the action's source (classroom-resources/
 * autograding-grading-reporter, v1) has them:
 *   - src/main.js: each runner id of the comma-separated "runners" input is
 *     trimmed and put in capitals, "_RESULTS" appended: that environment
 *     variable holds the runner's results, base64 of JSON.  The step fails
 *     when a runner's status is "fail" or "error".
 *   - src/helpers/test-helpers.js: a runner's points are the number of its
 *     tests whose status is "pass", divided by its number of tests, times
 *     its max_score (0 when max_score is missing or 0); its maximum is its
 *     max_score.
 *   - src/aggregate-results.js: the table's total adds the runners' points,
 *     in the order of the input, starting from 0, and likewise their maxima.
 *   - src/notify-classroom.js: runners whose max_score is missing or 0 are
 *     skipped; for the others their max_score is added to maxPoints and the
 *     "score" of each of their tests to totalPoints, in order, from 0.
 * JavaScript's numbers are IEEE doubles and every step above is one double
 * operation, so the C below (built with -ffp-contract=off) gives the same
 * bits.  Anything the reporter could not read (a missing variable, bad
 * base64, bad JSON, a test without a numeric score, a runner without
 * tests) is an error here: exit status 2.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "../tools/base64.h"
#include "../tools/json_read.h"
#include "../../labs/kit/numtext.h"

#include <ctype.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int die(const char *what, const char *detail)
{
    fprintf(stderr, "reporter_totals: %s%s%s\n", what, detail ? ": " : "", detail ? detail : "");
    exit(2);
}

/* The value of environment variable name in the file, malloc'd, or NULL. */
static char *env_lookup(const char *envfile, const char *name)
{
    FILE *f = fopen(envfile, "r");
    if (!f)
        die("cannot read", envfile);
    char *line = NULL, *value = NULL;
    size_t cap = 0;
    ssize_t n;
    size_t len = strlen(name);
    while ((n = getline(&line, &cap, f)) >= 0) {
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            line[--n] = '\0';
        if ((size_t)n > len && strncmp(line, name, len) == 0 && line[len] == '=') {
            free(value);                    /* the last one wins */
            value = strdup(line + len + 1);
        }
    }
    free(line);
    fclose(f);
    return value;
}

static const char *shortest(char *buf, double x)
{
    return kit_shortest_double(buf, 40, x);
}

int main(int argc, char **argv)
{
    bool dump = argc == 4 && strcmp(argv[1], "--dump") == 0;
    if (argc != 3 && !dump)
        die("usage: reporter_totals [--dump] RUNNERS ENVFILE", NULL);
    argv += dump;
    char *runners = strdup(argv[1]);
    double shown_total = 0, shown_max = 0, counted_total = 0, counted_max = 0;
    int failing = 0, nrunners = 0;
    char *save = NULL;
    for (char *id = strtok_r(runners, ",", &save); id; id = strtok_r(NULL, ",", &save)) {
        /* trim, capitals, _RESULTS */
        while (isspace((unsigned char)*id))
            id++;
        size_t len = strlen(id);
        while (len > 0 && isspace((unsigned char)id[len - 1]))
            id[--len] = '\0';
        char var[300];
        if (len == 0 || len > 200)
            die("a runner id that is empty or too long", id);
        for (size_t k = 0; k <= len; k++)
            var[k] = (char)toupper((unsigned char)id[k]);
        strcat(var, "_RESULTS");
        char *coded = env_lookup(argv[2], var);
        if (!coded || !*coded)
            die("no results in the environment variable", var);
        char err[256];
        size_t jlen;
        unsigned char *json = base64_decode(coded, strlen(coded), &jlen, err, sizeof err);
        if (!json)
            die(var, err);
        JsonValue v;
        if (json_parse((const char *)json, jlen, &v, err, sizeof err) != 0)
            die(var, err);
        if (dump) {
            printf("%s %s\n", id, (const char *)json);
            json_value_free(&v);
            free(json);
            free(coded);
            continue;
        }
        const JsonValue *status = json_member(&v, "status");
        const JsonValue *max = json_member(&v, "max_score");
        const JsonValue *tests = json_member(&v, "tests");
        const JsonValue *version = json_member(&v, "version");
        if (!version || version->type != JSON_NUMBER || version->number != 1)
            die(var, "no \"version\": 1");
        if (!status || status->type != JSON_STRING)
            die(var, "no status");
        if (max && max->type != JSON_NUMBER)
            die(var, "a max_score that is not a number");
        if (!tests || tests->type != JSON_ARRAY || tests->n == 0)
            die(var, "no tests (the reporter would divide by 0)");
        double max_score = max ? max->number : 0;   /* `max_score || 0` */
        int passed = 0;
        double counted = 0;
        for (int k = 0; k < tests->n; k++) {
            const JsonValue *t = &tests->items[k];
            const JsonValue *ts = json_member(t, "status");
            const JsonValue *score = json_member(t, "score");
            const JsonValue *name = json_member(t, "name");
            const JsonValue *line_no = json_member(t, "line_no");
            if (!name || name->type != JSON_STRING || !ts || ts->type != JSON_STRING)
                die(var, "a test without a name or status");
            if (!score || score->type != JSON_NUMBER)
                die(var, "a test without a numeric score (totalPoints would be NaN)");
            if (!line_no || line_no->type != JSON_NUMBER || line_no->number != 0)
                die(var, "a test without line_no 0 (the reporter would print \"- line ...\")");
            if (strcmp(ts->string, "pass") == 0)
                passed++;
            counted += score->number;
        }
        double shown = ((double)passed / (double)tests->n) * max_score;
        shown_total = shown_total + shown;
        shown_max = shown_max + max_score;
        if (max_score != 0) {
            counted_max = counted_max + max_score;
            for (int k = 0; k < tests->n; k++)
                counted_total = counted_total + json_member(&tests->items[k], "score")->number;
        } else {
            counted = 0;
        }
        if (strcmp(status->string, "fail") == 0 || strcmp(status->string, "error") == 0)
            failing = 1;
        char b1[40], b2[40], b3[40];
        printf("runner %s status %s tests %d passed %d max %s shown %s counted %s\n", id,
               status->string, tests->n, passed, shortest(b1, max_score), shortest(b2, shown),
               shortest(b3, counted));
        json_value_free(&v);
        free(json);
        free(coded);
        nrunners++;
    }
    if (dump)
        return 0;
    if (nrunners == 0)
        die("no runners", NULL);
    char b[40];
    printf("shown_total %s\n", shortest(b, shown_total));
    printf("shown_max %s\n", shortest(b, shown_max));
    printf("counted_total %s\n", shortest(b, counted_total));
    printf("counted_max %s\n", shortest(b, counted_max));
    printf("workflow %s\n", failing ? "fail" : "pass");
    free(runners);
    return 0;
}
