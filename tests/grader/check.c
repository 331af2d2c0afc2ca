/*
 * check.c - judging a child's answers, case by case, and telling the
 * student what went wrong: the input, what was expected, what came back,
 * the tolerance, and, when the answer matches a known mistake, a hint.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "grader.h"
#include "hexfloat.h"
#include "kit/numtext.h"
#include "kit/scene.h"                  /* the guard sphere's colour */

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *in_names[NKINDS][CASE_MAX_IN] = {
    [KIND_PLANE] = { "fov_degrees", "aspect", "d" },
    [KIND_PIXEL] = { "i", "j", "nx", "ny", "w", "h", "d" },
    [KIND_SPHERE] = { "c.x", "c.y", "c.z", "R", "e.x", "e.y", "e.z", "r.x", "r.y", "r.z" },
    [KIND_CAMERA] = { "eye.x", "eye.y", "eye.z", "pixel.x", "pixel.y", "pixel.z" },
    [KIND_COLOR] = { "e.x", "e.y", "e.z", "r.x", "r.y", "r.z" },
    [KIND_IMAGE] = { "pixel.x", "pixel.y", "pixel.z" },
    [KIND_PLANEHIT] = { "p.x", "p.y", "p.z", "n.x", "n.y", "n.z", "e.x", "e.y", "e.z", "r.x", "r.y", "r.z" },
    [KIND_TRIANGLE] = { "a.x", "a.y", "a.z", "b.x", "b.y", "b.z", "c.x", "c.y", "c.z",
                        "e.x", "e.y", "e.z", "r.x", "r.y", "r.z" },
    [KIND_MESH] = { "e.x", "e.y", "e.z", "r.x", "r.y", "r.z" },
};
static const char *out_names[NKINDS][CASE_MAX_OUT] = {
    [KIND_PLANE] = { "w", "h" },
    [KIND_PIXEL] = { "x", "y", "z" },
    [KIND_SPHERE] = { "hit", "t" },
    [KIND_CAMERA] = { "origin.x", "origin.y", "origin.z", "direction.x", "direction.y", "direction.z" },
    [KIND_COLOR] = { "r", "g", "b" },
    [KIND_IMAGE] = { "r", "g", "b" },
    [KIND_PLANEHIT] = { "hit", "t" },
    [KIND_TRIANGLE] = { "hit", "t" },
    [KIND_MESH] = { "hit", "t" },
};

static bool near(double got, double want, double tol)
{
    return fabs(got - want) <= tol;         /* false for NaN */
}

/* Parts 4 and 5: is the answer (hit, t) right?  A hit's t must be finite
 * and > 0; a hit is right within tol of want's t, and for a case in doubt
 * (CASE_EITHER_HIT) a miss is right too, and so is a hit at t >= alt[1]
 * (a ray parallel to the plane within rounding). */
static bool flat_ok(const Case *c, const double *got)
{
    bool either = c->flags & CASE_EITHER_HIT;
    if (got[0] != 0 && got[0] != 1)
        return false;
    if (got[0] == 0)
        return c->want[0] == 0 || either;
    if (!(got[1] > 0) || isinf(got[1]))
        return false;
    if (c->want[0] == 1 && near(got[1], c->want[1], c->tol[1]))
        return true;
    if (!either)
        return false;
    return near(got[1], c->want[1], c->tol[1]) || got[1] >= c->alt[1];
}

/* Does a (hit, t) answer match a known mistake's?  Hits at a non-finite t
 * match a mistake that also gives one (a division by zero), others match
 * to 6 digits. */
static bool flat_hint_matches(const double *mistake, const double *got, double tol)
{
    if (got[0] != mistake[0])
        return false;
    if (mistake[0] == 0)
        return true;
    if (isnan(mistake[1]))
        return isnan(got[1]);
    if (isinf(mistake[1]))
        return isinf(got[1]) && (got[1] > 0) == (mistake[1] > 0);
    return fabs(got[1] - mistake[1]) <= fmax(4 * tol, 1e-6 * fabs(mistake[1]));
}

