/*
 * diagnose.c - see diagnose.h.  One section per part: its models (what
 * each cause computes, in plain double), its probes, and the reading of
 * the probes' answers.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "diagnose.h"
#include "kit/numtext.h"
#include "../../labs/raytracer.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define U 0x1p-53                      /* unit roundoff of double */
#define MATCH_REL 1e-6                 /* an answer is a model's to 6 digits */

/* ---- the diagnosis being written ------------------------------------------ */

#define MAX_CAUSES 16
#define TAG_ALL (-1)                   /* a cause of a part's combined model */
#define TAG_UNWRITTEN (-2)             /* the skeleton's answer, whatever the input */

typedef struct {
    char key[32];
    char text[1200];               /* what it is, the evidence, the fix */
    int tag;                       /* which model explains its cases    */
    int explained[2];              /* failing cases it explains, of the
                                      core tests [0] and the hard [1]  */
} Cause;

typedef struct {
    Cause cause[MAX_CAUSES];
    int ncauses;
} Found;

/* Names a cause the probes confirmed: its key, the model (tag) that says
 * which failing cases it explains, and its explanation. */
static void name_cause(Found *f, const char *key, int tag, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static void name_cause(Found *f, const char *key, int tag, const char *fmt, ...)
{
    if (f->ncauses == MAX_CAUSES)
        return;
    Cause *c = &f->cause[f->ncauses++];
    snprintf(c->key, sizeof c->key, "%s", key);
    c->tag = tag;
    c->explained[0] = c->explained[1] = 0;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->text, sizeof c->text, fmt, ap);
    va_end(ap);
}

/* ---- probes ------------------------------------------------------------------ */

#define MAX_PROBES 9                   /* in a part's set (Part 3a's) */

typedef struct {
    const Probes *probes;
    TestList list;
    Answers a[MAX_PROBES];         /* each test's answers, once run */
} ProbeSet;

/* Adds a probe of n cases, the inputs of case k at rows + k * stride. */
static Test *probe_add(ProbeSet *ps, int part, Kind kind, const char *name, const double *rows, int stride,
                       int n)
{
    Test *t = testlist_add(&ps->list, part, kind, name);
    for (int k = 0; k < n; k++)
        memcpy(test_add_case(t)->in, rows + k * stride, (size_t)kind_nin(kind) * sizeof *rows);
    return t;
}

/* Runs every probe of the set; the answers of test k in ps->a[k]
 * (answered 0 when it did not run).  Returns them. */
static const Answers *probes_run(ProbeSet *ps)
{
    for (int k = 0; k < ps->list.n; k++)
        if (ps->probes->run(ps->probes->ctx, &ps->list.tests[k], &ps->a[k]) != 0)
            memset(&ps->a[k], 0, sizeof ps->a[k]);
    return ps->a;
}

static bool same(double got, double model, double scale)
{
    return fabs(got - model) <= MATCH_REL * scale;      /* false for NaN */
}

static bool is_float(double x)
{
    return (double)(float)x == x;
}

/* Every answer of a probe present and, where a model exists, float-exact
 * while that model's double answer is not (at least half the cases). */
static bool all_float(const Answers *a, int nout, const double (*model)[CASE_MAX_OUT], int ncases)
{
    if (a->answered < ncases)
        return false;
    int telling = 0;
    for (int c = 0; c < ncases; c++)
        for (int k = 0; k < nout; k++) {
            if (!is_float(a->got[c][k]))
                return false;
            telling += !is_float(model[c][k]);
        }
    return 2 * telling >= ncases;
}

/* The largest error of a probe's answers, relative to scale[c] (NULL: to
 * the right answer itself), right[c] the right answers of case c: its case
 * in *wc and answer in *wk.  Infinity when an error is not a number. */
static double worst_error(const Answers *a, const double (*right)[CASE_MAX_OUT], const double *scale,
                          int ncases, int nout, int *wc, int *wk)
{
    double worst = 0;
    *wc = *wk = 0;
    for (int c = 0; c < ncases; c++)
        for (int k = 0; k < nout; k++) {
            double err = fabs(a->got[c][k] - right[c][k]) / (scale ? scale[c] : fabs(right[c][k]));
            if (isnan(err))
                return INFINITY;
            if (err > worst)
                worst = err, *wc = c, *wk = k;
        }
    return worst;
}

/* What the untouched skeleton answers to a case (labs/part*.c). */
static void skeleton_answer(const Test *t, const Case *c, double *out)
{
    memset(out, 0, CASE_MAX_OUT * sizeof *out);
    if (t->kind == KIND_CAMERA)
        memcpy(out, c->in, 3 * sizeof *out);            /* origin = eye, direction 0 */
    else if (t->kind == KIND_COLOR || t->kind == KIND_IMAGE)
        memcpy(out, t->background, 3 * sizeof *out);
}

static bool is_skeleton_answer(const Test *t, const Case *c, const double *got)
{
    double v[CASE_MAX_OUT];
    skeleton_answer(t, c, v);
    for (int k = 0; k < kind_nout(t->kind); k++)
        if (got[k] != v[k])
            return false;
    return true;
}

/* Every answer of every probe run is the skeleton's: the function is not
 * written yet (or returns before its work).  Names that and returns true. */
static bool unwritten(Found *f, const ProbeSet *ps)
{
    const Answers *a = ps->a;
    int answered = 0;
    for (int k = 0; k < ps->list.n; k++) {
        const Test *t = &ps->list.tests[k];
        for (int c = 0; c < a[k].answered; c++, answered++)
            if (!is_skeleton_answer(t, &t->cases[c], a[k].got[c]))
                return false;
    }
    if (answered == 0)
        return false;
    name_cause(f, "unwritten", TAG_UNWRITTEN, "every answer is the skeleton's answer, %s, whatever the "
               "input: the function is not written yet, or returns before its work is done.",
               ps->list.tests[0].kind == KIND_PLANE ? "w = h = 0"
               : ps->list.tests[0].kind == KIND_PIXEL ? "(0, 0, 0)"
               : ps->list.tests[0].kind == KIND_SPHERE ? "always a miss"
               : "the eye and a zero direction; the background");
    return true;
}

/* Counts the failing cases of the part's tests each cause explains, drops
 * the causes that explain none (a flaw no failing test shows is not why
 * points were lost), and writes the diagnosis: text, the causes of the
 * core tests' failures; hard_text, those that explain the hard cases'
 * alone (told apart from the core, as extra credit). */
typedef bool (*Explains)(const void *ctx, int tag, const Test *t, const Case *c, const double *got);

/* The line that ends one group's causes: how many of its failing cases
 * (core or hard, group) the causes explain. */
static void summary_line(char **text, int group, int named, bool after_core, int failing, int explained)
{
    static const char *const kind[2] = { "core", "hard" };
    const char *these = after_core ? "With the causes above, this explains"
                      : named > 1 ? "Together these explain" : "This explains";
    if (explained == failing)
        appendf(text, "%s every failing %s case of this part (%d).\n", these, kind[group], failing);
    else
        appendf(text, "%s %d of the %d failing %s cases of this part; the others have a cause the "
                "probes did not find.\n", these, explained, failing, kind[group]);
}

/* The answers of test k if it is of the part and ran, else NULL. */
static const Answers *ran_in_part(int part, const TestList *tests, const TestResult *results, int k)
{
    return tests->tests[k].part == part && results[k].ran ? &results[k].answers : NULL;
}

static void write_diagnosis(Found *f, int part, const TestList *tests, const TestResult *results,
                            Explains explains, const void *ctx, char **text, char **hard_text, char **keys)
{
    int failing[2] = { 0, 0 }, explained[2] = { 0, 0 };
    for (int k = 0; k < tests->n; k++) {
        const Test *t = &tests->tests[k];
        const Answers *a = ran_in_part(part, tests, results, k);
        for (int c = 0; a && c < a->answered; c++) {
            if (a->ok[c])
                continue;
            failing[t->hard]++;
            bool any = false;
            for (int q = 0; q < f->ncauses; q++)
                if (f->cause[q].tag == TAG_UNWRITTEN ? is_skeleton_answer(t, &t->cases[c], a->got[c])
                                                     : explains(ctx, f->cause[q].tag, t, &t->cases[c], a->got[c])) {
                    f->cause[q].explained[t->hard]++;
                    any = true;
                }
            explained[t->hard] += any;
        }
    }
    char **out[2] = { text, hard_text };
    int named[2] = { 0, 0 };
    /* The core failures' causes first, then the hard cases' alone: the keys
     * in the order of the two texts' lines. */
    for (int q = 0; q < 2 * f->ncauses; q++) {
        const Cause *c = &f->cause[q % f->ncauses];
        if (failing[0] + failing[1] > 0 && c->explained[0] + c->explained[1] == 0)
            continue;
        int group = c->explained[0] == 0 && c->explained[1] > 0;      /* the hard cases' alone */
        if (group != q / f->ncauses)
            continue;
        appendf(keys, "%s%s", *keys ? " " : "", c->key);
        appendf(out[group], "- %s\n", c->text);
        named[group]++;
    }
    for (int group = 0; group < 2; group++)
        if (named[group] > 0 && failing[group] > 0)
            summary_line(out[group], group, named[group], group == 1 && named[0] > 0, failing[group],
                         explained[group]);
}

/* ==== Part 1 ================================================================ */

/* A model of image_plane_size: each way of getting it wrong, combined. */
typedef struct {
    int angle;      /* 0: alpha/2 in radians; 1: alpha/2 taken as radians;
                       2: the whole alpha in radians; 3: the whole alpha taken as radians */
    int factor2;    /* the 2 of h = 2 d tan */
    int use_d;
    int shape;      /* 0: w = aspect h; 1: w = h / aspect; 2: w and h swapped;
                       3: alpha horizontal (w from tan, h = w / aspect);
                       4: alpha along the shorter side (pbrt): 0 when aspect >= 1, else 3 */
} P1Model;

