/*
 * check.c - judging a child's answers, case by case, and telling the
 * student what went wrong: the input, what was expected, what came back,
 * the tolerance, and, when the answer matches a known mistake, a hint.
 */
#define _POSIX_C_SOURCE 200809L
#include "grader.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    char *s;
    size_t len, cap;
} Text;

static void say(Text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void say(Text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0)
        return;
    if (t->len + (size_t)n + 1 > t->cap) {
        t->cap = (t->len + (size_t)n + 1) * 2;
        char *ns = realloc(t->s, t->cap);
        if (!ns)
            return;
        t->s = ns;
    }
    va_start(ap, fmt);
    vsnprintf(t->s + t->len, (size_t)n + 1, fmt, ap);
    va_end(ap);
    t->len += (size_t)n;
}

static const char *in_names[NKINDS][CASE_MAX_IN] = {
    [KIND_PLANE] = { "fov_degrees", "aspect", "d" },
    [KIND_PIXEL] = { "i", "j", "nx", "ny", "w", "h", "d" },
    [KIND_SPHERE] = { "c.x", "c.y", "c.z", "R", "e.x", "e.y", "e.z", "r.x", "r.y", "r.z" },
    [KIND_CAMERA] = { "eye.x", "eye.y", "eye.z", "pixel.x", "pixel.y", "pixel.z" },
    [KIND_COLOR] = { "e.x", "e.y", "e.z", "r.x", "r.y", "r.z" },
    [KIND_IMAGE] = { "pixel.x", "pixel.y", "pixel.z" },
};
static const char *out_names[NKINDS][CASE_MAX_OUT] = {
    [KIND_PLANE] = { "w", "h" },
    [KIND_PIXEL] = { "x", "y", "z" },
    [KIND_SPHERE] = { "hit", "t" },
    [KIND_CAMERA] = { "origin.x", "origin.y", "origin.z", "direction.x", "direction.y", "direction.z" },
    [KIND_COLOR] = { "r", "g", "b" },
    [KIND_IMAGE] = { "r", "g", "b" },
};

static bool near(double got, double want, double tol)
{
    return fabs(got - want) <= tol;         /* false for NaN */
}

/* Is the answer right?  For the hint search, slack widens the tolerances. */
static bool case_ok(Kind kind, const Case *c, const double *want, const double *got, double slack)
{
    int nout = kind_nout(kind);
    if (kind == KIND_SPHERE) {
        bool either = c->flags & CASE_EITHER_HIT;
        bool want_hit = want[0] != 0;
        bool got_hit = got[0] != 0;
        if (got[0] != 0 && got[0] != 1)
            return false;
        if (!got_hit)
            return !want_hit || either;
        if (!(got[1] > 0) || isinf(got[1]))
            return false;
        if (!want_hit && !either)
            return false;
        if (!want_hit)                      /* a hit at a grazing miss */
            return !(want[1] > 0) || near(got[1], want[1], c->tol[1] * slack);
        return near(got[1], want[1], c->tol[1] * slack + slack * 1e-9 * fabs(want[1]) * (slack > 1));
    }
    if (kind == KIND_COLOR || kind == KIND_IMAGE) {
        bool same = true, same_alt = true;
        for (int k = 0; k < 3; k++) {
            same = same && near(got[k], want[k], c->tol[k]);
            same_alt = same_alt && near(got[k], c->alt[k], c->tol[k]);
        }
        return same || ((c->flags & CASE_EITHER_HIT) && same_alt);
    }
    for (int k = 0; k < nout; k++) {
        double tol = c->tol[k] * slack;
        if (slack > 1)                      /* hints: match to 6 digits */
            tol = fmax(tol, 1e-6 * fabs(want[k]));
        if (!near(got[k], want[k], tol))
            return false;
    }
    return true;
}

static void describe_numbers(Text *t, const char *const *names, const double *v, int n)
{
    for (int k = 0; k < n; k++)
        say(t, "%s%s = %.17g", k ? ", " : "", names[k], v[k]);
}

