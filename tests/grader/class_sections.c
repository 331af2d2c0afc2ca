/*
 * class_sections.c - two sections of the class page: the causes the
 * diagnosis named, part by part, most common first; and the submissions
 * that need a person (a grader error, no stage file, a file that did not
 * build, was refused or is missing, tests out of time), with the reason.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "build.h"

#include <stdlib.h>
#include <string.h>

/* ---- the causes ----------------------------------------------------------- */

static void cause_row(Markup *m, const ClassView *v, const ClassCauseRow *row)
{
    char mistake[200];
    mk_printf(m, "<tr class=\"cause\" data-part=\"%s\" data-cause=\"", part_label(row->part));
    mk_text(m, row->key);
    mk_printf(m, "\" data-count=\"%d\"><td class=\"num\">%d</td><td><p class=\"said\">", row->count,
              row->count);
    mk_text(m, row->text);
    mk_printf(m, "</p>");
    if (class_handout_lists(row->part, row->text, mistake, sizeof mistake)) {
        mk_printf(m, "<p class=\"handout\">One of the handout's listed mistakes: &ldquo;");
        mk_text(m, mistake);
        mk_printf(m, "&rdquo; (<code>handouts/%s.md</code>).</p>", stage_names[row->part]);
    }
    mk_printf(m, "<p class=\"key\">cause <code>");
    mk_text(m, row->key);
    mk_printf(m, "</code></p></td><td>");
    class_links(m, v, row->subs, row->count, row->count);
    mk_printf(m, "</td></tr>\n");
}

/* The submissions that lost core points in part p, built, and were given
 * no cause: the diagnosis confirmed none. */
static void uncaused(Markup *m, const ClassView *v, int p)
{
    const ClassRun *run = v->run;
    int *subs = malloc(((size_t)run->n + 1) * sizeof *subs), n = 0;
    for (int s = 0; subs && s < run->n; s++) {
        const ClassSub *sub = &run->subs[s];
        if (sub->record && sub->summary && sub->part[p].built && sub->part[p].ncauses == 0 &&
            sub->core[p] < v->cfg->core[p])
            subs[n++] = s;
    }
    if (n > 0) {
        mk_printf(m, "<p class=\"nocause\">%d other%s lost points in this part with no cause "
                     "named (the probes confirmed none): ", n, n == 1 ? "" : "s");
        class_links(m, v, subs, n, n);
        mk_printf(m, ".</p>\n");
    }
    free(subs);
}

void class_causes(Markup *m, const ClassView *v)
{
    mk_printf(m, "<h2 id=\"causes\">What went wrong, most common first</h2>\n");
    int lost = 0;
    for (int s = 0; s < v->run->n; s++)
        lost += v->run->subs[s].status != 0;
    if (v->ncauses == 0) {
        mk_printf(m, "<p>%s</p>\n", lost == 0 ? "No submission lost points: there is nothing to "
                                                "diagnose."
                                              : "The diagnosis named no cause in any submission "
                                                "(it names one only when probes run on the code "
                                                "confirm it): see the tests below.");
        return;
    }
    mk_printf(m, "<p>Each cause the diagnosis named (probes run on the code confirmed it), in the "
                 "words the students read, with the submissions that had it. A submission can have "
                 "more than one.</p>\n");
    for (int r = 0; r < v->ncauses; r++) {
        int p = v->causes[r].part;
        if (r == 0 || v->causes[r - 1].part != p) {
            mk_printf(m, "<h3 id=\"causes-%s\">", part_label(p));
            mk_text(m, part_title(p));
            mk_printf(m, "</h3>\n<table class=\"causes\">\n<tr><th>how many</th><th>what went wrong"
                         "</th><th>submissions</th></tr>\n");
        }
        cause_row(m, v, &v->causes[r]);
        if (r + 1 == v->ncauses || v->causes[r + 1].part != p) {
            mk_printf(m, "</table>\n");
            uncaused(m, v, p);
        }
    }
}

/* ---- the submissions that need a person -------------------------------------- */