static void p1_eval(P1Model m, const double *in, double *out)
{
    double fov = in[0], aspect = in[1], d = in[2];
    double theta = m.angle == 0 ? fov / 2 * (M_PI / 180) : m.angle == 1 ? fov / 2
                 : m.angle == 2 ? fov * (M_PI / 180) : fov;
    double h0 = (m.factor2 ? 2 : 1) * (m.use_d ? d : 1) * tan(theta);
    switch (m.shape == 4 ? (aspect >= 1 ? 0 : 3) : m.shape) {
    case 0:  out[0] = aspect * h0, out[1] = h0; break;
    case 1:  out[0] = h0 / aspect, out[1] = h0; break;
    case 2:  out[0] = h0, out[1] = aspect * h0; break;
    default: out[0] = h0, out[1] = h0 / aspect; break;
    }
}

static int p1_mistakes(P1Model m)
{
    return (m.angle != 0) + (m.angle == 3) + !m.factor2 + !m.use_d + (m.shape != 0);
}

static bool p1_matches(P1Model m, const double *in, const double *got)
{
    double v[2];
    p1_eval(m, in, v);
    return same(got[0], v[0], fabs(v[0])) && same(got[1], v[1], fabs(v[1]));
}

typedef struct {
    bool have_model;
    P1Model model;
    bool tan90;
    double factor;  /* a degrees-to-radians factor other than pi / 180 that
                       every ordinary answer implies, or 0 */
    bool float_digits;  /* every ordinary answer right to float's precision
                           only, not every one a float */
} P1Found;

/* The answers of a right formula whose degrees-to-radians factor is k. */
static void p1_with_factor(double k, const double *in, double *out)
{
    out[1] = 2 * in[2] * tan(in[0] / 2 * k);
    out[0] = in[1] * out[1];
}

/* Right to a few roundings of float (24 bits): within 2^-19 of itself. */
#define FLOAT_DIGITS 0x1p-19

/* tan(alpha/2) from its complement: 180 - alpha is exact near 180. */
static double p1_h_near_180(double fov, double d)
{
    return 2 * d / tan((180 - fov) * (M_PI / 360));
}

/* Does got look like a correct formula whose angle was rounded: is the
 * angle it implies within a few roundings of alpha pi / 360?  (Rounded past
 * 90 degrees, the angle gives a negative h: atan(2 d / h) is still
 * 90 degrees less that angle.) */
static bool p1_angle_rounding(const double *in, const double *got, double units)
{
    double fov = in[0], d = in[2];
    if (!(fabs(got[1]) > 0) || !isfinite(got[1]) || fov < 90)
        return false;
    double eps = (180 - fov) * (M_PI / 360);            /* pi/2 - theta, to a few u */
    double implied = atan(2 * d / got[1]);              /* pi/2 - the theta got used */
    return fabs(implied - eps) <= units * U * (M_PI / 2);
}

static bool p1_explains(const void *ctx, int tag, const Test *t, const Case *c, const double *got)
{
    const P1Found *p = ctx;
    (void)tag;
    (void)t;
    if (p->have_model && p1_matches(p->model, c->in, got))
        return true;
    if (p->factor > 0) {
        double v[2];
        p1_with_factor(p->factor, c->in, v);
        return same(got[0], v[0], fabs(v[0])) && same(got[1], v[1], fabs(v[1]));
    }
    if (p->float_digits) {
        double v[2];
        p1_with_factor(M_PI / 180, c->in, v);
        if (fabs(got[0] - v[0]) <= FLOAT_DIGITS * fabs(v[0]) &&
            fabs(got[1] - v[1]) <= FLOAT_DIGITS * fabs(v[1]))
            return true;
        /* Near 180 degrees tan magnifies the angle's rounding: there the
         * angle the answer implies is right to a few roundings of float. */
        return p1_angle_rounding(c->in, got, 0x1p32) &&
               fabs(got[0] - c->in[1] * got[1]) <= FLOAT_DIGITS * fabs(got[0]);
    }
    return p->tan90 && p1_angle_rounding(c->in, got, 8) && fabs(got[0] - c->in[1] * got[1]) <= 1e-12 * got[0];
}

/* Part 1's probes: ordinary fields of view, and those near 180 degrees. */
static const double p1_ordinary[][3] = {
    { 60, 2, 1.5 }, { 90, 0.5, 3 }, { 30, 1.5, 0.5 }, { 120, 1.25, 2 }, { 10, 4.0 / 3, 0.75 },
};
static const double p1_near180[][3] = {
    { 179.99, 1, 1 }, { 179.9999, 1, 1 }, { 179.999999, 1, 1 }, { 179.99999999, 1, 1 },
};
enum { N_FOV_ORDINARY = sizeof p1_ordinary / sizeof *p1_ordinary, N_FOV_NEAR180 = sizeof p1_near180 / sizeof *p1_near180 };

/* The simplest model that explains every ordinary answer. */
static void p1_simplest_model(P1Found *out, const Answers *ab)
{
    int best = 99;
    for (int angle = 0; angle < 4; angle++)
        for (int f2 = 0; f2 < 2; f2++)
            for (int ud = 0; ud < 2; ud++)
                for (int shape = 0; shape < 5; shape++) {
                    P1Model m = { angle, f2, ud, shape };
                    bool all = true;
                    for (int c = 0; c < N_FOV_ORDINARY && all; c++)
                        all = p1_matches(m, p1_ordinary[c], ab->got[c]);
                    if (all && p1_mistakes(m) < best) {
                        best = p1_mistakes(m);
                        out->model = m;
                        out->have_model = true;
                    }
                }
}

/* A right formula with a wrong constant: the factor from degrees to
 * radians each answer implies, k = 2 atan(h / 2 d) / alpha, is the same
 * in every case (to double's roundings) but is not pi / 180, as with
 * pi written 3.14159 or the factor 0.0174533. */
static void p1_pi_approximate(Found *f, P1Found *out, const Answers *ab)
{
    double kmin = INFINITY, kmax = -INFINITY;
    bool shaped = true;
    for (int c = 0; c < N_FOV_ORDINARY; c++) {
        const double *in = p1_ordinary[c], *got = ab->got[c];
        double k = 2 * atan(got[1] / (2 * in[2])) / in[0];
        shaped = shaped && got[1] > 0 && fabs(got[0] - in[1] * got[1]) <= 1e-12 * fabs(got[0]);
        kmin = fmin(kmin, k);
        kmax = fmax(kmax, k);
    }
    double k = (kmin + kmax) / 2, off = k / (M_PI / 180) - 1;
    if (shaped && kmax - kmin <= 1e-12 * k && fabs(off) > 1e-10 && fabs(off) < 1e-2) {
        out->factor = k;
        name_cause(f, "pi-approximate", TAG_ALL, "the factor from degrees to radians is %s by %.2g "
                   "of itself: every answer is that of the right formula with %.10g in place of "
                   "pi / 180 = 0.017453292519943295, as if pi were %.9g. Use M_PI (raytracer.h "
                   "defines it), not a value of pi or of pi / 180 written out.",
                   off > 0 ? "too large" : "too small", fabs(off), k, k * 180);
    }
}

/* Right to float's digits only, but not every answer a float: float
 * somewhere inside (a float variable, tanf, a constant written 180.0f). */
static void p1_float_inside(Found *f, P1Found *out, const Answers *ab)
{
    double v[N_FOV_ORDINARY][CASE_MAX_OUT];
    for (int c = 0; c < N_FOV_ORDINARY; c++)
        p1_with_factor(M_PI / 180, p1_ordinary[c], v[c]);
    int c, k;
    double worst = worst_error(ab, (const double (*)[CASE_MAX_OUT])v, NULL, N_FOV_ORDINARY, 2, &c, &k);
    if (worst <= FLOAT_DIGITS && worst > 1e-9) {
        char b0[40], b1[40];
        out->float_digits = true;
        name_cause(f, "float", TAG_ALL, "your answers agree with the right ones to about 7 digits, "
                   "float's precision, and no further: for alpha = %g, aspect = %g, d = %g your "
                   "%s = %s, the right one %s (off by %.2g of itself). Some of the computation is "
                   "in float (a float variable, tanf, a constant written 180.0f): use double "
                   "throughout.", p1_ordinary[c][0], p1_ordinary[c][1], p1_ordinary[c][2], k ? "h" : "w",
                   kit_shortest_double(b0, sizeof b0, ab->got[c][k]),
                   kit_shortest_double(b1, sizeof b1, v[c][k]), worst);
    }
}

/* Each mistake of the model found, named; g the answer for alpha = 90,
 * aspect = 0.5, d = 3. */
static void p1_model_mistakes(Found *f, P1Model m, const double *g)
{
    if (m.angle == 1 || m.angle == 3)
        name_cause(f, "degrees-as-radians", TAG_ALL, "tan was given the angle in degrees: for alpha = 90, "
                   "aspect = 0.5, d = 3 your code returned h = %.6g, which is %s tan(%s) with %s "
                   "read as radians. tan takes radians: multiply degrees by pi / 180 (and if your "
                   "function treats the field of view as radians, it is given in degrees here).",
                   g[1], m.factor2 ? "2 d" : "d", m.angle == 1 ? "45" : "90", m.angle == 1 ? "45" : "90");
    if (m.angle >= 2)
        name_cause(f, "full-angle", TAG_ALL, "tan of the whole field of view: h = 2 d tan(alpha / 2) "
                   "uses half the angle (the plane spans alpha / 2 above the axis and alpha / 2 below).");
    if (!m.factor2)
        name_cause(f, "no-factor-2", TAG_ALL, "the factor 2 is missing: tan(alpha / 2) gives half the "
                   "plane's height, h / (2 d); h = 2 d tan(alpha / 2).");
    if (!m.use_d)
        name_cause(f, "d-ignored", TAG_ALL, "the plane is sized as if d = 1 (for d = 3 your h is a third "
                   "of the right one): h = 2 d tan(alpha / 2) grows with d. Tutorials such as "
                   "Scratchapixel put the plane at distance 1; this lab's is at d.");
    if (m.shape == 1)
        name_cause(f, "aspect-inverted", TAG_ALL, "the aspect ratio is inverted: w = aspect h, with "
                   "aspect = nx / ny (for aspect 0.5 the plane is half as wide as it is tall).");
    if (m.shape == 2)
        name_cause(f, "w-h-swapped", TAG_ALL, "w and h are swapped: h = 2 d tan(alpha / 2) is the "
                   "height, and w = aspect h the width.");
    if (m.shape == 4)
        name_cause(f, "shorter-axis", TAG_ALL, "for tall images the field of view was taken "
                   "along the width, the image's shorter side (pbrt's convention): in this lab "
                   "alpha is always VERTICAL, h = 2 d tan(alpha / 2), whatever the aspect.");
    if (m.shape == 3)
        name_cause(f, "horizontal-fov", TAG_ALL, "the field of view is taken as the horizontal one "
                   "(w = 2 d tan(alpha / 2), h = w / aspect): in this lab alpha is VERTICAL, so "
                   "h = 2 d tan(alpha / 2) and w = aspect h.");
}

