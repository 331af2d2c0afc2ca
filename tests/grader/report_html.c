/*
 * report_html.c - the report page: one self-contained HTML file that a
 * student opens in any browser, with no network and no JavaScript.
 *
 *   the score of each part, and what went wrong (the diagnosis);
 *   the default scene drawn by the submission, by the reference, and the
 *   heat map of their difference (the same as `make compare`);
 *   how to read the pictures (the colours);
 *   each failing test: a figure of its first wrong case (figures.c), then
 *   the test's text as the terminal shows it;
 *   the tests that passed, folded away.
 *
 * The renders are PNG data: URIs and the figures inline SVG, so the file
 * can be moved or mailed alone.  It is written to a temporary file and
 * renamed into place (report_page_end).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "report.h"
#include "figures.h"
#include "markup.h"
#include "kit/compare.h"
#include "kit/savefile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

const char report_style[] =
    "body{font-family:Helvetica,Arial,sans-serif;color:#222;background:#fff;margin:0 auto;"
    "max-width:1180px;padding:0 20px 40px;line-height:1.45}\n"
    "h1{font-size:1.7em;margin:.8em 0 .2em}h2{font-size:1.35em;margin:1.6em 0 .5em;"
    "border-bottom:2px solid #ddd;padding-bottom:.2em}h3{font-size:1.15em;margin:1.4em 0 .4em}\n"
    "h4{font-size:1.02em;margin:0 0 .5em}\n"
    "code,pre{font-family:Menlo,Consolas,monospace;font-size:.88em}\n"
    "pre{background:#f6f6f6;border:1px solid #e2e2e2;padding:.6em .8em;overflow-x:auto;"
    "white-space:pre-wrap;word-break:break-word;margin:.5em 0 0}\n"
    "table.scores{border-collapse:collapse;margin:.4em 0}\n"
    "table.scores td,table.scores th{border:1px solid #ccc;padding:.3em .7em;text-align:left}\n"
    "table.scores th{background:#f0f0f0}td.num{text-align:right;font-variant-numeric:tabular-nums}\n"
    ".full{color:#1a7f37;font-weight:bold}.lost{color:#b42318;font-weight:bold}\n"
    ".diag{border-left:4px solid #d9480f;background:#fff4ec;padding:.5em .9em;margin:.7em 0;"
    "white-space:pre-line}\n"
    ".legend{display:flex;flex-wrap:wrap;gap:.4em 2em;align-items:center;background:#f7f9fc;"
    "border:1px solid #dde3ee;padding:.6em .9em}\n"
    ".legend svg{vertical-align:middle}\n"
    ".renders{display:flex;flex-wrap:wrap;gap:14px}\n"
    ".renders figure{margin:0;flex:1 1 300px;max-width:380px}\n"
    ".renders img{width:100%;height:auto;border:1px solid #bbb;image-rendering:pixelated}\n"
    ".nopic{border:1px dashed #b42318;background:#fff6f5;padding:.8em;font-size:.92em}\n"
    ".nopic pre{border:none;background:none;padding:0;margin:0}\n"
    ".nopic.same{border-color:#1a7f37;background:#f2fbf4}\n"
    "figcaption{font-size:.9em;color:#444;margin-top:.3em}\n"
    "article.test{border:1px solid #ddd;border-radius:6px;padding:.8em 1em;margin:1em 0;"
    "break-inside:avoid;page-break-inside:avoid}\n"
    "figure.case{margin:.3em 0}\n"
    "svg.fig{max-width:100%;height:auto;border:1px solid #e4e4e4}\n"
    "svg.fig text[font-weight=bold]{paint-order:stroke;stroke:#fff;stroke-width:3px;stroke-linejoin:round}\n"
    ".tag{display:inline-block;font-size:.78em;background:#eee;border-radius:3px;padding:0 .4em;"
    "margin-left:.4em;color:#444;font-weight:normal}\n"
    ".failword{color:#b42318}\n"
    "table.spheres{border-collapse:collapse;font-size:.9em;margin:.5em 0}\n"
    "table.spheres caption{text-align:left;font-weight:bold;padding:.2em 0}\n"
    "table.spheres td,table.spheres th{border:1px solid #ddd;padding:.15em .5em;text-align:left}\n"
    ".swatch{display:inline-block;width:1.1em;height:1.1em;border:1px solid #888;"
    "vertical-align:middle;margin-right:.3em}\n"
    "footer{margin-top:3em;color:#666;font-size:.88em;border-top:1px solid #ddd;padding-top:.6em}\n"
    "@media print{body{max-width:none;padding:0;font-size:10pt}"
    "h2{break-after:avoid;page-break-after:avoid}"
    ".renders figure{max-width:31%}pre{white-space:pre-wrap;border:none;background:none}"
    "a{color:inherit;text-decoration:none}details{display:none}"
    "article.test{border:1px solid #999}}\n";

void report_page_begin(Markup *m, const char *title, const char *name, const char *style)
{
    mk_init(m);
    mk_printf(m, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                 "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>");
    mk_text(m, title);
    mk_text(m, name);
    mk_printf(m, "</title>\n<style>\n%s%s</style>\n</head>\n<body>\n", report_style, style);
}

int report_page_end(Markup *m, const char *footer, const char *path, unsigned mode, char *err,
                    size_t errlen)
{
    mk_printf(m, "<footer>%s</footer>\n</body>\n</html>\n", footer);
    int status = -1;
    if (mk_ok(m))
        status = kit_save_file_mode(path, m->b.data, m->b.len, mode, err, errlen);
    else
        snprintf(err, errlen, "%s: out of memory", path);
    mk_free(m);
    return status;
}

/* How many of a part's graded tests failed, and how many there are. */
static void count_tests(const Grade *g, int part, int *failed, int *total)
{
    *failed = *total = 0;
    for (int k = 0; k < g->tests->n; k++)
        if (g->tests->tests[k].part == part) {
            (*total)++;
            *failed += !g->results[k].passed;
        }
}