/* Is the answer right? */
static bool case_ok(Kind kind, const Case *c, const double *want, const double *got)
{
    int nout = kind_nout(kind);
    if (kind == KIND_PLANEHIT || kind == KIND_TRIANGLE || kind == KIND_MESH)
        return flat_ok(c, got);
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
        if (either && c->alt[0] < c->alt[1] && got[1] >= c->alt[0] && got[1] <= c->alt[1])
            return true;                    /* another root the oracle accepts */
        if (!want_hit)                      /* a hit at a grazing miss */
            return !(want[1] > 0) || near(got[1], want[1], c->tol[1]);
        return near(got[1], want[1], c->tol[1]);
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
        double tol = c->tol[k];
        if (!near(got[k], want[k], tol))
            return false;
    }
    return true;
}

static void describe_numbers(char **t, const char *const *names, const double *v, int n)
{
    char b[40];
    for (int k = 0; k < n; k++)
        appendf(t, "%s%s = %s", k ? ", " : "", names[k], kit_shortest_double(b, sizeof b, v[k]));
}

static void describe_case(char **t, const Test *test, int index, const Case *c, const double *got, bool have)
{
    Kind kind = test->kind;
    int nin = kind_nin(kind), nout = kind_nout(kind);
    char b0[40], b1[40];
    appendf(t, "  case %d of %d", index + 1, test->ncases);
    if (kind == KIND_IMAGE && test->image_nx > 0)
        appendf(t, " (pixel i = %d, j = %d)", index % test->image_nx, index / test->image_nx);
    appendf(t, "\n    input:     ");
    describe_numbers(t, in_names[kind], c->in, nin);
    if (kind == KIND_COLOR || kind == KIND_IMAGE)
        appendf(t, "  (scene: %d spheres; background %.3g %.3g %.3g)", test->nspheres,
            test->background[0], test->background[1], test->background[2]);
    if (kind == KIND_MESH)
        appendf(t, "  (a closed mesh of %d triangles: the first hit over all of them)", test->ntriangles);
    appendf(t, "\n    expected:  ");
    if (kind_is_hit(kind)) {
        if (c->want[0] != 0)
            appendf(t, "hit at t = %s (within %.3g)", kit_shortest_double(b0, sizeof b0, c->want[1]),
                c->tol[1]);
        else
            appendf(t, "miss");
        if ((c->flags & CASE_EITHER_HIT) && kind == KIND_SPHERE && c->alt[0] < c->alt[1] && c->alt[0] <= 0)
            appendf(t, " -- or a hit at a t > 0 up to %s: the ray starts within rounding of "
                   "the surface, so a miss, a hit just ahead and the far side are all accepted "
                   "(t = 0, the origin itself, is not ahead)",
                kit_shortest_double(b1, sizeof b1, c->alt[1]));
        else if ((c->flags & CASE_EITHER_HIT) && kind == KIND_SPHERE && c->alt[0] < c->alt[1])
            appendf(t, " -- or a hit at t from %s to %s: the ray starts within rounding of "
                   "the surface, so a miss, a hit just ahead and the far side are all accepted",
                kit_shortest_double(b0, sizeof b0, c->alt[0]),
                kit_shortest_double(b1, sizeof b1, c->alt[1]));
        else if ((c->flags & CASE_EITHER_HIT) && kind == KIND_SPHERE)
            appendf(t, " -- the ray grazes the sphere within rounding: hit or miss both accepted");
        else if (c->flags & CASE_EITHER_HIT)
            appendf(t, " -- within rounding of an edge, of parallel or of the origin: a miss is "
                   "accepted too");
    } else {
        describe_numbers(t, out_names[kind], c->want, nout);
        if (kind == KIND_COLOR || kind == KIND_IMAGE) {
            if (c->flags & CASE_EITHER_HIT)
                appendf(t, "  (or %.3g %.3g %.3g: the ray grazes a silhouette)", c->alt[0], c->alt[1],
                        c->alt[2]);
        } else {
            appendf(t, "  (each within ");
            for (int k = 0; k < nout; k++)
                appendf(t, "%s%.3g", k ? ", " : "", c->tol[k]);
            appendf(t, ")");
        }
    }
    appendf(t, "\n    got:       ");
    if (!have) {
        appendf(t, "no answer\n");
        return;
    }
    if (kind_is_hit(kind)) {
        if (got[0] == 1)
            appendf(t, "hit at t = %s", kit_shortest_double(b0, sizeof b0, got[1]));
        else if (got[0] == 0)
            appendf(t, "miss");
        else
            appendf(t, "a return value that is neither true nor false");
    } else {
        describe_numbers(t, out_names[kind], got, nout);
    }
    appendf(t, "\n");
}