/* Near 180: a right formula whose rounded angle tan amplifies. */
static void p1_tan_near_90(const ProbeSet *ps, Found *f, P1Found *out, const Answers *af)
{
    bool wrong = false, rounding = true;
    double worst = 0, worst_fov = 0;
    for (int c = 0; c < N_FOV_NEAR180; c++) {
        double h = p1_h_near_180(p1_near180[c][0], 1);
        double rel = fabs(af->got[c][1] - h) / h;
        if (rel > 32 * U) {
            wrong = true;
            rounding = rounding && p1_angle_rounding(p1_near180[c], af->got[c], 8);
            if (rel > worst)
                worst = rel, worst_fov = p1_near180[c][0];
        }
    }
    if (wrong && rounding) {
        out->tan90 = true;
        name_cause(f, "tan-near-90", TAG_ALL, "h = 2 d tan(alpha / 2), the lecture's formula, loses "
                   "digits near 180 degrees, and so do your answers (at alpha = %.12g, h is off by "
                   "%.2g of itself): alpha pi / 360 is "
                   "rounded to a double like any number, and tan is so steep near 90 degrees that "
                   "this rounding of 1e-16 is magnified many times. Keeping those digits is the "
                   "handout's hard-case challenge (extra credit).%s", worst_fov, worst,
                   ps->probes->full_hints ? " Above 45 degrees use tan(alpha / 2) = 1 / tan(90 - "
                                            "alpha / 2): 180 - alpha is exact." : "");
    }
}

static void diagnose_part1(ProbeSet *ps, Found *f, P1Found *out)
{
    probe_add(ps, PART1, KIND_PLANE, "probe: ordinary fields of view", *p1_ordinary, 3, N_FOV_ORDINARY);
    probe_add(ps, PART1, KIND_PLANE, "probe: fields of view near 180 degrees", *p1_near180, 3,
              N_FOV_NEAR180);
    const Answers *a = probes_run(ps);
    const Answers ordinary = a[0], near180 = a[1];
    if (unwritten(f, ps))
        return;
    if (ordinary.answered == N_FOV_ORDINARY)
        p1_simplest_model(out, &ordinary);
    double model[N_FOV_ORDINARY][CASE_MAX_OUT];
    for (int c = 0; c < N_FOV_ORDINARY; c++)
        p1_eval(out->have_model ? out->model : (P1Model){ 0, 1, 1, 0 }, p1_ordinary[c], model[c]);
    bool in_float = all_float(&ordinary, 2, (const double (*)[CASE_MAX_OUT])model, N_FOV_ORDINARY);

    const P1Model m = out->model;
    const double *g = ordinary.answered ? ordinary.got[1] : NULL;     /* alpha = 90, aspect 0.5, d = 3 */
    if (ordinary.answered == N_FOV_ORDINARY)
        p1_pi_approximate(f, out, &ordinary);
    if (ordinary.answered == N_FOV_ORDINARY && !in_float && out->factor == 0)
        p1_float_inside(f, out, &ordinary);
    if (out->have_model && p1_mistakes(m) > 0)
        p1_model_mistakes(f, m, g);
    if (in_float && (!out->have_model || m.angle == 0)) {
        char b[40];
        name_cause(f, "float", TAG_ALL, "computed in float: every answer is a float (24 bits, about 7 digits), "
                   "e.g. h = %s for alpha = 90, aspect = 0.5, d = 3. Use double throughout "
                   "(tan, not tanf; 180.0, not 180.0f).", kit_shortest_double(b, sizeof b, g ? g[1] : 0));
    }
    if (out->have_model && m.angle == 0 && m.factor2 && m.use_d && !in_float &&
        near180.answered == N_FOV_NEAR180)
        p1_tan_near_90(ps, f, out, &near180);
}

/* ==== Part 2 ================================================================ */

/* Models of each coordinate, one at a time: x depends on i, nx, w; y on
 * j, ny, h; z on d. */
/* X_INT, X_INT_RIGHT, Y_INT, Y_INT_TOP: an integer division, 0 whatever
 * the pixel, leaves x or y at an edge of the plane, which edge as the
 * formula has it ((2 i + 1) / (2 nx) in -w/2 + w (...) or w/2 - w (...)). */
enum { X_RIGHT, X_CORNER, X_FAR_CORNER, X_NOT_CENTRED, X_SWAPPED, X_INT, X_INT_RIGHT, X_NM1, X_SQUARE,
       X_FROM_J, NX_MODELS };
enum { Y_RIGHT, Y_BOTTOM, Y_CORNER, Y_FAR_CORNER, Y_BOTTOM_CORNER, Y_NX, Y_NOT_CENTRED, Y_SWAPPED,
       Y_INT, Y_INT_TOP, Y_NM1, Y_BOTTOM_NM1, Y_FROM_I, NY_MODELS };
enum { Z_RIGHT, Z_PLUS, Z_ONE, NZ_MODELS };

static double p2_x(int m, const double *in)
{
    double i = in[0], nx = in[2], w = in[4], h = in[5];
    switch (m) {
    case X_RIGHT:       return -w / 2 + w * (i + 0.5) / nx;
    case X_CORNER:      return -w / 2 + w * i / nx;
    case X_FAR_CORNER:  return -w / 2 + w * (i + 1) / nx;
    case X_NOT_CENTRED: return w * (i + 0.5) / nx;
    case X_SWAPPED:     return -h / 2 + h * (i + 0.5) / nx;
    case X_NM1:         return -w / 2 + w * i / (nx - 1);         /* nx - 1 steps: edge to edge */
    case X_SQUARE:      return h * (i + 0.5 - nx / 2) / in[3];    /* in units of h / ny */
    case X_FROM_J:      return -w / 2 + w * (in[1] + 0.5) / nx;   /* i and j swapped */
    case X_INT_RIGHT:   return w / 2;
    default:            return -w / 2;
    }
}

static double p2_y(int m, const double *in)
{
    double j = in[1], nx = in[2], ny = in[3], w = in[4], h = in[5];
    switch (m) {
    case Y_RIGHT:         return h / 2 - h * (j + 0.5) / ny;
    case Y_BOTTOM:        return -h / 2 + h * (j + 0.5) / ny;
    case Y_CORNER:        return h / 2 - h * j / ny;
    case Y_FAR_CORNER:    return h / 2 - h * (j + 1) / ny;
    case Y_BOTTOM_CORNER: return -h / 2 + h * j / ny;
    case Y_NX:            return -h / 2 + h * (ny - 0.5 - j) / nx;
    case Y_NOT_CENTRED:   return h * (ny - 0.5 - j) / ny;
    case Y_SWAPPED:       return w / 2 - w * (j + 0.5) / ny;
    case Y_NM1:           return h / 2 - h * j / (ny - 1);
    case Y_BOTTOM_NM1:    return -h / 2 + h * j / (ny - 1);
    case Y_FROM_I:        return h / 2 - h * (in[0] + 0.5) / ny;  /* i and j swapped */
    case Y_INT_TOP:       return h / 2;
    default:              return -h / 2;
    }
}

static double p2_z(int m, const double *in)
{
    double d = in[6];
    return m == Z_RIGHT ? -d : m == Z_PLUS ? d : -1;
}

typedef struct {
    int x, y, z;                   /* the model of each coordinate, or -1 */
} P2Found;

static double p2_scale(const double *in)
{
    return fmax(fmax(fabs(in[4]), fabs(in[5])), fabs(in[6]));
}

static bool p2_coord_matches(int coord, int m, const double *in, double got)
{
    double v = coord == 0 ? p2_x(m, in) : coord == 1 ? p2_y(m, in) : p2_z(m, in);
    return same(got, v, p2_scale(in));
}

static bool p2_explains(const void *ctx, int tag, const Test *t, const Case *c, const double *got)
{
    const P2Found *p = ctx;
    (void)tag;
    (void)t;
    const int m[3] = { p->x, p->y, p->z };
    for (int k = 0; k < 3; k++) {
        if (c->tol[k] >= 0 && fabs(got[k] - c->want[k]) <= c->tol[k])
            continue;                                   /* this coordinate is right */
        if (m[k] < 0 || !p2_coord_matches(k, m[k], c->in, got[k]))
            return false;
    }
    return true;
}

/* Part 2's probe, i j nx ny w h d: pixels not square, w / h far from
 * nx / ny, d not 1. */
static const double p2_cases[][7] = {
    { 1, 0, 4, 3, 2.5, 1.2, 1.5 }, { 3, 2, 5, 4, 4, 3, 2 }, { 0, 3, 6, 4, 6.4, 2.2, 0.5 },
    { 2, 1, 3, 5, 1.2, 2.6, 1.25 }, { 4, 0, 5, 7, 2, 3, 3 }, { 6, 5, 7, 6, 3.3, 1.7, 0.8 },
};
enum { N_PIXELS = sizeof p2_cases / sizeof *p2_cases };

/* Right to float's digits only: float somewhere inside.  model holds
 * the right answers. */
