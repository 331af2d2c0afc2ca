/*
 * test_figures.c - the report page's figures of a failing case (tests/
 * grader/fig_*.c) show what they are about, for every case of Parts 2 to
 * 5 in the public tests and in the hidden tests of SEEDS seeds, each drawn
 * with several wrong answers:
 *
 *   - an expected hit (Part 2: the expected centre) is marked in the main
 *     window;
 *   - a returned one is marked there too, or said to be off the figure;
 *   - Part 2: the expected centre is the middle of the pixel drawn as (i, j);
 *   - Parts 3a and 3b: the expected hit's mark lies on its sphere's circle;
 *   - Part 4: it lies on the plane's line;
 *   - Part 5: a triangle the ray hits is drawn with the ray's point in it.
 *
 * What is checked is the SVG the page would show: each window is an <svg>
 * of its own, clipped to its box, so a mark drawn outside the first one's
 * box is not seen.  (A main window narrowed beside a zoomed one once kept
 * its left edge and cut off the hit it was drawn for; a plane met 1e-12
 * from e was drawn a few pixels off its hit.)
 */
#include "check.h"
#include "../grader/grader.h"
#include "../grader/figures.h"
#include "../oracle/testgen.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef SEEDS
#define SEEDS 6
#endif

/* ---- reading the SVG back ------------------------------------------------------ */

/* The number after name=" in the element that starts at el (and ends at
 * its '>'), or NAN. */
static double attr(const char *el, const char *name)
{
    char key[32];
    snprintf(key, sizeof key, " %s=\"", name);
    const char *end = strchr(el, '>'), *p = strstr(el, key);
    if (!p || !end || p > end)
        return NAN;
    return strtod(p + strlen(key), NULL);
}

static bool attr_is(const char *el, const char *name, const char *value)
{
    char key[64];
    snprintf(key, sizeof key, " %s=\"%s\"", name, value);
    const char *end = strchr(el, '>'), *p = strstr(el, key);
    return p && end && p < end;
}

typedef struct {
    double x, y, w, h;          /* the main window's box                       */
    bool want, got;             /* its marks: the expected and the returned hit */
    double want_x, want_y, got_x, got_y;
    bool line;                  /* Part 4: the plane's line (its thick stroke)  */
    double lx1, ly1, lx2, ly2;
    bool circle;                /* Parts 3a, 3b: the sphere's circle, drawn whole */
    double cx, cy, r;
    bool pixel;                 /* Part 2: pixel (i, j), filled                 */
    double px, py, pw, ph;
} MainWindow;

/* The first window of the figure in svg: false when it has none. */
static bool main_window(const char *svg, MainWindow *mw)
{
    memset(mw, 0, sizeof *mw);
    const char *p = strstr(svg, "<svg x=\"");
    if (!p)
        return false;
    mw->x = attr(p, "x"), mw->y = attr(p, "y"), mw->w = attr(p, "width"), mw->h = attr(p, "height");
    const char *end = strstr(p + 1, "</svg>");
    if (!end)
        return false;
    for (const char *q = strchr(p + 1, '<'); q && q < end; q = strchr(q + 1, '<')) {
        if (strncmp(q, "<circle ", 8) == 0 && attr(q, "r") == 5.5 && attr_is(q, "fill", COL_WANT)) {
            mw->want = true;
            mw->want_x = attr(q, "cx"), mw->want_y = attr(q, "cy");
        } else if (strncmp(q, "<circle ", 8) == 0 && attr(q, "r") == 7.5 && attr_is(q, "stroke", COL_GOT)) {
            mw->got = true;
            mw->got_x = attr(q, "cx"), mw->got_y = attr(q, "cy");
        } else if (strncmp(q, "<rect ", 6) == 0 && attr_is(q, "fill", "#fff1b8")) {
            mw->pixel = true;
            mw->px = attr(q, "x"), mw->py = attr(q, "y"), mw->pw = attr(q, "width"), mw->ph = attr(q, "height");
        } else if (strncmp(q, "<circle ", 8) == 0 && attr_is(q, "stroke-width", "1.6")) {
            mw->circle = true;
            mw->cx = attr(q, "cx"), mw->cy = attr(q, "cy"), mw->r = attr(q, "r");
        } else if (strncmp(q, "<line ", 6) == 0 && attr_is(q, "stroke-width", "3")) {
            mw->line = true;
            mw->lx1 = attr(q, "x1"), mw->ly1 = attr(q, "y1"), mw->lx2 = attr(q, "x2"), mw->ly2 = attr(q, "y2");
        }
    }
    return true;
}

static bool in_box(const MainWindow *mw, double x, double y)
{
    return x >= mw->x && x <= mw->x + mw->w && y >= mw->y && y <= mw->y + mw->h;
}