/* Whether a case's input holds a NaN. */
static bool nan_input(Kind kind, const Case *c)
{
    for (int k = 0; k < kind_nin(kind); k++)
        if (isnan(c->in[k]))
            return true;
    return false;
}

/* The test the same code passed that rules out the mistake of this hint
 * text (a case of it has the hint, so there the mistake answers wrongly,
 * and the code answered right), or NULL.  A case with NaN input rules out
 * nothing: what code answers there depends on where its first comparison
 * meets the NaN, not on the mistake (GLM's det tests turn NaN away before
 * t is made, so its missing test of t gives no NaN hit). */
static const Test *ruled_out_by(const char *text, const PartSoFar *part)
{
    for (int k = 0; k < part->npassed; k++) {
        const Test *pt = part->passed[k];
        for (int c = 0; c < pt->ncases; c++) {
            if (nan_input(pt->kind, &pt->cases[c]))
                continue;
            for (int h = 0; h < pt->cases[c].nhints; h++)
                if (strcmp(pt->cases[c].hints[h].text, text) == 0)
                    return pt;
        }
    }
    return NULL;
}

static bool ruled_out(const char *text, const PartSoFar *part)
{
    return ruled_out_by(text, part) != NULL;
}

/* Whether every wrong answer of the test that the mistake of this hint
 * text explains is a miss of the mistake's: the test shows that mistake
 * only by elimination, through hits it missed. */
static bool shown_by_misses(const Test *test, const bool *ok, int answered, const char *text)
{
    for (int c = 0; c < answered; c++)
        for (int h = 0; h < test->cases[c].nhints; h++)
            if (!ok[c] && strcmp(test->cases[c].hints[h].text, text) == 0 && test->cases[c].hints[h].out[0] != 0)
                return false;
    return true;
}

/* Whether the mistake of this hint text was named for another test of the
 * part that the same code failed. */
static bool named_before(const char *text, const PartSoFar *part)
{
    for (int k = 0; k < part->nnamed; k++)
        if (strcmp(part->named[k], text) == 0)
            return true;
    return false;
}

/* Whether one of the tests passed has a case whose certain answer is a
 * hit: code that passed it is not code that misses every ray. */
static bool hits_right(const PartSoFar *part)
{
    for (int k = 0; k < part->npassed; k++) {
        const Test *pt = part->passed[k];
        for (int c = 0; c < pt->ncases; c++)
            if (kind_is_hit(pt->kind) && pt->cases[c].want[0] == 1 && !(pt->cases[c].flags & CASE_EITHER_HIT))
                return true;
    }
    return false;
}

/* Parts 4 and 5: the known mistake that explains every answer of the test.
 * A mistake explains a case when the answer there is the mistake's output
 * (a hint of that text on the case) or, where the mistake gives the right
 * answer (no hint of that text), the right answer; it must explain every
 * case answered, and be wrong somewhere.  That mistake when it is the only
 * one.  When several fit, the part's other tests may tell them apart: a
 * mistake that would have failed a test the code passed is dropped, and
 * the one left, if one is, is named; if more are left, the one named for
 * another failed test of the part, if one was (those judged before this
 * one; once the part's every test is, check_part_again judges again a test
 * that named none, with those judged after it too).  (Only then: a
 * mistake is a model of many ways to write it, the student's way may
 * differ from it elsewhere, and a test it alone explains names it
 * whatever the other tests say.)  A test answered with misses alone
 * names only a mistake named for another test and not ruled out.  NULL
 * when none is confirmed. */
