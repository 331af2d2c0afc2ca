/*
 * check_results - checks a results.json against what PrairieLearn reads of
 * it (its documentation, "External Grading", "Grading results", and the
 * pl-external-grader-results element), for tests/suites/prairielearn.sh.
 *
 *   check_results FILE
 *   check_results --info FILE
 *
 * The file must be at most 1 MB of valid JSON (UTF-8), one object with
 *   gradable   a boolean (the kit always writes it)
 *   score      a number in [0, 1] (required when gradable)
 *   message, output   strings
 *   format_errors     a string or an array of strings, if present
 *   tests      an array; each test an object with name, description,
 *              message and output strings and points and max_points
 *              numbers, 0 <= points <= max_points; when the tests' points
 *              are shown, they add up to the score: sum(points) /
 *              sum(max_points) = score.
 * and a hidden test's output (its name has "hidden:") never shows its
 * cases.  Prints "gradable G score S points P max_points M tests N
 * neutral K" (K: tests with max_points 0, which PrairieLearn shows
 * neutrally) and exits 0, or names the first problem and exits 1 (2 for
 * bad usage).
 *
 * With --info, FILE is a question's info.json instead: type "v3", a UUID,
 * a title and topic, gradingMethod "External", and externalGradingOptions
 * with image prairielearn/grader-c, an entrypoint under /grade/tests and a
 * whole timeout of 1 to 600 seconds; prints "image I entrypoint E timeout T".
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "../tools/json_read.h"
#include "../../labs/kit/numtext.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *path;

static void bad(const char *what, const char *detail)
{
    printf("%s: %s%s%s\n", path, what, detail ? ": " : "", detail ? detail : "");
    exit(1);
}

/* Member name of object, which must be of type want (or absent, when
 * optional). */
static const JsonValue *member(const JsonValue *object, const char *name, JsonType want, int optional)
{
    const JsonValue *v = json_member(object, name);
    if (!v) {
        if (!optional)
            bad("a member is missing", name);
        return NULL;
    }
    if (v->type != want) {
        char why[200];
        snprintf(why, sizeof why, "%s is a %s, not a %s", name, json_type_name(v->type), json_type_name(want));
        bad("a member of the wrong type", why);
    }
    return v;
}

/* The checks of --info. */
static int check_info(const JsonValue *v)
{
    const char *uuid = member(v, "uuid", JSON_STRING, 0)->string;
    for (int k = 0; k < 36; k++) {
        bool dash = k == 8 || k == 13 || k == 18 || k == 23;
        if (dash ? uuid[k] != '-' : !strchr("0123456789abcdef", uuid[k]) || !uuid[k])
            bad("a uuid that is not one", uuid);
    }
    if (strlen(uuid) != 36)
        bad("a uuid that is not one", uuid);
    if (strcmp(member(v, "type", JSON_STRING, 0)->string, "v3") != 0)
        bad("type is not v3", NULL);
    member(v, "title", JSON_STRING, 0);
    member(v, "topic", JSON_STRING, 0);
    if (strcmp(member(v, "gradingMethod", JSON_STRING, 0)->string, "External") != 0)
        bad("gradingMethod is not External", NULL);
    const JsonValue *o = member(v, "externalGradingOptions", JSON_OBJECT, 0);
    const char *image = member(o, "image", JSON_STRING, 0)->string;
    const char *entry = member(o, "entrypoint", JSON_STRING, 0)->string;
    double timeout = member(o, "timeout", JSON_NUMBER, 0)->number;
    if (strcmp(image, "prairielearn/grader-c") != 0)
        bad("the image is not prairielearn/grader-c", image);
    if (strncmp(entry, "/grade/tests/", 13) != 0)
        bad("the entrypoint is not in the question's tests folder", entry);
    if (!(timeout >= 1 && timeout <= 600 && timeout == floor(timeout)))
        bad("the timeout is not a whole number of seconds from 1 to 600", NULL);
    printf("image %s entrypoint %s timeout %g\n", image, entry, timeout);
    return 0;
}

int main(int argc, char **argv)
{
    bool info = argc == 3 && strcmp(argv[1], "--info") == 0;
    if (argc != 2 && !info) {
        fprintf(stderr, "usage: check_results [--info] FILE\n");
        return 2;
    }
    path = argv[argc - 1];
    FILE *f = fopen(path, "rb");
    if (!f)
        bad("cannot read it", NULL);
    static char text[2 << 20];
    size_t n = fread(text, 1, sizeof text, f);
    fclose(f);
    if (n > 1024 * 1024)
        bad("over 1 MB (PrairieLearn refuses it)", NULL);
    JsonValue v;
    char err[256];
    if (json_parse(text, n, &v, err, sizeof err) != 0)
        bad("not valid JSON", err);
    if (v.type != JSON_OBJECT)
        bad("not a JSON object", NULL);
    if (info)
        return check_info(&v);
    bool gradable = member(&v, "gradable", JSON_BOOL, 0)->boolean;
    const JsonValue *score = member(&v, "score", JSON_NUMBER, !gradable);
    if (score && !(score->number >= 0 && score->number <= 1))
        bad("a score outside [0, 1]", NULL);
    member(&v, "message", JSON_STRING, 0);
    member(&v, "output", JSON_STRING, 0);
    const JsonValue *fe = json_member(&v, "format_errors");
    if (fe && fe->type != JSON_STRING) {
        if (fe->type != JSON_ARRAY)
            bad("format_errors is neither a string nor an array", NULL);
        for (int k = 0; k < fe->n; k++)
            if (fe->items[k].type != JSON_STRING)
                bad("format_errors holds something other than strings", NULL);
    }
    if (json_member(&v, "succeeded"))
        bad("it has 'succeeded', which PrairieLearn's grader host sets itself", NULL);
    const JsonValue *tests = member(&v, "tests", JSON_ARRAY, 0);
    double points = 0, max_points = 0;
    int neutral = 0;
    for (int k = 0; k < tests->n; k++) {
        const JsonValue *t = &tests->items[k];
        if (t->type != JSON_OBJECT)
            bad("a test that is not an object", NULL);
        const char *name = member(t, "name", JSON_STRING, 0)->string;
        member(t, "description", JSON_STRING, 0);
        member(t, "message", JSON_STRING, 0);
        const char *output = member(t, "output", JSON_STRING, 0)->string;
        if (strstr(name, "hidden:") && (strstr(output, "expected:") || strstr(output, "got:")))
            bad("a hidden test shows its cases", name);
        double p = member(t, "points", JSON_NUMBER, 0)->number;
        double m = member(t, "max_points", JSON_NUMBER, 0)->number;
        if (!(p >= 0 && m >= 0 && p <= m))
            bad("a test whose points are not within 0 .. max_points", name);
        points += p;
        max_points += m;
        neutral += m == 0;
    }
    if (gradable && max_points > 0 && fabs(points / max_points - score->number) > 1e-12)
        bad("the tests' points do not add up to the score", NULL);
    char b1[40], b2[40], b3[40];
    printf("gradable %s score %s points %s max_points %s tests %d neutral %d\n", gradable ? "true" : "false",
           kit_shortest_double(b1, sizeof b1, score ? score->number : 0),
           kit_shortest_double(b2, sizeof b2, points), kit_shortest_double(b3, sizeof b3, max_points),
           tests->n, neutral);
    json_value_free(&v);
    return 0;
}