/* A box of what part p's grading said, under "Part P, " said; text as it
 * is with pre. */
#define PROBES "probes run on your code confirmed it)"
static void diag(Markup *m, int p, const char *said, const char *text, bool pre)
{
    mk_printf(m, "<div class=\"diag\"><strong>Part %s, %s:</strong>\n%s", part_label(p), said,
              pre ? "<pre>" : "");
    mk_text(m, text);
    mk_printf(m, "%s</div>\n", pre ? "</pre>" : "");
}

/* How many tests of the graded parts failed; *unrun of them are those of
 * parts that did not build, where none could run (none is drawn). */
static int failed_tests(const Grade *g, int *unrun)
{
    int nfailed = 0;
    *unrun = 0;
    for (int p = 0; p < NPARTS; p++) {
        int failed, total;
        count_tests(g, p, &failed, &total);
        nfailed += g->graded[p] ? failed : 0;
        *unrun += g->graded[p] && !g->built[p] && failed == total ? total : 0;
    }
    return nfailed;
}

/* The table of each part's points, the total, and each part's diagnosis. */
static void scores(Markup *m, const Grade *g, const GradeConfig *cfg)
{
    mk_printf(m, "<table class=\"scores\">\n<tr><th>part</th><th>points</th><th>hard cases%s</th>"
                 "<th>tests failed</th><th></th></tr>\n", cfg->hard_is_bonus ? " (bonus)" : "");
    for (int p = 0; p < NPARTS; p++) {
        if (!g->graded[p])
            continue;
        int failed, total;
        count_tests(g, p, &failed, &total);
        /* Full marks are the core's: the hard cases are extra credit. */
        bool full = g->core[p] >= g->core_max[p] && (cfg->hard_is_bonus || g->hard[p] >= g->hard_max[p]);
        /* a part with failures links to them */
        mk_printf(m, "<tr><td>");
        if (failed)
            mk_printf(m, "<a href=\"#part-%s\">", part_label(p));
        mk_text(m, part_title(p));
        mk_printf(m, "%s</td><td class=\"num\">%s / %s</td><td class=\"num\">", failed ? "</a>" : "",
                  points_text(g->core[p]).s, points_text(g->core_max[p]).s);
        if (g->hard_max[p] > 0)
            mk_printf(m, "%s / %s", points_text(g->hard[p]).s, points_text(g->hard_max[p]).s);
        mk_printf(m, "</td><td class=\"num\">%d of %d</td><td class=\"%s\">%s</td></tr>\n", failed,
                  total, full ? "full" : "lost", full ? "full marks" : "points lost");
    }
    mk_printf(m, "</table>\n<p><strong>Score: %s / %s</strong>", points_text(g->total).s,
              points_text(g->total_max).s);
    if (g->bonus_max > 0)
        mk_printf(m, " &nbsp; hard-case bonus: %s / %s", points_text(g->bonus).s, points_text(g->bonus_max).s);
    mk_printf(m, " &nbsp; (graded in %.1f s)</p>\n", g->seconds);
    for (int p = 0; p < NPARTS; p++) {
        /* Its causes one a line, as the terminal shows them ("- "): of the
         * core's failures, then of the hard cases' alone. */
        if (g->graded[p] && g->diagnosis[p] && g->core[p] < g->core_max[p])
            diag(m, p, "what went wrong (" PROBES, g->diagnosis[p], false);
        if (g->graded[p] && g->diagnosis_hard[p])
            diag(m, p, cfg->hard_is_bonus ? "the hard cases (extra credit; " PROBES : "the hard cases (" PROBES,
                 g->diagnosis_hard[p], false);
    }
    for (int p = 0; p < NPARTS; p++)
        if (grade_warned(g, p))
            diag(m, p, "the compiler warned (a warning often points at a mistake)", g->build_messages[p], true);
}