static const char *flat_mistake(const Test *test, const double (*got)[CASE_MAX_OUT],
                                const bool *ok, int answered, const PartSoFar *part,
                                const char **alone_ruled_out)
{
    enum { MAX_FIT = 16 };
    const char *fit[MAX_FIT];
    int nfit = 0;
    for (int c0 = 0; c0 < answered; c0++) {
        for (int h0 = 0; h0 < test->cases[c0].nhints; h0++) {
            const char *text = test->cases[c0].hints[h0].text;
            bool seen = false;
            for (int k = 0; k < nfit && !seen; k++)
                seen = strcmp(fit[k], text) == 0;
            if (seen)
                continue;
            bool explains = true, wrong_somewhere = false;
            for (int c = 0; c < answered && explains; c++) {
                const Case *cs = &test->cases[c];
                const Hint *h = NULL;
                for (int k = 0; k < cs->nhints && !h; k++)
                    if (strcmp(cs->hints[k].text, text) == 0)
                        h = &cs->hints[k];
                if (h) {
                    explains = flat_hint_matches(h->out, got[c], cs->tol[1]);
                    wrong_somewhere = wrong_somewhere || !ok[c];
                } else {
                    explains = ok[c];
                }
            }
            if (explains && wrong_somewhere) {
                if (nfit == MAX_FIT)
                    return NULL;
                fit[nfit++] = text;
            }
        }
    }
    /* A test answered with misses alone shows no more than that: every
     * mistake that misses its hits fits it (an epsilon on det fits a test
     * of tiny triangles answered by code that misses every hit, whatever
     * the reason).  Its mistake is then the one another test named, where
     * the answers held hits too, if one did. */
    bool any_hit = false;
    for (int c = 0; c < answered; c++)
        any_hit = any_hit || got[c][0] == 1;
    /* A mistake that this test shows only by the hits it missed is not
     * named when a test the code passed shows that it does not make it
     * (a test without an epsilon on det misses slivers through its own
     * rounding, and hits the tiny triangles an epsilon loses). */
    if (nfit == 1 && any_hit && shown_by_misses(test, ok, answered, fit[0]) && ruled_out(fit[0], part)) {
        *alone_ruled_out = fit[0];
        return NULL;
    }
    if (nfit == 1 && any_hit)
        return fit[0];
    int nleft = 0;
    for (int k = 0; k < nfit; k++)
        if (!ruled_out(fit[k], part))
            fit[nleft++] = fit[k];
    if (nleft == 1 && any_hit)
        return fit[0];
    const char *named = NULL;
    for (int k = 0; k < nleft; k++) {
        if (!named_before(fit[k], part))
            continue;
        if (named)
            return NULL;                /* two mistakes fit: name neither */
        named = fit[k];
    }
    return named;
}

/* Parts 4 and 5: what explains the test's answers.  When every answer is
 * a miss, a fact rather than a mistake: the skeleton answers so, as does a
 * sign that puts every hit behind the ray, and such answers fit every
 * mistake that misses this test's hits.  Only when the code passed a test
 * of its part with a hit in it is it not the skeleton; then the mistake
 * flat_mistake confirms, if it confirms one, is named. */
static const char *flat_diagnosis(const Test *test, const double (*got)[CASE_MAX_OUT],
                                  const bool *ok, int answered, const PartSoFar *part,
                                  const char **mistake, const char **ruled)
{
    static const char all_miss_fact[] =
        "every case of this test was answered as a miss, also where the ray plainly hits";
    bool all_miss = answered > 0;
    for (int c = 0; c < answered; c++)
        all_miss = all_miss && got[c][0] == 0;
    *mistake = *ruled = NULL;
    if (all_miss && !hits_right(part))
        return all_miss_fact;
    *mistake = flat_mistake(test, got, ok, answered, part, ruled);
    return *mistake ? *mistake : all_miss ? all_miss_fact : NULL;
}

/* A hit at t <= 0, or at a t that is not a number, where the input is not
 * NaN (that case has a hint of its own): the answer alone shows it, and
 * this says so.  Whether it did. */
static bool hit_not_ahead(char **t, const double *got)
{
    double tg = got[1];
    if (got[0] != 1 || tg > 0)
        return false;
    if (isnan(tg))
        appendf(t, "    hint:      a hit at t = NaN: a hit needs t > 0, and a test written as \"t < 0: "
               "miss\" lets NaN through (every comparison with NaN is false); write it as "
               "!(t > 0)\n");
    else
        appendf(t, "    hint:      a hit at t = %.3g is %s the ray's origin: only t > 0 is a hit\n", tg,
            tg == 0 ? "at" : "behind");
    return true;
}