/* What needs a person, in the order the table lists them. */
enum { NEED_ERROR, NEED_EMPTY, NEED_BUILD, NEED_REFUSED, NEED_MISSING, NEED_TIME, NNEEDS };
static const char *const need_names[NNEEDS] = {
    "grader error", "no stage file", "did not build", "refused", "file missing", "out of time",
};

/* The line of a build's messages that says why: the first that names an
 * error (the line of the first "error" in them), else the first. */
static void why_line(const char *why, char *out, size_t n)
{
    const char *pick = why ? why : "";
    const char *error = strstr(pick, "error");
    while (error && error > pick && error[-1] != '\n')
        error--;
    pick = error ? error : pick;
    snprintf(out, n, "%.*s", (int)strcspn(pick, "\n"), pick);
}

static void need_row(Markup *m, const ClassView *v, int s, int need, int part, const char *why)
{
    mk_printf(m, "<tr class=\"person\" data-need=\"%s\"><td>", need_names[need]);
    class_link(m, v, s);
    mk_printf(m, "</td><td>%s</td><td>", need_names[need]);
    if (part >= 0)
        mk_printf(m, "Part %s: ", part_label(part));
    mk_text(m, why);
    mk_printf(m, "</td></tr>\n");
}

/* Submission s's rows of kind need; the number written. */
static int need_rows(Markup *m, const ClassView *v, int s, int need)
{
    const ClassSub *sub = &v->run->subs[s];
    char why[600];
    int rows = 0;
    if (need == NEED_ERROR && !sub->summary) {
        /* Why its grading stopped without reporting its points: the first
         * line of what its record says, or its status. */
        if (sub->error && sub->error[0])
            snprintf(why, sizeof why, "%.*s", (int)strcspn(sub->error, "\n"), sub->error);
        else
            snprintf(why, sizeof why, "its grading ended with status %d and reported no points", sub->status);
        need_row(m, v, s, need, -1, why);
        return 1;
    }
    if (!sub->summary || !sub->record)
        return 0;
    if (need == NEED_EMPTY && sub->no_stage_file) {
        need_row(m, v, s, need, -1, "no stage file in the folder (nor in a labs folder in it): "
                                    "its results file names the files it holds");
        return 1;
    }
    for (int p = 0; p < NPARTS && !sub->no_stage_file; p++) {
        const ClassPart *cp = &sub->part[p];
        bool missing = cp->why && strncmp(cp->why, "missing:", 8) == 0;
        int kind = cp->built ? -1 : !cp->refused ? NEED_BUILD : missing ? NEED_MISSING : NEED_REFUSED;
        if (cp->graded && kind == need) {
            why_line(cp->why, why, sizeof why);
            need_row(m, v, s, need, p, why);
            rows++;
        }
        if (cp->graded && need == NEED_TIME && cp->ranout > 0) {
            snprintf(why, sizeof why, "%d test%s did not finish within %g s", cp->ranout,
                     cp->ranout == 1 ? "" : "s", v->cfg->timeout);
            need_row(m, v, s, need, p, why);
            rows++;
        }
    }
    return rows;
}

void class_people(Markup *m, const ClassView *v)
{
    Markup rows;
    mk_init(&rows);
    int n = 0;
    for (int need = 0; need < NNEEDS; need++)
        for (int s = 0; s < v->run->n; s++)
            n += need_rows(&rows, v, s, need);
    mk_printf(m, "<h2 id=\"people\">Submissions that need a person</h2>\n");
    if (n == 0)
        mk_printf(m, "<p>None: every submission's files were there and built, and every test "
                     "finished in time.</p>\n");
    else
        mk_printf(m, "<p>Their points say little until someone looks: the grader could not grade "
                     "them, found no stage file, could not build or would not compile a file, or "
                     "stopped tests that ran out of time.</p>\n<table class=\"people\">\n<tr><th>"
                     "submission</th><th>what</th><th>why</th></tr>\n");
    if (mk_ok(&rows))
        mk_raw(m, (const char *)rows.b.data, rows.b.len);
    else
        m->failed = true;
    if (n > 0)
        mk_printf(m, "</table>\n");
    mk_free(&rows);
}