/* What the figures' colours and windows mean. */
static void legend(Markup *m)
{
    mk_printf(m, "<div class=\"legend\">\n<span><svg width=\"16\" height=\"16\" "
                 "viewBox=\"0 0 16 16\" aria-hidden=\"true\">");
    svg_mark_want(m, 8, 8);
    mk_printf(m, "</svg> <strong>blue</strong>: what was expected (the right answer)</span>\n"
                 "<span><svg width=\"20\" height=\"20\" viewBox=\"0 0 20 20\" aria-hidden=\"true\">");
    svg_mark_got(m, 10, 10);
    mk_printf(m, "</svg> <strong>orange</strong>: what your code returned</span>\n"
                 "<span>Every figure is drawn to scale; a small framed window (\"zoomed in\") "
                 "shows what is too small to see at that scale.</span>\n</div>\n");
}

/* A PNG of the heat map's colours, from no difference to the largest. */
static void heat_scale(Markup *m)
{
    Image bar;
    char err[128];
    if (image_alloc(&bar, 256, 12, err, sizeof err) < 0)
        return;
    for (int j = 0; j < 12; j++)
        for (int i = 0; i < 256; i++)
            compare_heat(i, bar.rgb + 3 * (j * 256 + i));
    mk_printf(m, "<p>Heat map: <img src=\"");
    mk_png_uri(m, &bar);
    mk_printf(m, "\" width=\"256\" height=\"12\" alt=\"the heat map's colours\"> black: the "
                 "pixel is the same; dark blue, red, yellow, white: ever larger differences "
                 "(the largest of the red, green and blue differences, 0 to 255).</p>\n");
    image_free(&bar);
}

/* Where a picture's data: URI is in the page's text. */
typedef struct {
    size_t at, len;
} UriSpan;

/* One picture as a PNG data: URI, with its caption (a picture that cannot
 * be encoded becomes an empty data: URI).  Its pixels are img's; they are
 * encoded only when neither of the others is given: again, the URI of a
 * picture written before with the same pixels, copied; png, the bytes of a
 * PNG file of them, shown as they are.  *uri (when not NULL) is set to
 * where this picture's URI is. */
