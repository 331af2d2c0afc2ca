/*
 * class_tests.c - the class page's tests most failed: each with how many
 * of the submissions whose file of its part built passed it, and the
 * figure (figures.h) of the wrong answer most of them gave: the same case
 * answered with the same numbers, to the bit.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "figures.h"

#include <math.h>
#include <string.h>

/* The figure of case c of t answered with got.  An image test's case is
 * the colour of the ray from the eye, at the origin, through a pixel's
 * centre: it is drawn as a colour test's case of that ray. */
static void answer_figure(Markup *m, const Test *t, int c, const double *got)
{
    if (t->kind != KIND_IMAGE) {
        figure_case(m, t, NULL, c, got);
        return;
    }
    Case ray = t->cases[c];
    memcpy(ray.in + 3, t->cases[c].in, 3 * sizeof ray.in[0]);
    memset(ray.in, 0, 3 * sizeof ray.in[0]);
    fig_color(m, t, &ray, got);
}

static void common_answer(Markup *m, const ClassView *v, const ClassTestRow *row, const Test *t)
{
    const ClassFail *f = row->common;
    char which[64] = "";
    if (t->kind == KIND_IMAGE && t->image_nx > 0)
        snprintf(which, sizeof which, " (pixel i = %d, j = %d)", f->c % t->image_nx, f->c / t->image_nx);
    if (row->answers == 1)
        mk_printf(m, "<p>The one wrong answer given, to case %d of %d%s, by %d of them: ", f->c + 1,
                  t->ncases, which, row->ncommon);
    else if (row->ncommon > 1)
        mk_printf(m, "<p>The most common wrong answer, to case %d of %d%s, given by %d of them (of %d "
                     "different ones): ", f->c + 1, t->ncases, which, row->ncommon, row->answers);
    else
        mk_printf(m, "<p>No two gave the same wrong answer (%d different); drawn, the first's, to "
                     "case %d of %d%s: ", row->answers, f->c + 1, t->ncases, which);
    class_links(m, v, row->common_subs, row->ncommon, 12);
    mk_printf(m, ".</p>\n<figure class=\"case\">\n");
    answer_figure(m, t, f->c, f->got);
    mk_printf(m, "<figcaption>Case %d of %d: blue, what was expected; orange, the answer %s.</figcaption>"
                 "\n</figure>\n", f->c + 1, t->ncases,
              row->ncommon == 1 ? "drawn" : "these submissions gave");
}

static void test_article(Markup *m, const ClassView *v, const ClassTestRow *row, int rank)
{
    const Test *t = &v->tests->tests[row->test];
    int passed = row->built - row->failed;
    mk_printf(m, "<article class=\"test\" id=\"most-%d\" data-built=\"%d\" data-failed=\"%d\">\n<h4>",
              rank + 1, row->built, row->failed);
    mk_text(m, t->name);
    mk_printf(m, "%s%s</h4>\n", t->hard ? "<span class=\"tag\">hard case</span>" : "",
              t->hidden ? "<span class=\"tag\">hidden test</span>" : "");
    mk_printf(m, "<p>Passed by <strong>%d of %d</strong> (%.0f%%) of the submissions whose file "
                 "of Part %s built; failed by %d.</p>\n", passed, row->built,
              floor(100.0 * passed / row->built + 0.5), part_label(t->part), row->failed);
    if (row->common)
        common_answer(m, v, row, t);
    else
        mk_printf(m, "<p>None of them gave a wrong answer to draw: they crashed, ran out of time "
                     "or stopped before they answered.</p>\n");
    mk_printf(m, "</article>\n");
}

void class_tests(Markup *m, const ClassView *v)
{
    mk_printf(m, "<h2 id=\"tests\">The tests most failed</h2>\n");
    if (!v->tests && v->tests_note[0]) {
        mk_printf(m, "<p>The tests could not be read again to draw them: ");
        mk_text(m, v->tests_note);
        mk_printf(m, "</p>\n");
        return;
    }
    if (v->nworst == 0) {
        mk_printf(m, "<p>None: every submission whose files built passed every test.</p>\n");
        return;
    }
    mk_printf(m, "<p>The %d test%s failed by the most submissions, counting those whose file of the "
                 "test's part built (the others could run no test). The figure is drawn as the "
                 "students' pages draw a failure, for the wrong answer most of them gave.</p>\n",
              v->nworst, v->nworst == 1 ? "" : "s");
    mk_printf(m, "<div class=\"tests\">\n");
    for (int r = 0; r < v->nworst; r++)
        test_article(m, v, &v->worst[r], r);
    mk_printf(m, "</div>\n");
}