/* Parts 4 and 5: causes that an answer shows by itself, whatever the
 * test: a hit at t <= 0, at NaN or at infinity, t rounded to float, t a
 * whole number, a ray through a closed mesh that the test gets right
 * elsewhere.  Each is stated only when the answers prove it. */
static void flat_evidence(char **t, const Test *test, const Case *c, const double *got, int failed)
{
    double want = c->want[1], tg = got[1];
    /* A crack: a miss or a later hit (farther by more than a t a few
     * digits off: the mesh's far side) on a mesh whose other rays (at
     * least three quarters of them) the same test gets right. */
    if (test->kind == KIND_MESH && c->want[0] == 1 && (got[0] == 0 || tg > want * (1 + 1e-6) + c->tol[1])
        && 4 * failed <= test->ncases) {
        appendf(t, "    hint:      the ray entered this closed mesh through an edge or vertex that "
               "triangles share, and %s: your test is not watertight there (the hard-case "
               "challenge)\n", got[0] == 0 ? "hit nothing" : "its first hit was farther on");
        return;
    }
    if (hit_not_ahead(t, got))
        return;
    /* A hit at t = +inf: a quotient whose divisor was 0. */
    if (got[0] == 1 && tg == INFINITY) {
        appendf(t, "    hint:      a hit at t = inf is no point of the ray: t must be finite. A division by "
               "%s = 0 (a ray parallel to the %s) gives it: that is a miss\n",
            test->kind == KIND_PLANEHIT ? "r.n" : "det", test->kind == KIND_PLANEHIT ? "plane" : "triangle");
        return;
    }
    if (got[0] != 1 || c->want[0] != 1 || !isfinite(tg) || !(want > 0))
        return;
    bool near_want = fabs(tg - want) <= 1e-5 * want;
    if (near_want && (double)(float)tg == tg && (double)(float)want != want)
        appendf(t, "    hint:      t = %.9g is a float (24 bits): compute in double\n", tg);
    else if (tg == floor(tg) && want != floor(want) && fabs(tg - want) < 1)
        appendf(t, "    hint:      t = %.17g is a whole number: is t, or a value it comes from, an "
                "int?\n", tg);
}

/* Parts 4 and 5: true when the test's answers missed some hits, and every
 * hit they missed is at least a thousand times nearer the ray's origin than
 * every hit they found: *missed is the farthest missed t, *found the
 * nearest found.  A fact of the answers; what it suggests (an epsilon
 * against shadow acne, where this lab's rule is tmin = 0) the hint says as
 * such. */
static bool flat_near_misses(const Test *test, const Answers *a, double *missed, double *found)
{
    *missed = -1;
    *found = INFINITY;
    for (int c = 0; c < a->answered; c++) {
        const Case *cs = &test->cases[c];
        if (cs->want[0] != 1 || !(cs->want[1] > 0))
            continue;
        if (a->ok[c])
            *found = fmin(*found, cs->want[1]);
        else if (a->got[c][0] == 0)
            *missed = fmax(*missed, cs->want[1]);
    }
    return *missed > 0 && isfinite(*found) && *missed <= 1e-3 * *found;
}

int batch_split(const char *answers, size_t len, int ntests, const char **from, size_t *size)
{
    const char *p = answers, *end = answers + len;
    int got = 0;
    while (p < end && got < ntests) {
        const char *line = p, *q = NULL;
        for (;;) {
            const char *nl = memchr(line, '\n', (size_t)(end - line));
            if (!nl)
                return -1;
            if (nl - line >= 4 && memcmp(line, "end ", 4) == 0) {
                q = nl + 1;
                break;
            }
            line = nl + 1;
        }
        from[got] = p;
        size[got] = (size_t)(q - p);
        got++;
        p = q;
    }
    return got == ntests && p == end ? ntests : -1;
}

void answers_free(Answers *a)
{
    free(a->got);
    free(a->ok);
    memset(a, 0, sizeof *a);
}