/* The distance in pixels from (x, y) to the line through the plane's stroke. */
static double off_line(const MainWindow *mw, double x, double y)
{
    double dx = mw->lx2 - mw->lx1, dy = mw->ly2 - mw->ly1, len = hypot(dx, dy);
    return len > 0 ? fabs(dx * (y - mw->ly1) - dy * (x - mw->lx1)) / len : INFINITY;
}

/* ---- drawing every case with wrong answers ------------------------------------------ */

typedef struct {
    int figures, want_marks, got_marks, got_off, on_line, on_circle, crossed, centred;
    int failures;               /* reported; the first few are printed */
} Tally;

static void fail(Tally *ty, const Test *t, int c, const double *got, int nout, const char *what)
{
    if (ty->failures++ >= 40)
        return;
    char ans[160] = "no answer";
    if (got) {
        int n = 0;
        for (int k = 0; k < nout && n < (int)sizeof ans; k++)
            n += snprintf(ans + n, sizeof ans - (size_t)n, "%s%.17g", k ? ", " : "", got[k]);
    }
    CHECK_MSG(false, "\"%s\", case %d, answered (%s): %s", t->name, c + 1, ans, what);
}

static void check_figure(Tally *ty, const Test *t, int c, const double *got)
{
    const Case *cs = &t->cases[c];
    TestResult r;
    memset(&r, 0, sizeof r);
    Markup m;
    mk_init(&m);
    figure_case(&m, t, &r, c, got);
    CHECK(mk_ok(&m) && kit_buf_push(&m.b, 0) == 0);
    const char *svg = (const char *)m.b.data;
    int nout = kind_nout(t->kind);
    MainWindow mw;
    if (!svg || !main_window(svg, &mw)) {
        /* a ray with no direction, or a NaN: no view of a ray at all */
        mk_free(&m);
        return;
    }
    ty->figures++;
    /* the expected hit: Parts 3a and 4 say so in the legend, Part 3b names
     * the sphere whose colour is expected */
    /* the expected hit (Part 2: the expected centre): Parts 3a, 4 and 5
     * say so in the legend, Part 3b names the sphere whose colour is
     * expected */
    bool want_hit = t->kind == KIND_PIXEL ? true
                    : t->kind == KIND_COLOR ? strstr(svg, "expected: sphere ") != NULL : cs->want[0] != 0;
    if (want_hit && !(mw.want && in_box(&mw, mw.want_x, mw.want_y)))
        fail(ty, t, c, got, nout, mw.want ? "the expected hit is marked outside the main window"
                                          : "the expected hit is not marked in the main window");
    ty->want_marks += want_hit && mw.want;
    /* the returned hit: marked, or said to be off the figure (or NaN) */
    bool got_hit = got && (t->kind == KIND_PIXEL ? isfinite(got[0]) && isfinite(got[1])
                           : t->kind == KIND_COLOR ? strstr(svg, "your code: sphere ") && !strstr(svg, "does not see")
                           : got[0] == 1);
    bool said_off = strstr(svg, "off the figure") || strstr(svg, "NaN: no point");
    if (got_hit && !(mw.got && in_box(&mw, mw.got_x, mw.got_y)) && !said_off)
        fail(ty, t, c, got, nout, "the returned hit is neither marked in the main window nor said to be off it");
    ty->got_marks += got_hit && mw.got;
    ty->got_off += got_hit && !mw.got && said_off;
    /* Part 4: the plane's line goes through the expected hit */
    if (t->kind == KIND_PLANEHIT && want_hit && mw.want) {
        double d = mw.line ? off_line(&mw, mw.want_x, mw.want_y) : INFINITY;
        if (!(d <= 1.5)) {
            char what[120];
            snprintf(what, sizeof what, "the expected hit is %.3g px off the plane's line", d);
            fail(ty, t, c, got, nout, what);
        }
        ty->on_line += d <= 1.5;
    }
    /* Parts 3a and 3b: the circle of the sphere hit goes through it */
    if ((t->kind == KIND_SPHERE || t->kind == KIND_COLOR) && want_hit && mw.want && mw.circle) {
        double d = fabs(hypot(mw.want_x - mw.cx, mw.want_y - mw.cy) - mw.r);
        if (!(d <= 1.5)) {
            char what[120];
            snprintf(what, sizeof what, "the expected hit is %.3g px off the sphere's circle", d);
            fail(ty, t, c, got, nout, what);
        }
        ty->on_circle += d <= 1.5;
    }
    /* Part 2: the expected centre is the middle of the pixel drawn as (i, j) */
    if (t->kind == KIND_PIXEL && mw.want && mw.pixel && mw.pw >= 4 && mw.ph >= 4) {
        double d = hypot(mw.want_x - (mw.px + mw.pw / 2), mw.want_y - (mw.py + mw.ph / 2));
        if (!(d <= 1)) {
            char what[120];
            snprintf(what, sizeof what, "the expected centre is %.3g px from the middle of pixel (i, j)", d);
            fail(ty, t, c, got, nout, what);
        }
        ty->centred += d <= 1;
    }
    /* Part 5: a triangle the ray hits is drawn with the ray's point in it
     * (a hit within rounding of an edge may be drawn either way) */
    bool crossed = t->kind == KIND_TRIANGLE ? strstr(svg, "inside or on the edge of") != NULL
                                            : strstr(svg, "crosses triangles ") != NULL;
    if ((t->kind == KIND_TRIANGLE || t->kind == KIND_MESH) && want_hit && !(cs->flags & CASE_EITHER_HIT)) {
        if (!crossed)
            fail(ty, t, c, got, nout, "the ray hits, but is drawn going through no triangle");
        ty->crossed += crossed;
    }
    mk_free(&m);
}