static void p2_float_inside(Found *f, const Answers *a, const double (*model)[CASE_MAX_OUT])
{
    const double (*cases)[7] = p2_cases;
    double scale[N_PIXELS];
    for (int c = 0; c < N_PIXELS; c++)
        scale[c] = p2_scale(cases[c]);
    int c, k;
    double worst = worst_error(a, model, scale, N_PIXELS, 3, &c, &k);
    char b0[40], b1[40];
    if (worst > 1e-10 && worst <= FLOAT_DIGITS)
        name_cause(f, "float", TAG_ALL, "your coordinates agree with the right ones to about 7 "
                   "digits, float's precision, and no further: for pixel (%g, %g) of a %g x %g image "
                   "your %c = %s, the right one %s. Some of the computation is in float (a float "
                   "variable, a constant written 0.5f): use double throughout.", cases[c][0], cases[c][1],
                   cases[c][2], cases[c][3], "xyz"[k], kit_shortest_double(b0, sizeof b0, a->got[c][k]),
                   kit_shortest_double(b1, sizeof b1, model[c][k]));
}

static void diagnose_part2(ProbeSet *ps, Found *f, P2Found *out)
{
    const double (*cases)[7] = p2_cases;
    enum { N = N_PIXELS };
    probe_add(ps, PART2, KIND_PIXEL, "probe: pixels of images that are not square", *cases, 7, N);
    const Answers a = probes_run(ps)[0];
    out->x = out->y = out->z = -1;
    if (a.answered < N || unwritten(f, ps))
        return;
    const int nmodels[3] = { NX_MODELS, NY_MODELS, NZ_MODELS };
    int *which[3] = { &out->x, &out->y, &out->z };
    for (int coord = 0; coord < 3; coord++)
        for (int m = 0; m < nmodels[coord] && *which[coord] < 0; m++) {
            bool all = true;
            for (int c = 0; c < N && all; c++)
                all = p2_coord_matches(coord, m, cases[c], a.got[c][coord]);
            if (all)
                *which[coord] = m;
        }
    double model[N][CASE_MAX_OUT];
    for (int c = 0; c < N; c++) {
        model[c][0] = p2_x(X_RIGHT, cases[c]);
        model[c][1] = p2_y(Y_RIGHT, cases[c]);
        model[c][2] = p2_z(Z_RIGHT, cases[c]);
    }
    const double *g = a.got[0], *in = cases[0];
    int x = out->x, y = out->y;
    bool x_int = x == X_INT || x == X_INT_RIGHT, y_int = y == Y_INT || y == Y_INT_TOP;
    if (x_int || y_int) {
        name_cause(f, "integer-division", TAG_ALL, "%s came back at the plane's %s (%s%s%s) whatever the "
                   "pixel: an integer division such as (2 * i + 1) / (2 * nx) is 0 in C when both "
                   "are ints. Write 0.5 or convert to double first: (i + 0.5) / nx.",
                   x_int && y_int ? "every pixel" : x_int ? "x" : "y", x_int && y_int ? "corner" : "edge",
                   x_int ? (x == X_INT ? "x = -w/2" : "x = w/2") : "", x_int && y_int ? ", " : "",
                   y_int ? (y == Y_INT ? "y = -h/2" : "y = h/2") : "");
        x = x_int ? X_RIGHT : x;
        y = y_int ? Y_RIGHT : y;
    }
    if (x == X_CORNER || x == X_FAR_CORNER || y == Y_CORNER || y == Y_FAR_CORNER || y == Y_BOTTOM_CORNER)
        name_cause(f, "pixel-corner", TAG_ALL, "that is a pixel's corner, not its centre: for pixel (%g, %g) "
                   "of a %g x %g image your code returned (%.6g, %.6g), half a pixel from the centre "
                   "(%.6g, %.6g). The centre is at i + 0.5 and j + 0.5 (written i + 1 / 2, it is i: "
                   "1 / 2 is an integer division, 0 in C; write 0.5).",
                   in[0], in[1], in[2], in[3], g[0], g[1], model[0][0], model[0][1]);
    if (x == X_NM1 || y == Y_NM1 || y == Y_BOTTOM_NM1)
        name_cause(f, "n-minus-1", TAG_ALL, "x and y step by w / (nx - 1) and h / (ny - 1), so the "
                   "first and last pixels sit on the plane's edges (as in early versions of Ray Tracing "
                   "in One Weekend): each pixel's centre is w / nx apart, x = -w/2 + w (i + 0.5) / nx, "
                   "y = h/2 - h (j + 0.5) / ny.");
    if (x == X_SQUARE)
        name_cause(f, "square-pixels", TAG_ALL, "x is measured in units of h / ny (Shadertoy's uv "
                   "= (fragCoord - 0.5 iResolution) / iResolution.y): right only where pixels are "
                   "square, w / nx = h / ny. x uses the plane's width: x = -w/2 + w (i + 0.5) / nx.");
    if (y == Y_BOTTOM || y == Y_BOTTOM_CORNER || y == Y_BOTTOM_NM1)
        name_cause(f, "bottom-origin", TAG_ALL, "y is upside down: row j = 0 came out at the bottom of the "
                   "plane (y < 0), as in OpenGL and many image libraries. In this lab row 0 is the TOP "
                   "row: y = h/2 - h (j + 0.5) / ny.");
    if (y == Y_NX)
        name_cause(f, "nx-for-y", TAG_ALL, "y divides by nx: rows are counted by ny, y = -h/2 + h (ny - 0.5 - j) / ny.");
    if (x == X_NOT_CENTRED || y == Y_NOT_CENTRED)
        name_cause(f, "not-centred", TAG_ALL, "the plane is not centred on the axis: x runs from -w/2 to w/2 "
                   "(and y from -h/2 to h/2), not from 0.");
    if (x == X_FROM_J && y == Y_FROM_I)
        name_cause(f, "i-j-swapped", TAG_ALL, "i and j are swapped: i is the column, counted from the "
                   "left, and gives x; j is the row, counted from the top, and gives y (pixel (i, j) "
                   "as (x, y), not as (row, column)).");
    if (x == X_SWAPPED || y == Y_SWAPPED)
        name_cause(f, "w-h-swapped", TAG_ALL, "w and h are swapped: x spans the width w (with nx columns), "
                   "y the height h (with ny rows).");
    if (out->z == Z_PLUS)
        name_cause(f, "z-sign", TAG_ALL, "z has the wrong sign: the eye looks down -z, so the plane is at "
                   "z = -d (your z was +d).");
    if (out->z == Z_ONE)
        name_cause(f, "d-ignored", TAG_ALL, "z is -1 whatever d: the plane is at z = -d (tutorials "
                   "such as Scratchapixel put it at distance 1; this lab's is at d).");
    if (x == X_RIGHT && y == Y_RIGHT && all_float(&a, 2, (const double (*)[CASE_MAX_OUT])model, N)) {
        char b[40];
        name_cause(f, "float", TAG_ALL, "computed in float: every coordinate is a float (24 bits, about 7 "
                   "digits), e.g. x = %s. Use double throughout.",
                   kit_shortest_double(b, sizeof b, g[0]));
    } else if (x == X_RIGHT && y == Y_RIGHT && out->z == Z_RIGHT) {
        p2_float_inside(f, &a, (const double (*)[CASE_MAX_OUT])model);
    }
}

/* ==== Part 3a ================================================================ */

typedef struct {
    double A, B, C, disc;
    bool real;
    double t0, t1;                 /* the roots, t0 <= t1, when real */
} Quad;

static Quad quad(const double *in)
{
    const double *c = in, *e = in + 4, *r = in + 7;
    double R = in[3], f[3] = { e[0] - c[0], e[1] - c[1], e[2] - c[2] };
    Quad q;
    q.A = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    q.B = f[0] * r[0] + f[1] * r[1] + f[2] * r[2];
    q.C = f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - R * R;
    q.disc = q.B * q.B - q.A * q.C;
    q.real = q.disc >= 0 && q.A > 0;
    q.t0 = q.t1 = NAN;
    if (q.real) {
        double sq = sqrt(q.disc);
        double qq = q.B < 0 ? sq - q.B : -(q.B + sq);
        double r0 = qq != 0 ? q.C / qq : -q.B / q.A, r1 = qq / q.A;
        q.t0 = fmin(r0, r1);
        q.t1 = fmax(r0, r1);
    }
    return q;
}

/* A hit/miss answer as a pair; miss is (0, 0). */
static void hit(double *out, bool h, double t)
{
    out[0] = h ? 1 : 0;
    out[1] = h ? t : 0;
}

/* The smallest root above tmin, as the lecture's rule with tmin = 0. */
static void first_root_above(const Quad *q, double tmin, double *out)
{
    if (!q->real)
        hit(out, false, 0);
    else if (q->t0 > tmin)
        hit(out, true, q->t0);
    else
        hit(out, q->t1 > tmin, q->t1);
}

enum { M_RIGHT, M_FAR, M_HALVED, M_DISC4, M_UNIT, M_DISTANCE, M_BEHIND, M_BSIGN, M_INSIDE_MISS,
       M_CENTRE_BEHIND, M_TANGENT_MISS, M_TMIN, M_NAN, M_FLOAT, M_T_ZERO, NMODELS3, M_CANCEL = NMODELS3 };