static void describe_case(Text *t, const Test *test, int index, const Case *c, const double *got, bool have)
{
    Kind kind = test->kind;
    int nin = kind_nin(kind), nout = kind_nout(kind);
    say(t, "  case %d of %d", index + 1, test->ncases);
    if (kind == KIND_IMAGE && test->image_nx > 0)
        say(t, " (pixel i = %d, j = %d)", index % test->image_nx, index / test->image_nx);
    say(t, "\n    input:     ");
    describe_numbers(t, in_names[kind], c->in, nin);
    if (kind == KIND_COLOR || kind == KIND_IMAGE)
        say(t, "  (scene: %d spheres; background %.3g %.3g %.3g)", test->nspheres,
            test->background[0], test->background[1], test->background[2]);
    say(t, "\n    expected:  ");
    if (kind == KIND_SPHERE) {
        if (c->want[0] != 0)
            say(t, "hit at t = %.17g (within %.3g)", c->want[1], c->tol[1]);
        else
            say(t, "miss");
        if (c->flags & CASE_EITHER_HIT)
            say(t, " -- the ray grazes the sphere within rounding: hit or miss both accepted");
    } else {
        describe_numbers(t, out_names[kind], c->want, nout);
        if (kind == KIND_COLOR || kind == KIND_IMAGE) {
            if (c->flags & CASE_EITHER_HIT)
                say(t, "  (or %.3g %.3g %.3g: the ray grazes a silhouette)", c->alt[0], c->alt[1], c->alt[2]);
        } else {
            say(t, "  (each within ");
            for (int k = 0; k < nout; k++)
                say(t, "%s%.3g", k ? ", " : "", c->tol[k]);
            say(t, ")");
        }
    }
    say(t, "\n    got:       ");
    if (!have) {
        say(t, "no answer\n");
        return;
    }
    if (kind == KIND_SPHERE) {
        if (got[0] == 1)
            say(t, "hit at t = %.17g", got[1]);
        else if (got[0] == 0)
            say(t, "miss");
        else
            say(t, "a return value that is neither true nor false");
    } else {
        describe_numbers(t, out_names[kind], got, nout);
    }
    say(t, "\n");
}

/* A hint for a wrong answer: a known mistake's output, or "close but not
 * close enough" (float arithmetic, a truncated constant). */
static void hint(Text *t, Kind kind, const Case *c, const double *got)
{
    for (int h = 0; h < c->nhints; h++) {
        if (case_ok(kind, c, c->hints[h].out, got, 4)) {
            say(t, "    hint:      %s\n", c->hints[h].text);
            return;
        }
    }
    if (kind == KIND_PLANE || kind == KIND_PIXEL || kind == KIND_CAMERA) {
        bool close = true;
        for (int k = 0; k < kind_nout(kind); k++)
            close = close && fabs(got[k] - c->want[k]) <= 1e-5 * fmax(1e-300, fabs(c->want[k])) + c->tol[k];
        if (close)
            say(t, "    hint:      right to about 5 or more digits but not to the tolerance: "
                   "is something computed in float, or a constant such as pi rounded?\n");
    }
    for (int k = 0; k < kind_nout(kind); k++)
        if (isnan(got[k])) {
            say(t, "    hint:      NaN: a square root of a negative number, 0/0, or an "
                   "uninitialised variable?\n");
            break;
        }
}

bool check_answers(const Test *test, const char *answers, size_t len, char **out)
{
    Text t = { 0 };
    int nout = kind_nout(test->kind);
    const char *p = answers, *end = answers + len;
    int failed = 0, first_bad = -1, answered = 0;
    bool complete = false;

    for (int c = 0; c < test->ncases; c++) {
        double got[CASE_MAX_OUT] = { 0 };
        bool have = p < end;
        for (int k = 0; k < nout && have; k++) {
            char *q;
            got[k] = strtod(p, &q);
            have = q != p && q <= end;
            p = q;
        }
        if (have) {
            while (p < end && (*p == ' ' || *p == '\t'))
                p++;
            have = p < end && *p == '\n';
            p++;
        }
        if (!have)
            break;
        answered++;
        if (!case_ok(test->kind, &test->cases[c], test->cases[c].want, got, 1)) {
            if (failed++ == 0) {
                first_bad = c;
                describe_case(&t, test, c, &test->cases[c], got, true);
                hint(&t, test->kind, &test->cases[c], got);
            }
        }
    }
    if (answered == test->ncases) {
        int n = -1;
        complete = p < end && sscanf(p, "end %d", &n) == 1 && n == test->ncases;
    }
    if (!complete) {
        say(&t, "  the answers stopped after case %d of %d", answered, test->ncases);
        if (answered < test->ncases) {
            say(&t, ": this case did not finish\n");
            describe_case(&t, test, answered, &test->cases[answered], NULL, false);
        } else {
            say(&t, ": the program did not finish normally\n");
        }
    }
    if (failed > 1)
        say(&t, "  %d of %d cases were wrong; the first is shown.\n", failed, test->ncases);
    (void)first_bad;
    *out = t.s ? t.s : calloc(1, 1);
    return complete && failed == 0;
}