/* Each case of each test drawn with answers that are wrong in the ways a
 * figure must show: a miss, no answer, a hit too far, too near, a hair
 * off, behind e, out of all proportion, not a number; for Part 2, x and y
 * swapped, y flipped, the pixel's corner, three pixels off, a hair off,
 * 1e300 and NaN; for Part 3b, no answer, the background and each
 * sphere's colour.  (Parts 1 and 3b's camera rays: figures with no marks
 * to read back.) */
static void check_list(Tally *ty, const TestList *l)
{
    for (int i = 0; i < l->n; i++) {
        const Test *t = &l->tests[i];
        if (t->kind == KIND_CAMERA || t->kind == KIND_PLANE || t->kind == KIND_IMAGE)
            continue;
        for (int c = 0; c < t->ncases; c++) {
            const Case *cs = &t->cases[c];
            check_figure(ty, t, c, NULL);
            if (t->kind == KIND_PIXEL) {
                const double *w = cs->want, pw = cs->in[4] / cs->in[2], ph = cs->in[5] / cs->in[3];
                const double answers[][3] = {
                    { w[1], w[0], w[2] }, { w[0], -w[1], w[2] }, { w[0] - pw / 2, w[1] + ph / 2, w[2] },
                    { w[0] + 3 * pw, w[1], w[2] }, { w[0], w[1] * (1 + 1e-9), w[2] }, { 1e300, w[1], w[2] },
                    { NAN, w[1], w[2] },
                };
                for (size_t k = 0; k < sizeof answers / sizeof answers[0]; k++)
                    check_figure(ty, t, c, answers[k]);
                continue;
            }
            if (t->kind == KIND_COLOR) {
                check_figure(ty, t, c, t->background);
                for (int k = 0; k < t->nspheres && k < 4; k++)
                    check_figure(ty, t, c, t->spheres[k].color);
                continue;
            }
            double tw = cs->want[0] != 0 && isfinite(cs->want[1]) ? cs->want[1] : 1;
            const double answers[][2] = {
                { 0, 0 }, { 1, 2 * tw }, { 1, tw / 3 }, { 1, tw * (1 + 1e-7) }, { 1, -tw },
                { 1, 1e300 }, { 1, NAN },
            };
            /* (a triangle's figure marks every hit on the ray's point: two do) */
            size_t n = t->kind == KIND_TRIANGLE || t->kind == KIND_MESH ? 2 : sizeof answers / sizeof answers[0];
            for (size_t k = 0; k < n; k++)
                check_figure(ty, t, c, answers[k]);
        }
    }
}

static void test_figures_show_what_they_are_about(void)
{
    Tally ty = { 0 };
    TestList l = { 0 };
    testgen_public(&l);
    testgen_public_flat(&l);
    check_list(&ty, &l);
    testlist_free(&l);
    for (uint64_t seed = 1; seed <= SEEDS; seed++) {
        TestList h = { 0 };
        testgen_hidden(&h, seed ^ HIDDEN_SALT_CORE);
        testgen_hidden_flat(&h, seed ^ HIDDEN_SALT_FLAT);
        check_list(&ty, &h);
        testlist_free(&h);
    }
    CHECK_MSG(ty.failures == 0, "%d figures in all leave out what they are about", ty.failures);
    /* and the checks above met what they check, many times over */
    char said[400];
    snprintf(said, sizeof said, "%d figures: %d expected hits marked, %d returned hits marked and %d said "
             "off the figure; %d pixel centres in their pixel, %d hits on their sphere's circle, %d on the "
             "plane's line, %d in their triangle", ty.figures, ty.want_marks, ty.got_marks, ty.got_off,
             ty.centred, ty.on_circle, ty.on_line, ty.crossed);
    CHECK_MSG(ty.want_marks > 1000 && ty.got_marks > 1000 && ty.got_off > 100 && ty.centred > 100 &&
              ty.on_circle > 1000 && ty.on_line > 100 && ty.crossed > 100, "%s", said);
    printf("%s\n", said);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_figures_show_what_they_are_about),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