/* What cause m answers to a case.  tmin is the epsilon M_TMIN uses. */
static void p3_eval(int m, const double *in, double tmin, double *out)
{
    Quad q = quad(in);
    const double *r = in + 7;
    double len = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    switch (m) {
    case M_FAR:
        hit(out, q.real && q.t1 > 0, q.t1);
        break;
    case M_HALVED:
        first_root_above(&q, 0, out);
        out[1] /= 2;
        break;
    case M_DISC4: {
        double d4 = q.B * q.B - 4 * q.A * q.C;
        double t = d4 >= 0 ? (-q.B - sqrt(d4)) / (2 * q.A) : -1;
        hit(out, t > 0, t);
        break;
    }
    case M_UNIT: {                                  /* A = 1 whatever r */
        double d1 = q.B * q.B - q.C;
        double t0 = -q.B - sqrt(d1), t1 = -q.B + sqrt(d1);
        hit(out, d1 >= 0 && (t0 > 0 || t1 > 0), t0 > 0 ? t0 : t1);
        break;
    }
    case M_DISTANCE:                                /* the distance along the ray, t |r| */
        first_root_above(&q, 0, out);
        out[1] *= len;
        break;
    case M_BEHIND:                                  /* the smaller root, whatever its sign */
        hit(out, q.real, q.t0);
        break;
    case M_BSIGN: {                                 /* t = (B -+ sqrt) / A */
        Quad m2 = q;
        m2.t0 = -q.t1, m2.t1 = -q.t0;
        first_root_above(&m2, 0, out);
        break;
    }
    case M_INSIDE_MISS:                             /* the near root alone: behind from */
        if (q.C <= 0)                               /* inside, the origin itself from on */
            hit(out, false, 0);
        else
            first_root_above(&q, 0, out);
        break;
    case M_CENTRE_BEHIND:                           /* "if (tca < 0) return false" */
        if (q.B > 0)
            hit(out, false, 0);
        else
            first_root_above(&q, 0, out);
        break;
    case M_TANGENT_MISS:
        if (q.disc == 0)
            hit(out, false, 0);
        else
            first_root_above(&q, 0, out);
        break;
    case M_TMIN:
        first_root_above(&q, tmin, out);
        break;
    case M_FLOAT:
        first_root_above(&q, 0, out);
        out[1] = (float)out[1];
        break;
    default:
        first_root_above(&q, 0, out);
        break;
    }
}

/* Is got model's answer, t to a relative rel (at least 6 digits)? */
static bool p3_same(const double *got, const double *model, double rel)
{
    if (got[0] != model[0])
        return false;
    return model[0] == 0 || fabs(got[1] - model[1]) <= fmax(rel, MATCH_REL) * fabs(model[1]);
}

/* Right as the core tests judge an ordinary case: to 1e-9 (rel), or for
 * code found to compute in float, to float's precision. */
static bool p3_right(const double *got, const double *in, double rel)
{
    double v[2];
    p3_eval(M_RIGHT, in, 0, v);
    if (got[0] != v[0])
        return false;
    return v[0] == 0 || fabs(got[1] - v[1]) <= rel * fabs(v[1]);
}

typedef struct {
    bool model[NMODELS3];          /* causes with a model, confirmed */
    double tmin;                   /* the epsilon M_TMIN confirmed   */
    bool cancellation;
    double rel;                    /* "right" to this relative error */
    bool float_digits;             /* M_FLOAT: t right to 5-7 digits, not floats */
} P3aFound;

static bool p3_explains(const void *ctx, int tag, const Test *t, const Case *c, const double *got)
{
    const P3aFound *p = ctx;
    if (tag == M_CANCEL)                 /* the textbook's losses: the hard cases */
        return t->hard;
    if (tag == M_NAN)
        return got[0] == 1 && !isfinite(got[1]);
    if (tag == M_T_ZERO)                 /* a hit at the ray's own origin */
        return got[0] == 1 && got[1] == 0;
    if (tag == M_FLOAT && p->float_digits)   /* a t right to float's digits, not further */
        return got[0] == 1 && c->want[0] == 1 && fabs(got[1] - c->want[1]) <= 1e-5 * fabs(c->want[1]);
    if (tag == M_FLOAT)                  /* a t rounded to float, right or not */
        return got[0] == 1 && is_float(got[1]) && !(c->want[0] == 1 && is_float(c->want[1]));
    double v[2];
    p3_eval(tag, c->in, p->tmin, v);
    return p3_same(got, v, p->rel);
}

/* Every answer of a probe is model m's (and, somewhere, not the right one). */
static bool p3_all(const Answers *a, const double (*in)[CASE_MAX_IN], int n, int m, double tmin, double rel)
{
    if (a->answered < n)
        return false;
    bool differs = false;
    for (int c = 0; c < n; c++) {
        double v[2];
        p3_eval(m, in[c], tmin, v);
        if (!p3_same(a->got[c], v, rel))
            return false;
        differs = differs || !p3_right(a->got[c], in[c], rel);
    }
    return differs;
}

static bool p3_all_right(const Answers *a, const double (*in)[CASE_MAX_IN], int n, double rel)
{
    if (a->answered < n)
        return false;
    for (int c = 0; c < n; c++)
        if (!p3_right(a->got[c], in[c], rel))
            return false;
    return true;
}

#define SPH(cx, cy, cz, R, ex, ey, ez, rx, ry, rz) { cx, cy, cz, R, ex, ey, ez, rx, ry, rz }

typedef const double (*Rays)[CASE_MAX_IN];

/* Part 3a's probes, in the order they run. */
enum { PROBE_ORDINARY, PROBE_SCALED, PROBE_BEHIND, PROBE_INSIDE, PROBE_TANGENT, PROBE_NEAR, PROBE_NAN,
       PROBE_FAR, PROBE_ON_SPHERE, NPROBES3 };
_Static_assert(NPROBES3 <= MAX_PROBES, "a ProbeSet holds the answers of Part 3a's probes");

/* Ordinary hits from outside, unit directions, answers not floats. */
static const double ordinary_rays[][CASE_MAX_IN] = {
    SPH(0.1, 0.2, -5.3, 1.3, 0, 0, 0, 0, 0, -1),
    SPH(4.5, 0.5, -6.2, 2.2, 0, 0, 0, 0.6, 0, -0.8),
    SPH(-2, 0.5, -6.1, 1.7, 0.3, 0.1, 0.2, -0.28, 0, -0.96),
    SPH(0, -1, -4.7, 1.1, 0, 0, 0, 0, -0.28, -0.96),
    SPH(0.3, -0.7, -9.1, 2.9, 0, 0, 0, 0, 0, -1),
    SPH(0.05, 0, -1.9, 1.7, 0, 0, 0, 0, 0, -1),         /* near: B^2 - 4 A C >= 0 */
};
/* Spheres wholly behind the origin (misses), then one ahead. */
static const double behind_rays[][CASE_MAX_IN] = {
    SPH(0, 0, 5.2, 1.3, 0, 0, 0, 0, 0, -1),
    SPH(1, 1, 9, 2.5, 0, 0, 0, -0.6, 0, -0.8),
    SPH(0, 0.5, 7.3, 1, 0, 0, 0, 0, 0, -2),
    SPH(0, 0, -5.2, 1.3, 0, 0, 0, 0, 0, -1),
};
/* From inside: the hit is the exit point. */
static const double inside_rays[][CASE_MAX_IN] = {
    SPH(0, 0, 0, 10.3, 0, 0, 0, 0, 0, -1),
    SPH(0.5, -0.2, -1, 5.1, 0, 0, 0, 0.6, 0, -0.8),
    SPH(1, 2, 3, 50.7, 0, 0, 0, 0, 0.28, 0.96),
    SPH(0, 0, 1.3, 5.1, 0, 0, 0, 0, 0, -1),             /* the centre behind the origin */
    SPH(-0.5, 1, 2, 4.2, 0, 0, 0, 0.6, 0, -0.8),
};
/* Exact tangents: B^2 - A C is 0 in any order of operations. */
static const double tangent_rays[][CASE_MAX_IN] = {
    SPH(2, 0, -10, 2, 0, 0, 0, 0, 0, -1),
    SPH(0, -3, -6, 3, 0, 0, 0, 0, 0, -2),
    SPH(-1.5, 0, -4, 1.5, 0, 0, 0, 0, 0, -0.5),
};
/* Hits just ahead of the origin: e a gap g outside the sphere, so the
 * hit is at t = g exactly (binary fractions), the far root at g + 2. */
static const double near_gaps[] = { 0x1p-30, 0x1p-23, 0x1p-17, 0x1p-14, 0x1p-12, 0x1.4p-11,
                                    0x1p-9, 0x1p-7, 0x1p-5, 0x1p-3, 0.5, 1.5, 4 };
/* A zero direction, and NaN input: misses. */
static const double nan_rays[][CASE_MAX_IN] = {
    SPH(0, 0, -5, 1, 0, 0, 0, 0, 0, 0),
    SPH(NAN, 0, -5, 1, 0, 0, 0, 0, 0, -1),
    SPH(0, 0, -1, 5, 0, 0, 0, 0, 0, 0),     /* a zero direction from inside */
};
/* Far, small spheres: B^2 and A C agree to 16 digits; the hit is at
 * D - sqrt(R^2 - rho^2), rho the line's distance from c. */
static const double far_rays[][CASE_MAX_IN] = {
    SPH(0.5, 0, -(0x1p27 + 1), 1, 0, 0, 0, 0, 0, -1),
    SPH(0, 0.6, -(0x1p28 + 3), 1, 0, 0, 0, 0, 0, -1),
    SPH(0.75, 0, -(0x1p29 + 5), 1, 0, 0, 0, 0, 0, -1),
};
/* Origins exactly on the sphere, axis-aligned unit directions: the
 * roots are 0 and 2, 4, 6 ahead (a hit there) or behind (a miss). */
static const double on_sphere_rays[][CASE_MAX_IN] = {
    SPH(0, 0, -1, 1, 0, 0, 0, 0, 0, -1),
    SPH(0, 0, -1, 1, 0, 0, 0, 0, 0, 1),
    SPH(2, 0, 0, 2, 0, 0, 0, 1, 0, 0),
    SPH(0, -3, 0, 3, 0, 0, 0, 0, 1, 0),
    SPH(1, 1, -3, 3, 1, 1, 0, 0, 0, -1),
};
enum { N_ORDINARY = 6, N_SCALED = 8, N_BEHIND = 4, N_INSIDE = 5, N_TANGENT = 3,
       N_NEAR = sizeof near_gaps / sizeof *near_gaps, N_NAN = 3, N_FAR = 3, N_ON_SPHERE = 5 };

static void add_probe3(ProbeSet *ps, const char *name, const double (*in)[CASE_MAX_IN], int n)
{
    probe_add(ps, PART3A, KIND_SPHERE, name, *in, CASE_MAX_IN, n);
}

/* Part 3a's probes, the rays computed here among them: the ordinary ones
 * with directions scaled by 3 and by 1/4 (t scales by 1/3 and 4), and
 * those just ahead of the origin. */