static void picture(Markup *m, const Image *img, const char *alt, const char *caption,
                    const UriSpan *again, const char *png, size_t png_len, UriSpan *uri)
{
    mk_printf(m, "<figure><img src=\"");
    size_t at = m->b.len;
    bool encoded = true;
    if (again && again->len > 0) {
        if (kit_buf_reserve(&m->b, again->len) != 0)
            m->failed = true;
        else
            mk_raw(m, (const char *)m->b.data + again->at, again->len);
    } else if (png) {
        mk_png_bytes_uri(m, png, png_len);
    } else if (mk_png_uri(m, img) != 0) {
        mk_printf(m, "data:,");
        encoded = false;
    }
    if (uri)
        *uri = (UriSpan){ at, encoded && !m->failed ? m->b.len - at : 0 };
    mk_printf(m, "\" width=\"%d\" height=\"%d\" alt=\"", img->width, img->height);
    mk_text(m, alt);
    mk_printf(m, "\"><figcaption>");
    mk_text(m, caption);
    mk_printf(m, "</figcaption></figure>\n");
}

/* In place of a picture: why there is none (same: in place of the heat
 * map of identical pictures, which is all black). */
static void no_picture(Markup *m, const char *caption, const char *why, bool same)
{
    mk_printf(m, "<figure><div class=\"nopic%s\">%s", same ? " same" : "", same ? "" : "<pre>");
    mk_text(m, why);
    mk_printf(m, "%s</div><figcaption>", same ? "" : "</pre>");
    mk_text(m, caption);
    mk_printf(m, "</figcaption></figure>\n");
}

/* The scene drawn by the submission, by the reference, and their heat map. */
static void renders(Markup *m, const ReportRenders *rr)
{
    mk_printf(m, "<h2 id=\"render\">The %s scene: your picture and the reference's</h2>\n", rr->scene);
    mk_printf(m, "<p>Your code drew <code>labs/scenes/");
    mk_text(m, rr->scene);
    mk_printf(m, ".scene</code> (as <code>make render</code> does, with your four files of "
                 "Parts 1 to 3b); beside it the reference solution's picture and the heat map "
                 "of their difference (as <code>make compare</code> draws it).</p>\n"
                 "<div class=\"renders\">\n");
    /* Measured first: pictures the same, pixel for pixel, are shown by one
     * PNG, the reference's file as it is (else encoded once). */
    CompareStats st = { 0 };
    bool comparable = rr->have_sub && rr->have_ref && rr->sub.width == rr->ref.width &&
                      rr->sub.height == rr->ref.height;
    if (comparable)
        st = compare_measure(&rr->sub, &rr->ref);
    bool same = comparable && st.differing == 0;
    UriSpan sub_uri = { 0, 0 };
    if (rr->have_sub)
        picture(m, &rr->sub, "the scene drawn by your code", "your code", NULL,
                same ? rr->ref_png : NULL, rr->ref_png_len, &sub_uri);
    else
        no_picture(m, "your code: no picture", rr->sub_note, false);
    if (rr->have_ref)
        picture(m, &rr->ref, "the scene drawn by the reference solution", "the reference",
                same ? &sub_uri : NULL, rr->ref_png, rr->ref_png_len, NULL);
    else
        no_picture(m, "the reference: no picture", rr->ref_note, false);
    /* Identical pictures have an all-black heat map: a box says so
     * instead, and the page spares encoding it and the map's scale. */
    Image heat;
    char err[256];
    if (same) {
        no_picture(m, "difference: none", "The two pictures are identical, pixel for pixel: there is no "
                   "difference to map.", true);
    } else if (comparable && compare_heat_map(&rr->sub, &rr->ref, &heat, err, sizeof err) == 0) {
        char caption[200];
        snprintf(caption, sizeof caption, "difference: %.3g%% of the pixels differ, by up to "
                 "%d of 255", 100.0 * (double)st.differing / (double)st.pixels, st.max_error);
        picture(m, &heat, "heat map of the difference", caption, NULL, NULL, 0, NULL);
        image_free(&heat);
    }
    mk_printf(m, "</div>\n");
    if (rr->have_sub && rr->have_ref && !same)
        heat_scale(m);
    if (same)
        mk_printf(m, "<p>Your picture is exactly the reference's.</p>\n");
}

int report_figure_case(const Test *t, const TestResult *r, const double **got)
{
    const Answers *a = &r->answers;
    *got = NULL;
    if (!r->ran)
        return -1;
    if (a->first_bad >= 0 && a->first_bad < t->ncases && a->got) {
        *got = a->got[a->first_bad];
        return a->first_bad;
    }
    if (a->answered < t->ncases)
        return a->answered;
    return -1;
}