bool case_is_right(Kind kind, const Case *c, const double *got)
{
    return case_ok(kind, c, c->want, got);
}

bool check_answers(const Test *test, const char *answers, size_t len, char **out, Answers *keep)
{
    return check_answers_in_part(test, answers, len, NULL, out, keep);
}

static bool is_flat(const Test *test)
{
    return test->kind == KIND_PLANEHIT || test->kind == KIND_TRIANGLE || test->kind == KIND_MESH;
}

/* The message for the student about answers a to the test, read beside
 * the other tests of its part; sets a->named.  Returns the message. */
static char *verdict(const Test *test, Answers *a, const PartSoFar *part)
{
    char *t = NULL;
    if (a->first_bad >= 0)
        describe_case(&t, test, a->first_bad, &test->cases[a->first_bad], a->got[a->first_bad], true);
    /* The guard sphere's colour, which only a read past the scene's last
     * sphere can give (scene.h). */
    if ((test->kind == KIND_COLOR || test->kind == KIND_IMAGE) && a->first_bad >= 0 &&
        a->got[a->first_bad][0] == SCENE_GUARD_RED && a->got[a->first_bad][1] == SCENE_GUARD_GREEN &&
        a->got[a->first_bad][2] == SCENE_GUARD_BLUE)
        appendf(&t, "    hint:      this magenta is the grader's marker sphere, kept just past the last "
                "sphere, around everything: ray_color read scene->spheres[scene->nspheres], one sphere "
                "too many. Loop while k < scene->nspheres\n");
    a->named = NULL;
    if (is_flat(test) && a->first_bad >= 0) {
        const Case *bad = &test->cases[a->first_bad];
        bool nan_in = nan_input(test->kind, bad);
        const char *ruled;
        const char *why = flat_diagnosis(test, (const double (*)[CASE_MAX_OUT])a->got, a->ok, a->answered,
                                         part, &a->named, &ruled);
        double missed, found;
        if (ruled) {
            /* The mistake's words up to its fix ("...: compare it with 0"). */
            const char *fix = strstr(ruled, ": ");
            int n = fix ? (int)(fix - ruled) : (int)strlen(ruled);
            appendf(&t, "    hint:      the hits missed here fit one known mistake alone (%.*s), but your "
                    "code passed \"%s\", which code with that mistake fails: they have another cause%s\n",
                    n, ruled, ruled_out_by(ruled, part)->name,
                    test->hard ? ", such as rounding where this hard case makes it large (the handout's "
                                 "hard-case challenge)" : "");
        }
        else if (nan_in && a->got[a->first_bad][0] == 1)
            appendf(&t, "    hint:      NaN input must be a miss: a test written as \"t < 0: miss\" lets "
                    "NaN through (every comparison with NaN is false); write it as !(t > 0)\n");
        else if (why) {
            appendf(&t, "    hint:      %s\n", why);
            if (a->named && !strstr(a->named, "t > 0"))  /* what the case shown proves besides */
                hit_not_ahead(&t, a->got[a->first_bad]);
        }
        else if (flat_near_misses(test, a, &missed, &found)) {
            /* A fact of the test's missed hits; the case shown may be wrong
             * for a reason of its own (a float t), which is said first. */
            flat_evidence(&t, test, bad, a->got[a->first_bad], a->failed);
            appendf(&t, "    hint:      every hit this test missed (the farthest at t = %.3g) is a thousand "
                    "times nearer the ray's origin, or more, than every hit it found (the nearest at "
                    "t = %.3g): are hits below some small t ignored? This lab's rule is tmin = 0: every "
                    "hit with t > 0 counts\n", missed, found);
        } else
            flat_evidence(&t, test, bad, a->got[a->first_bad], a->failed);
    }
    if (!a->complete) {
        appendf(&t, "  the answers stopped after case %d of %d", a->answered, test->ncases);
        if (a->answered < test->ncases) {
            appendf(&t, ": this case did not finish\n");
            describe_case(&t, test, a->answered, &test->cases[a->answered], NULL, false);
        } else {
            appendf(&t, ": the program did not finish normally\n");
        }
    }
    if (a->failed > 1)
        appendf(&t, "  %d of %d cases were wrong; the first is shown.\n", a->failed, test->ncases);
    return t ? t : calloc(1, 1);
}