static void add_part3a_probes(ProbeSet *ps, double (*scaled)[CASE_MAX_IN], double (*near)[CASE_MAX_IN])
{
    for (int k = 0; k < N_SCALED; k++) {
        memcpy(scaled[k], ordinary_rays[k % 4], sizeof scaled[k]);
        for (int q = 7; q < 10; q++)
            scaled[k][q] *= k < 4 ? 3 : 0.25;
    }
    for (int k = 0; k < N_NEAR; k++) {
        double row[CASE_MAX_IN] = SPH(0, 0, -2, 1, 0, 0, -1 + near_gaps[k], 0, 0, -1);
        memcpy(near[k], row, sizeof row);
    }
    add_probe3(ps, "probe: ordinary hits", ordinary_rays, N_ORDINARY);
    add_probe3(ps, "probe: directions scaled by 3 and by 1/4", (Rays)scaled, N_SCALED);
    add_probe3(ps, "probe: spheres behind the origin", behind_rays, N_BEHIND);
    add_probe3(ps, "probe: from inside the sphere", inside_rays, N_INSIDE);
    add_probe3(ps, "probe: tangent rays", tangent_rays, N_TANGENT);
    add_probe3(ps, "probe: hits just ahead of the origin", (Rays)near, N_NEAR);
    add_probe3(ps, "probe: a zero direction and NaN input", nan_rays, N_NAN);
    add_probe3(ps, "probe: far, small spheres", far_rays, N_FAR);
    add_probe3(ps, "probe: rays that start on the sphere", on_sphere_rays, N_ON_SPHERE);
}

/* Rays that start on the sphere (C = 0 exactly, one root t = 0): every
 * answer right or a hit at t = 0 exactly, and one such hit, is t >= 0 taken
 * for t > 0 (Embree's inclusive tnear <= t).  Not named where roots behind
 * the origin are taken anyway (hits-behind says more). */
static void p3_t_zero(Found *f, P3aFound *out, const Answers *a, const double (*in)[CASE_MAX_IN], int n)
{
    if (out->model[M_BEHIND] || a->answered < n)
        return;
    int zero = -1;
    for (int c = 0; c < n; c++) {
        bool at_zero = a->got[c][0] == 1 && a->got[c][1] == 0;
        if (!at_zero && !p3_right(a->got[c], in[c], out->rel))
            return;
        if (at_zero && zero < 0)
            zero = c;
    }
    if (zero < 0)
        return;
    const double *z = in[zero];
    double v[2];
    p3_eval(M_RIGHT, z, 0, v);
    char right[80];
    if (v[0] == 1)
        snprintf(right, sizeof right, "a hit at t = %g, where the ray leaves the sphere", v[1]);
    else
        snprintf(right, sizeof right, "a miss: the ray heads away from the sphere");
    out->model[M_T_ZERO] = true;
    name_cause(f, "t-zero", M_T_ZERO, "a ray that starts on the sphere (C = 0, one root t = 0) was a hit "
               "at t = 0, its own origin: from (%g, %g, %g) along (%g, %g, %g), at the sphere of centre "
               "(%g, %g, %g) and radius %g, your code answered a hit at t = 0; the right answer is %s. A "
               "hit needs t > 0, not t >= 0 (Embree's ray interval, tnear <= t, includes its start; this "
               "lab's does not).",
               z[4], z[5], z[6], z[7], z[8], z[9], z[0], z[1], z[2], z[3], right);
}

/* Float first: every t of the probes a float, where the right ones are
 * not.  Then "right" means right to float's precision throughout (out->rel). */
static void p3_float(Found *f, P3aFound *out, const Answers *a, Rays scaled)
{
    const Answers *pf[] = { &a[PROBE_ORDINARY], &a[PROBE_SCALED], &a[PROBE_INSIDE], &a[PROBE_TANGENT] };
    const double (*pin[])[CASE_MAX_IN] = { ordinary_rays, scaled, inside_rays, tangent_rays };
    const int pn[] = { N_ORDINARY, N_SCALED, N_INSIDE, N_TANGENT };
    /* Or float inside: t not floats, but most right to float's digits and
     * no further (a double formula gets these to 1e-15; now and then one
     * comes out a float, or right, by chance). */
    int float_t = 0, near_t = 0, exact_t = 0, wk = 0, wc = 0;
    double worst = 0;
    for (int k = 0; k < 4; k++)
        for (int c = 0; c < pf[k]->answered && c < pn[k]; c++) {
            double right[2];
            p3_eval(M_RIGHT, pin[k][c], 0, right);
            if (pf[k]->got[c][0] != 1 || right[0] != 1 || is_float(right[1]))
                continue;
            double err = fabs(pf[k]->got[c][1] - right[1]) / right[1];
            if (!(err <= 1e-5))
                continue;                   /* wrong for another cause: no evidence */
            if (is_float(pf[k]->got[c][1]))
                float_t++;
            else if (err > 1e-10)
                near_t++;
            else
                exact_t++;
            if (err > worst)
                worst = err, wk = k, wc = c;
        }
    double rel = 1e-9;
    char b0[40], b1[40];
    if (float_t >= 3 && near_t + exact_t == 0) {
        out->model[M_FLOAT] = true;
        rel = 1e-5;
        name_cause(f, "float", M_FLOAT, "computed in float: every t is a float (24 bits, about 7 digits): "
                   "e.g. t = %s where the hit is at %s. Use double throughout (double, sqrt, not "
                   "float, sqrtf).", kit_shortest_double(b0, sizeof b0, a[PROBE_ORDINARY].got[0][1]),
                   kit_shortest_double(b1, sizeof b1, quad(ordinary_rays[0]).t0));
    } else if (near_t >= 3 && near_t > 2 * (exact_t + float_t)) {
        out->model[M_FLOAT] = true;
        out->float_digits = true;
        rel = 1e-5;
        name_cause(f, "float", M_FLOAT, "your t agree with the right ones to 5 to 7 digits, about "
                   "float's precision, and no further: e.g. t = %s where the hit is at %s. Some of "
                   "the computation is in float (a float variable, sqrtf): use double throughout.",
                   kit_shortest_double(b0, sizeof b0, pf[wk]->got[wc][1]),
                   kit_shortest_double(b1, sizeof b1, quad(pin[wk][wc]).t0));
    }
    out->rel = rel;
}

/* Hits just ahead: right from some gap up, wrong below: an epsilon. */
static void p3_tmin(Found *f, P3aFound *out, const Answers *got, Rays near)
{
    double rel = out->rel;
    if (got->answered != N_NEAR)
        return;
    int lowest_right = N_NEAR;
    bool threshold = true;
    for (int c = N_NEAR - 1; c >= 0; c--) {
        if (p3_right(got->got[c], near[c], rel) && lowest_right == c + 1)
            lowest_right = c;
    }
    for (int c = 0; c < lowest_right && threshold; c++) {
        double v[2];
        p3_eval(M_TMIN, near[c], near_gaps[c] * 1.0000001, v);       /* the far root */
        threshold = p3_same(got->got[c], v, rel) || got->got[c][0] == 0;
    }
    if (!threshold || lowest_right == 0 || lowest_right == N_NEAR)
        return;
    double lo = near_gaps[lowest_right - 1], hi = near_gaps[lowest_right];
    out->model[M_TMIN] = true;
    out->tmin = sqrt(lo * hi);
    const char *like = lo < 1e-3 && 1e-3 <= hi ? ": it looks like Ray Tracing in One Weekend's "
                                                 "t_min = 0.001"
                     : lo < 1e-4 && 1e-4 <= hi ? ": it looks like smallpt's eps = 1e-4"
                     : lo < 1 && 1 <= hi ? ": it looks like a t_min of 1 (Computer Graphics from "
                                           "Scratch's, which starts rays at the projection plane)"
                     : "";
    double v[2];
    p3_eval(M_RIGHT, near[lowest_right - 1], 0, v);
    name_cause(f, "tmin-epsilon", M_TMIN, "hits closer than a tmin between %.3g and %.3g are ignored%s. "
               "Asked for a hit at t = %.3g (the ray starts just outside the sphere), your code "
               "answered %s; from t = %.3g on it was right. This lab's rule is tmin = 0: every "
               "hit with t > 0 counts. Tutorials use an epsilon against shadow acne, next "
               "week's topic.", lo, hi, like, v[1],
               got->got[lowest_right - 1][0] == 0 ? "a miss" : "the far root", hi);
}

/* Ordinary hits: right (M_RIGHT, but for a tmin confirmed), or one
 * mistake's answers (its cause named), or -1. */
static int p3_ordinary_model(Found *f, P3aFound *out, const Answers *a)
{
    const Answers *ordinary = &a[PROBE_ORDINARY];
    double rel = out->rel;
    if (p3_all_right(ordinary, ordinary_rays, N_ORDINARY, rel) ||
        (out->model[M_TMIN] && p3_all(ordinary, ordinary_rays, N_ORDINARY, M_TMIN, out->tmin, rel)))
        return M_RIGHT;
    /* b-sign misses every sphere ahead: the spheres behind confirm it. */
    static const int plain[] = { M_FAR, M_HALVED, M_BSIGN, M_DISC4 };
    int model = -1;
    for (int k = 0; k < 4 && model < 0; k++)
        if (p3_all(ordinary, ordinary_rays, N_ORDINARY, plain[k], 0, rel) &&
            (plain[k] != M_BSIGN || p3_all(&a[PROBE_BEHIND], behind_rays, N_BEHIND, M_BSIGN, 0, rel)))
            model = plain[k];
    if (model < 0)
        return model;
    out->model[model] = true;
    if (model == M_FAR)
        name_cause(f, "far-root", M_FAR, "the far root: for a ray that enters the sphere at t = %.6g and "
                   "leaves at t = %.6g your code returned %.6g. The first hit is the smaller root "
                   "t > 0, (-B - sqrt(B^2 - A C)) / A.", quad(ordinary_rays[0]).t0,
                   quad(ordinary_rays[0]).t1, ordinary->got[0][1]);
    else if (model == M_HALVED)
        name_cause(f, "t-halved", M_HALVED, "every t is half the right one: with B = f.r (not 2 f.r) the roots "
                   "are (-B -+ sqrt(B^2 - A C)) / A, without the 2 of the school formula's 2a.");
    else if (model == M_DISC4)
        name_cause(f, "disc-4ac", M_DISC4, "B^2 - 4 A C mixes two forms: with the lecture's B = f.r the "
                   "discriminant is B^2 - A C and t = (-B -+ sqrt(B^2 - A C)) / A; the 4 and the 2 "
                   "belong with b = 2 f.r.");
    else
        name_cause(f, "b-sign", M_BSIGN, "the sign of B: spheres ahead were missed and spheres behind were "
                   "hit, as if the ray pointed backwards. With f = e - c, B = f.r and "
                   "t = (-B -+ sqrt(B^2 - A C)) / A.");
    return model;
}