/* One failing test: its name, exactly one figure (a drawing of its first
 * wrong case, or a box saying why there is none), and its text. */
static void failing_test(Markup *m, const Test *t, const TestResult *r, int index, bool show_output)
{
    mk_printf(m, "<article class=\"test\" id=\"test-%d\">\n<h4><span class=\"failword\">FAIL</span> ",
              index + 1);
    mk_text(m, t->name);
    if (t->hard)
        mk_printf(m, "<span class=\"tag\">hard case</span>");
    if (t->hidden)
        mk_printf(m, "<span class=\"tag\">hidden test</span>");
    mk_printf(m, "</h4>\n<figure class=\"case\">\n");
    const double *got = NULL;
    int c = report_figure_case(t, r, &got);
    if (c >= 0) {
        figure_case(m, t, r, c, got);
        mk_printf(m, "<figcaption>Case %d of %d", c + 1, t->ncases);
        if (t->kind == KIND_IMAGE && t->image_nx > 0)
            mk_printf(m, " (pixel i = %d, j = %d)", c % t->image_nx, c / t->image_nx);
        if (got) {
            mk_printf(m, ", the first that was wrong.");
            int others = r->answers.failed - 1;
            if (others > 0)
                mk_printf(m, " %d other case%s of this test %s wrong too.", others,
                          others == 1 ? "" : "s", others == 1 ? "was" : "were");
        } else {
            mk_printf(m, ": your code gave no answer here (it stopped), so only the expected "
                         "answer is drawn.");
        }
        mk_printf(m, "</figcaption>\n");
    } else {
        mk_printf(m, "<div class=\"nopic\">No picture: %s</div>\n",
                  !show_output ? "your file did not build, so this test could not run (why is "
                                 "said above)."
                  : !r->ran ? "this test did not run, so there is no answer to draw (see below)."
                            : "every answer was right, but the program did not finish normally "
                              "(see below).");
    }
    mk_printf(m, "</figure>\n");
    if (show_output && r->output && *r->output) {
        mk_printf(m, "<pre class=\"output\">");
        mk_text(m, r->output);
        mk_printf(m, "</pre>\n");
    }
    mk_printf(m, "</article>\n");
}

/* The end of a <details> element's summary, and the names of the tests
 * of the graded parts (of part alone, unless it is -1) that passed or not:
 * the tests a page lists without their details. */
static void test_names(Markup *m, const Grade *g, int part, bool passed)
{
    mk_printf(m, "</summary>\n<ul>\n");
    for (int k = 0; k < g->tests->n; k++) {
        const Test *t = &g->tests->tests[k];
        if (!g->graded[t->part] || (part >= 0 && t->part != part) || g->results[k].passed != passed)
            continue;
        mk_printf(m, "<li>");
        mk_text(m, t->name);
        mk_printf(m, "%s</li>\n", t->hard ? " <span class=\"tag\">hard case</span>" : "");
    }
    mk_printf(m, "</ul>\n</details>\n");
}

/* Every failing test, part by part, core tests before hard ones (as the
 * terminal lists them), the hard ones under a heading of their own (bonus:
 * they are extra credit); a part that did not build shows the compiler's
 * messages once. */