bool check_name_again(const Test *test, Answers *a, const PartSoFar *part, char **out)
{
    if (!is_flat(test) || a->named || a->first_bad < 0 || !a->got)
        return false;
    char *text = verdict(test, a, part);
    if (!a->named) {
        free(text);
        return false;
    }
    *out = text;
    return true;
}

/* The result's output with its verdict replaced by v; false when memory
 * runs out (the output unchanged). */
static bool replace_verdict(TestResult *r, const char *v)
{
    size_t head = r->verdict_at, vlen = strlen(v), tail = strlen(r->output + head + r->verdict_len);
    char *out = malloc(head + vlen + tail + 1);
    if (!out)
        return false;
    memcpy(out, r->output, head);
    memcpy(out + head, v, vlen);
    memcpy(out + head + vlen, r->output + head + r->verdict_len, tail + 1);
    free(r->output);
    r->output = out;
    r->verdict_len = vlen;
    return true;
}

void check_part_again(const TestList *tests, TestResult *results, int part)
{
    const Test **passed = calloc((size_t)tests->n + 1, sizeof *passed);
    const char **named = calloc((size_t)tests->n + 1, sizeof *named);
    for (bool changed = passed && named; changed;) {
        changed = false;
        for (int k = 0; k < tests->n; k++) {
            TestResult *r = &results[k];
            const Test *t = &tests->tests[k];
            if (t->part != part || !is_flat(t) || r->passed || !r->ran || r->answers.named || !r->output ||
                !r->verdict_len)
                continue;
            PartSoFar so_far = { passed, 0, named, 0 };
            for (int j = 0; j < tests->n; j++) {
                const TestResult *rj = &results[j];
                if (j == k || tests->tests[j].part != part)
                    continue;
                if (rj->passed)
                    passed[so_far.npassed++] = &tests->tests[j];
                else if (rj->ran && rj->answers.named)
                    named[so_far.nnamed++] = rj->answers.named;
            }
            char *v;
            if (so_far.nnamed == 0 || !check_name_again(t, &r->answers, &so_far, &v))
                continue;
            if (replace_verdict(r, v))
                changed = true;
            else
                r->answers.named = NULL;            /* the message names none */
            free(v);
        }
    }
    free(passed);
    free(named);
}

bool check_answers_in_part(const Test *test, const char *answers, size_t len,
                           const PartSoFar *part, char **out, Answers *keep)
{
    static const PartSoFar alone = { 0 };
    if (!part)
        part = &alone;
    int nout = kind_nout(test->kind);
    const char *p = answers, *end = answers + len;
    Answers a = { 0 };
    a.first_bad = -1;
    a.got = calloc((size_t)test->ncases + 1, sizeof *a.got);
    a.ok = calloc((size_t)test->ncases + 1, sizeof *a.ok);
    if (!a.got || !a.ok) {
        answers_free(&a);
        *out = strdup("  the grader ran out of memory judging this test\n");
        if (keep)
            memset(keep, 0, sizeof *keep);
        return false;
    }

    for (int c = 0; c < test->ncases; c++) {
        double *got = a.got[c];
        bool have = p < end;
        for (int k = 0; k < nout && have; k++) {
            char *q;
            got[k] = hexfloat_read(p, &q);
            have = q != p && q <= end;
            p = q;
        }
        if (have) {
            while (p < end && (*p == ' ' || *p == '\t'))
                p++;
            have = p < end && *p == '\n';
            p++;
        }
        if (!have) {
            memset(got, 0, sizeof a.got[c]);
            break;
        }
        a.answered++;
        a.ok[c] = case_ok(test->kind, &test->cases[c], test->cases[c].want, got);
        if (!a.ok[c] && a.failed++ == 0)
            a.first_bad = c;
    }
    if (a.answered == test->ncases) {
        int n = -1;
        a.complete = p < end && sscanf(p, "end %d", &n) == 1 && n == test->ncases;
    }
    *out = verdict(test, &a, part);
    bool right = a.complete && a.failed == 0;
    if (keep)
        *keep = a;
    else
        answers_free(&a);
    return right;
}