/* Scaled directions: A = 1 assumed, or the distance returned. */
static void p3_scaled(Found *f, P3aFound *out, const Answers *got, Rays scaled)
{
    double rel = out->rel;
    if (got->answered != N_SCALED || p3_all_right(got, scaled, N_SCALED, rel))
        return;
    if (p3_all(got, scaled, N_SCALED, M_UNIT, 0, rel)) {
        out->model[M_UNIT] = true;
        name_cause(f, "unit-direction", M_UNIT, "the direction is assumed to have unit length: the same "
                   "ray with its direction r scaled by 3 must hit at a third of the t (%.6g), but "
                   "your code returned %.6g. r need not be a unit vector, so A = r.r is not 1 "
                   "(smallpt, Inigo Quilez's and tinyraytracer's tests assume |r| = 1).",
                   quad(scaled[0]).t0, got->got[0][1]);
    } else if (p3_all(got, scaled, N_SCALED, M_DISTANCE, 0, rel)) {
        out->model[M_DISTANCE] = true;
        name_cause(f, "distance-not-t", M_DISTANCE, "the distance along the ray is returned, not t: with "
                   "the direction scaled by 3 the hit must be at a third of the t (%.6g), but "
                   "your code returned the same %.6g. If you normalise r, divide the distance "
                   "by |r| to get t.", quad(scaled[0]).t0, got->got[0][1]);
    }
}

/* A hit at t <= 0 among these answers? */
static bool hit_at_or_behind_origin(const Answers *got)
{
    for (int c = 0; c < got->answered; c++)
        if (got->got[c][0] == 1 && got->got[c][1] <= 0)
            return true;
    return false;
}

/* Roots at t <= 0: behind the origin, or the near root from inside.
 * Says whether the near root from inside was one. */
static bool p3_behind(Found *f, P3aFound *out, const Answers *a)
{
    bool behind_neg = hit_at_or_behind_origin(&a[PROBE_BEHIND]);
    bool inside_neg = hit_at_or_behind_origin(&a[PROBE_INSIDE]);
    if (behind_neg || inside_neg) {
        out->model[M_BEHIND] = true;
        name_cause(f, "hits-behind", M_BEHIND, "a root with t <= 0 was returned as a hit (%s): t <= 0 is "
                   "behind the ray's origin, so it is no hit. Take the smaller root if it is > 0, "
                   "else the larger if it is > 0, else report a miss.",
                   inside_neg ? "from inside the sphere, the near root, which is behind the origin"
                              : "a sphere wholly behind the origin");
    }
    return inside_neg;
}

/* From inside, a miss: every ray, or those pointing away from the centre. */
static void p3_inside(Found *f, P3aFound *out, const Answers *got)
{
    if (got->answered != N_INSIDE)
        return;
    if (p3_all(got, inside_rays, N_INSIDE, M_INSIDE_MISS, 0, out->rel)) {
        out->model[M_INSIDE_MISS] = true;
        name_cause(f, "inside-miss", M_INSIDE_MISS, "from inside the sphere (C < 0) every ray was a miss: one root is "
                   "behind the origin and the other, t = %.6g here, is where the ray leaves the "
                   "sphere; that is the hit.", quad(inside_rays[0]).t1);
    } else if (p3_all(got, inside_rays, N_INSIDE, M_CENTRE_BEHIND, 0, out->rel)) {
        out->model[M_CENTRE_BEHIND] = true;
        name_cause(f, "inside-miss", M_CENTRE_BEHIND, "from inside the sphere, a ray pointing away from "
                   "its centre was a miss: an early exit such as \"if (tca < 0) return false\" (the "
                   "centre behind the origin) is right only from outside. From inside, the ray leaves "
                   "the sphere ahead, at t = %.6g here.", quad(inside_rays[3]).t1);
    }
}

/* Exact tangents, missed. */
static void p3_tangent(Found *f, P3aFound *out, const Answers *got)
{
    if (got->answered == N_TANGENT && p3_all(got, tangent_rays, N_TANGENT, M_TANGENT_MISS, 0, out->rel)) {
        out->model[M_TANGENT_MISS] = true;
        name_cause(f, "tangent-miss", M_TANGENT_MISS, "a tangent ray (B^2 - A C = 0 exactly) was a miss: it touches "
                   "the sphere at t = -B / A, and touching is a hit (test disc < 0 for a miss, not "
                   "disc <= 0).");
    }
}

/* A zero direction or NaN input answered as a hit at NaN, or a zero
 * direction from inside the sphere at infinity (a root written C / q). */
static void p3_nan(Found *f, P3aFound *out, const Answers *got)
{
    int c = 0;
    while (c < got->answered && !(got->got[c][0] == 1 && !isfinite(got->got[c][1])))
        c++;
    if (c == got->answered)
        return;
    out->model[M_NAN] = true;
    if (!isnan(got->got[c][1]))
        name_cause(f, "nan-hit", M_NAN, "a hit at t = infinity was returned (for a zero direction from "
                   "inside the sphere): with r = 0, A = 0, B = 0 and C < 0, so a root written C / q is "
                   "C / 0 = infinity, which passes t > 0. Reject A = 0 first: no direction, no ray.");
    else
        name_cause(f, "nan-hit", M_NAN, "a hit at t = NaN was returned (%s): with r = 0, A = 0 and the "
                   "roots are 0/0 = NaN, and every comparison with NaN is false, so a test written "
                   "as \"if (t < tmin) return false\" lets it through. Write it as "
                   "\"if (!(t > tmin)) return false\", or reject A = 0 first.",
                   c == 1 ? "for NaN input" : "for a zero direction");
}

/* Far, small spheres: right on ordinary rays, wrong here. */
static void p3_far(const ProbeSet *ps, Found *f, P3aFound *out, const Answers *got)
{
    if (got->answered != N_FAR)
        return;
    bool wrong = false;
    for (int c = 0; c < N_FAR; c++) {
        double rho = hypot(far_rays[c][0], far_rays[c][1]), D = -far_rays[c][2];
        double t = D - sqrt(1 - rho * rho);
        wrong = wrong || got->got[c][0] != 1 || !(fabs(got->got[c][1] - t) <= 1e-10 * t);
    }
    if (wrong) {
        out->cancellation = true;
        name_cause(f, "cancellation", M_CANCEL, "B^2 - A C, the lecture's discriminant, loses the sphere "
                   "when it is small and far, and so do your answers (a sphere of radius 1 at 2^27): "
                   "B^2 and A C (or |L|^2 and tca^2) agree to 16 digits there, and their difference, "
                   "the part that says where the ray is, is rounding error. Computing it without that cancellation "
                   "is the handout's hard-case challenge (extra credit).%s",
                   ps->probes->full_hints ? " The discriminant is A R^2 - |f x r|^2." : "");
    }
}

/* The probes' answers read in order: float, an epsilon, the ordinary
 * hits, then what only right ordinary hits let one tell apart. */
static void diagnose_part3a(ProbeSet *ps, Found *f, P3aFound *out)
{
    double scaled[N_SCALED][CASE_MAX_IN], near[N_NEAR][CASE_MAX_IN];
    add_part3a_probes(ps, scaled, near);
    const Answers *a = probes_run(ps);
    if (unwritten(f, ps))
        return;
    p3_float(f, out, a, (Rays)scaled);
    p3_tmin(f, out, &a[PROBE_NEAR], (Rays)near);
    bool ordinary = p3_ordinary_model(f, out, a) == M_RIGHT;
    if (ordinary)
        p3_scaled(f, out, &a[PROBE_SCALED], (Rays)scaled);
    bool inside_neg = p3_behind(f, out, a);
    p3_t_zero(f, out, &a[PROBE_ON_SPHERE], on_sphere_rays, N_ON_SPHERE);
    if (ordinary && !inside_neg)
        p3_inside(f, out, &a[PROBE_INSIDE]);
    if (ordinary)
        p3_tangent(f, out, &a[PROBE_TANGENT]);
    p3_nan(f, out, &a[PROBE_NAN]);
    if (ordinary && !out->model[M_FLOAT])
        p3_far(ps, f, out, &a[PROBE_FAR]);
}

/* ==== Part 3b ================================================================ */

enum { C_RIGHT, C_UNNORMALISED, C_REVERSED, C_AT_PIXEL, C_AT_PIXEL_REVERSED, NC_MODELS };

static void p3b_camera(int m, const double *in, double *out)
{
    const double *e = in, *p = in + 3;
    double d[3] = { p[0] - e[0], p[1] - e[1], p[2] - e[2] };
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    bool at_pixel = m == C_AT_PIXEL || m == C_AT_PIXEL_REVERSED;
    double sign = m == C_REVERSED || m == C_AT_PIXEL_REVERSED ? -1 : 1;
    for (int k = 0; k < 3; k++) {
        out[k] = at_pixel ? p[k] : e[k];
        out[3 + k] = m == C_UNNORMALISED ? d[k] : sign * d[k] / len;
    }
}

enum { K_RIGHT, K_FIRST, K_FARTHEST, K_LAST, K_BLACK, K_NONE, NK_MODELS };