static void failures(Markup *m, const Grade *g, bool bonus)
{
    int unrun, nfailed = failed_tests(g, &unrun);
    mk_printf(m, "<h2 id=\"failures\">What failed</h2>\n");
    if (nfailed == 0) {
        mk_printf(m, "<p>Nothing: every test passed.</p>\n");
        return;
    }
    if (unrun == nfailed)
        mk_printf(m, "<p>%d test%s failed: the files of their parts did not build, so none could "
                     "run.</p>\n", nfailed, nfailed == 1 ? "" : "s");
    else
        mk_printf(m, "<p>%d test%s failed%s. Each %shas a picture of its first wrong case, then what "
                     "the terminal says about it: the input, what was expected, what your code "
                     "returned, how close it had to be, and a hint when your answer matches a known "
                     "mistake.</p>\n", nfailed, nfailed == 1 ? "" : "s",
                  unrun ? ", some in parts whose files did not build" : "", unrun ? "that ran " : "");
    for (int p = 0; p < NPARTS; p++) {
        int failed, total;
        count_tests(g, p, &failed, &total);
        if (!g->graded[p] || failed == 0)
            continue;
        mk_printf(m, "<h3 id=\"part-%s\">", part_label(p));
        mk_text(m, part_title(p));
        mk_printf(m, ": %s / %s</h3>\n", points_text(g->core[p]).s, points_text(g->core_max[p]).s);
        bool built = g->built[p];
        if (!built) {
            /* The compiler's words, or the grader's own when it did not
             * hand the file to the compiler (missing, unreadable, a link, a
             * kit file included...), in the words of every other report. */
            char why[200];
            grade_unbuilt_why(g, p, true, why, sizeof why);
            mk_printf(m, "<p>");
            mk_textf(m, "%s, so none of its tests could run:", why);
            mk_printf(m, "</p>\n<pre>");
            mk_text(m, g->build_messages[p]);
            mk_printf(m, "</pre>\n");
            if (failed == total) {      /* counted in unrun above */
                /* Each test's own article would only say it could not run. */
                mk_printf(m, "<details><summary>None of its %d tests could run (open to list "
                             "them)", total);
                test_names(m, g, p, false);
                continue;
            }
        }
        for (int group = 0; group < 2; group++) {
            bool heading = false;           /* the hard cases apart, after the core */
            for (int k = 0; k < g->tests->n; k++) {
                const Test *t = &g->tests->tests[k];
                if (t->part != p || t->hard != group || g->results[k].passed)
                    continue;
                if (group == 1 && !heading) {
                    mk_printf(m, "<h4>Hard cases (%s): %s / %s</h4>\n", bonus ? "extra credit" : "counted",
                              points_text(g->hard[p]).s, points_text(g->hard_max[p]).s);
                    heading = true;
                }
                failing_test(m, t, &g->results[k], k, built || g->results[k].ran);
            }
        }
    }
}

/* The tests that passed, folded away (a <details> element, no script). */
static void passed(Markup *m, const Grade *g)
{
    int n = 0;
    for (int k = 0; k < g->tests->n; k++)
        n += g->graded[g->tests->tests[k].part] && g->results[k].passed;
    if (n == 0)
        return;
    mk_printf(m, "<h2 id=\"passed\">What passed</h2>\n<details><summary>%d test%s passed "
                 "(open to list them)", n, n == 1 ? "" : "s");
    test_names(m, g, -1, true);
}

/* Makes the directories of path's parents that are missing; never fails
 * (the write that follows reports what is wrong). */
static void make_parents(const char *path)
{
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    for (char *p = dir + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(dir, 0777) != 0 && errno != EEXIST)
            return;
        *p = '/';
    }
}

int report_html(const char *path, const Grade *g, const GradeConfig *cfg, const char *submission,
                const ReportRenders *rr, char *err, size_t errlen)
{
    Markup m;
    report_page_begin(&m, "Grade report: ", submission, "");
    mk_printf(&m, "<h1>Your grade, with pictures</h1>\n<p>Submission <code>");
    mk_text(&m, submission);
    mk_printf(&m, "</code>, graded by <code>make grade</code>. This page is for you to read on "
                  "your own computer; the terminal says the same in numbers.</p>\n");
    mk_printf(&m, "<h2 id=\"scores\">Scores</h2>\n");
    scores(&m, g, cfg);
    /* The legend is for the failures' figures: a page with none has no use
     * for it (a part that did not build is listed, not drawn). */
    int unrun;
    if (failed_tests(g, &unrun) > unrun) {
        mk_printf(&m, "<h2 id=\"reading\">How to read the pictures</h2>\n");
        legend(&m);
    }
    if (rr)
        renders(&m, rr);
    failures(&m, g, cfg->hard_is_bonus);
    passed(&m, g);
    make_parents(path);
    return report_page_end(&m, "Written by the kit's grader (tests/grader). The pictures are drawn from the "
                               "numbers of each test: the expected answers, computed independently, and "
                               "your code's answers.", path, 0666, err, errlen);
}