/* The colour model m gives a ray in test t's scene. */
static void p3b_colour(int m, const Test *t, const double *in, double *out)
{
    int best = -1, first = -1, last = -1;
    double tbest = INFINITY, tfar = -INFINITY;
    int far = -1;
    for (int s = 0; s < t->nspheres; s++) {
        const TestSphere *sp = &t->spheres[s];
        double row[CASE_MAX_IN] = SPH(sp->c[0], sp->c[1], sp->c[2], sp->R, in[0], in[1], in[2],
                                      in[3], in[4], in[5]);
        double h[2];
        p3_eval(M_RIGHT, row, 0, h);
        if (h[0] != 1)
            continue;
        if (first < 0)
            first = s;
        last = s;
        if (h[1] < tbest)
            tbest = h[1], best = s;
        if (h[1] > tfar)
            tfar = h[1], far = s;
    }
    int k = m == K_FIRST ? first : m == K_FARTHEST ? far : m == K_LAST ? last : m == K_NONE ? -1 : best;
    for (int q = 0; q < 3; q++)
        out[q] = k >= 0 ? t->spheres[k].color[q] : m == K_BLACK ? 0 : t->background[q];
}

typedef struct {
    int camera, colour;            /* the confirmed models, or -1 */
} P3bFound;

static bool vec_same(const double *got, const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!same(got[k], v[k], fmax(1, fabs(v[k]))))
            return false;
    return true;
}

static bool p3b_explains(const void *ctx, int tag, const Test *t, const Case *c, const double *got)
{
    const P3bFound *p = ctx;
    double v[6], ray[6];
    (void)tag;
    if (t->kind == KIND_CAMERA) {
        p3b_camera(p->camera > 0 ? p->camera : C_RIGHT, c->in, v);
        return p->camera > 0 && vec_same(got, v, 6);
    }
    if (t->kind == KIND_COLOR) {
        memcpy(ray, c->in, sizeof ray);
    } else {                                        /* an image: the ray from the eye at 0 */
        double in[6] = { 0, 0, 0, c->in[0], c->in[1], c->in[2] };
        p3b_camera(p->camera > 0 ? p->camera : C_RIGHT, in, ray);
    }
    p3b_colour(p->colour > 0 ? p->colour : K_RIGHT, t, ray, v);
    return (p->camera > 0 || p->colour > 0) && vec_same(got, v, 3);
}

static void diagnose_part3b(ProbeSet *ps, Found *f, P3bFound *out)
{
    static const double cams[][6] = {
        { 0, 0, 0, 3, 0, -4 }, { 1, 2, 3, 4, -2, 3 }, { 0, 0, 0, 0.1, 0.2, -1 }, { -1, 0.5, 2, 2, 2.5, -4 },
    };
    enum { NCAM = sizeof cams / sizeof *cams };
    probe_add(ps, PART3B, KIND_CAMERA, "probe: camera rays", *cams, 6, NCAM);
    /* Spheres listed neither near to far nor far to near.  The last ray
     * misses the red sphere and meets the other two: there the last sphere
     * hit in the list is the farthest, not the closest. */
    static const double rays[][6] = {
        { 0, 0, 0, 0, 0, -1 }, { 0, 0, 0, 0.05, 0.02, -1 }, { 0, 0, 0, 0, 0.6, -0.8 }, { 0, 0, 0, 0.1, 0.2, -1 },
        { 0, 0, 0, -0.15, 0, -1 },
    };
    enum { NR = sizeof rays / sizeof *rays };
    Test *colours = probe_add(ps, PART3B, KIND_COLOR, "probe: colours of the closest hit", *rays, 6, NR);
    colours->background[0] = 0.2, colours->background[1] = 0.4, colours->background[2] = 0.6;
    test_add_sphere(colours, (const double[3]){ 0, 0, -10 }, 2, (const double[3]){ 0, 1, 0 });
    test_add_sphere(colours, (const double[3]){ 0, 0, -20 }, 5, (const double[3]){ 0, 0, 1 });
    test_add_sphere(colours, (const double[3]){ 0.5, 0, -5 }, 1, (const double[3]){ 1, 0, 0 });
    const Answers *a = probes_run(ps);
    const Answers camera_answers = a[0], colour_answers = a[1];
    if (unwritten(f, ps))
        return;
    out->camera = out->colour = -1;
    for (int m = 0; m < NC_MODELS && out->camera < 0 && camera_answers.answered == NCAM; m++) {
        bool all = true;
        for (int c = 0; c < NCAM && all; c++) {
            double v[6];
            p3b_camera(m, cams[c], v);
            all = vec_same(camera_answers.got[c], v, 6);
        }
        if (all)
            out->camera = m;
    }
    for (int m = 0; m < NK_MODELS && out->colour < 0 && colour_answers.answered == NR; m++) {
        bool all = true;
        for (int c = 0; c < NR && all; c++) {
            double v[3];
            p3b_colour(m, colours, rays[c], v);
            all = vec_same(colour_answers.got[c], v, 3);
        }
        if (all)
            out->colour = m;
    }
    if (out->camera == C_UNNORMALISED)
        name_cause(f, "unnormalised", TAG_ALL, "camera_ray's direction is not unit length: for the eye at "
                   "the origin and the pixel (3, 0, -4) it returned (%.6g, %.6g, %.6g); divide s - e "
                   "by its length |s - e| = 5.",
                   camera_answers.got[0][3], camera_answers.got[0][4], camera_answers.got[0][5]);
    if (out->camera == C_REVERSED || out->camera == C_AT_PIXEL_REVERSED)
        name_cause(f, "reversed", TAG_ALL, "camera_ray's direction is reversed: it points from the pixel to "
                   "the eye; the ray goes from the eye e TOWARDS the pixel s, (s - e) / |s - e|.");
    if (out->camera == C_AT_PIXEL || out->camera == C_AT_PIXEL_REVERSED)
        name_cause(f, "origin-at-pixel", TAG_ALL, "camera_ray starts at the pixel: the ray's origin is the eye e.");
    /* The colour models' causes: each confirmed by every probe ray. */
    static const struct { int model; const char *key, *text; } colour_causes[] = {
        { K_FIRST, "first-hit", "ray_color returns the first sphere hit in the list, not the closest: "
          "with the spheres listed in another order than by distance, the ray through the middle got "
          "the colour of a sphere behind the nearest one. Keep the smallest t over ALL spheres." },
        { K_FARTHEST, "farthest-hit", "ray_color returns the farthest sphere hit: keep the SMALLEST t "
          "(start tmin at infinity and keep a hit only when its t is smaller)." },
        { K_LAST, "last-hit", "ray_color returns the last sphere hit in the list, not the closest: each "
          "hit replaces the colour whatever its t, so a ray through two spheres got the colour of the "
          "one listed later, behind the nearer one. Keep a hit only when its t is smaller than the "
          "smallest so far (start that at infinity)." },
        { K_NONE, "no-hit-kept", "ray_color returns the background for every ray, even through a "
          "sphere's middle: no sphere's colour is ever kept. It must test every sphere with "
          "sphere_intersect and keep the colour of the smallest t; if that smallest t starts at 0, "
          "no t > 0 is ever smaller: start it at infinity." },
        { K_BLACK, "background-ignored", "a ray that hits nothing came back black: it has the scene's "
          "background colour, scene->background." },
    };
    for (size_t k = 0; k < sizeof colour_causes / sizeof colour_causes[0]; k++)
        if (out->colour == colour_causes[k].model)
            name_cause(f, colour_causes[k].key, TAG_ALL, "%s", colour_causes[k].text);
}

/* ==== Parts 4 and 5 ========================================================= */

/* Their tests are their probes (each case's answer says hit or miss): every
 * answer of every test that ran a miss, where some are hits, is the
 * skeleton's answer.  Names that; the tests' hints say the rest. */
static void flat_unwritten(int part, const TestList *tests, const TestResult *results, char **text,
                           char **keys)
{
    int answered = 0, hits = 0;
    for (int k = 0; k < tests->n; k++) {
        const Test *t = &tests->tests[k];
        const Answers *a = ran_in_part(part, tests, results, k);
        for (int c = 0; a && c < a->answered; c++) {
            if (a->got[c][0] != 0)
                return;
            answered++;
            hits += t->cases[c].want[0] == 1 && !(t->cases[c].flags & CASE_EITHER_HIT);
        }
    }
    if (answered == 0 || hits == 0)
        return;
    appendf(text, "- every answer is a miss, the skeleton's answer, whatever the input (%d cases, %d of "
            "them hits): the function is not written yet, or returns before its work is done.\n",
            answered, hits);
    appendf(keys, "unwritten");
}

/* ==== every part ============================================================= */

void diagnose_part(int part, const TestList *tests, const TestResult *results, const Probes *probes,
                   char **text, char **hard_text, char **keys)
{
    *text = *hard_text = *keys = NULL;
    bool failed = false;
    for (int k = 0; k < tests->n; k++)
        failed = failed || (ran_in_part(part, tests, results, k) && !results[k].passed);
    if (!failed)
        return;
    if (part > PART3B) {
        flat_unwritten(part, tests, results, text, keys);
        return;
    }
    Found f = { .ncauses = 0 };
    ProbeSet ps = { .probes = probes };
    P1Found p1 = { 0 };
    P2Found p2 = { -1, -1, -1 };
    P3aFound p3 = { { false }, 0, false, 1e-9, false };
    P3bFound pb = { -1, -1 };
    if (part == PART1)
        diagnose_part1(&ps, &f, &p1);
    else if (part == PART2)
        diagnose_part2(&ps, &f, &p2);
    else if (part == PART3A)
        diagnose_part3a(&ps, &f, &p3);
    else
        diagnose_part3b(&ps, &f, &pb);
    Explains explains[] = { p1_explains, p2_explains, p3_explains, p3b_explains };
    const void *ctx[] = { &p1, &p2, &p3, &pb };
    write_diagnosis(&f, part, tests, results, explains[part], ctx[part], text, hard_text, keys);
    if (part == PART3B && probes->own_part3a && probes->part3a_failed)
        appendf(text, "Part 3b calls your own sphere_intersect here, and Part 3a lost points: put Part "
                "3a right first, then look at Part 3b again.\n");
    for (int k = 0; k < ps.list.n; k++)
        answers_free(&ps.a[k]);
    testlist_free(&ps.list);
}
