/*
 * class_page.c - the class page, OUT/index.html: one self-contained HTML
 * file (inline SVG, no script, nothing from the network), in the report
 * pages' style, written for the instructor alone (mode 0600):
 *
 *   a paragraph that says the class in numbers;
 *   the scores: histograms, medians, quartiles, full points (class_hist.c);
 *   the causes, most common first, and the tests most failed, with the
 *   figure of their most common wrong answer (class_sections.c, class_tests.c);
 *   the submissions that need a person (class_sections.c);
 *   what changed since a previous run (class_previous.c);
 *   what the run cost.
 *
 * Every name and text that came from a submission is escaped (mk_text);
 * a link to a submission's page has its name percent-encoded.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "report.h"
#include "sandbox.h"

#include <string.h>
#include <sys/stat.h>

static const char class_style[] =
    ".hists{display:flex;flex-wrap:wrap;gap:12px}.hists figure{margin:0}\n"
    "table.causes,table.people,table.changes{border-collapse:collapse;margin:.4em 0 .8em;width:100%}\n"
    "table.causes td,table.causes th,table.people td,table.people th,table.changes td,"
    "table.changes th{border:1px solid #ccc;padding:.3em .6em;text-align:left;vertical-align:top}\n"
    "table.causes th,table.people th,table.changes th{background:#f0f0f0}\n"
    "table.causes td:first-child{text-align:right;font-weight:bold;width:4em}\n"
    "p.said{margin:0}p.handout{margin:.3em 0 0;color:#1a7f37;font-size:.9em}\n"
    "p.key{margin:.2em 0 0;color:#666;font-size:.85em}.note,.nocause{color:#555;font-size:.92em}\n"
    "nav{margin:.4em 0 1em}nav a{margin-right:1.2em}\n"
    ".tests{display:grid;grid-template-columns:repeat(auto-fill,minmax(540px,1fr));gap:0 16px}\n"
    ".tests article.test{margin:.6em 0}.tests svg.fig{width:100%}\n";

/* Whether submission s needs a person (class_sections.c lists why). */
static bool needs_person(const ClassSub *s)
{
    if (!s->summary || !s->record || s->no_stage_file)
        return true;
    for (int p = 0; p < NPARTS; p++)
        if (s->part[p].graded && (!s->part[p].built || s->part[p].ranout > 0))
            return true;
    return false;
}

void class_link(Markup *m, const ClassView *v, int s)
{
    const char *name = v->run->subs[s].name;
    char path[PATH_MAX + 300];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s.html", v->run->out, name);
    bool page = stat(path, &st) == 0 && S_ISREG(st.st_mode);
    if (page) {
        mk_printf(m, "<a href=\"");
        for (const unsigned char *c = (const unsigned char *)name; *c; c++) {
            bool plain = (*c >= 'A' && *c <= 'Z') || (*c >= 'a' && *c <= 'z') || (*c >= '0' && *c <= '9') ||
                         strchr("-._~", *c);
            mk_printf(m, plain ? "%c" : "%%%02X", *c);
        }
        mk_printf(m, ".html\">");
    }
    mk_text(m, name);
    if (page)
        mk_printf(m, "</a>");
}

void class_links(Markup *m, const ClassView *v, const int *subs, int n, int max)
{
    for (int k = 0; k < n && k < max; k++) {
        if (k > 0)
            mk_printf(m, ", ");
        class_link(m, v, subs[k]);
    }
    if (n > max)
        mk_printf(m, " and %d more", n - max);
}

/* The length of a cause's first clause: its sentence up to the first
 * colon, bracket, semicolon or full stop (what it is, before the evidence). */
static size_t clause_length(const char *text)
{
    size_t n = 0;
    while (text[n] && !strchr(":(;\n", text[n]) && !(text[n] == '.' && (text[n + 1] == ' ' || !text[n + 1])))
        n++;
    while (n > 0 && text[n - 1] == ' ')
        n--;
    return n;
}

/* The class in one paragraph: how many, full core marks, points lost, a
 * person needed, and the most common cause. */
static void summary(Markup *m, const ClassView *v)
{
    const ClassRun *run = v->run;
    int graded = 0, full = 0, lost = 0, people = 0;
    for (int s = 0; s < run->n; s++) {
        const ClassSub *sub = &run->subs[s];
        bool core = sub->summary;
        for (int p = 0; p < NPARTS; p++)
            core = core && (!v->cfg->parts[p] || sub->core[p] >= v->cfg->core[p]);
        graded += sub->summary;
        full += core;
        lost += sub->summary && sub->status != 0;
        people += needs_person(sub);
    }
    int nparts = 0;
    for (int p = 0; p < NPARTS; p++)
        nparts += v->cfg->parts[p];
    mk_printf(m, "<p class=\"glance\" data-submissions=\"%d\" data-full=\"%d\"><strong>%d "
                 "submission%s</strong> graded (Part%s", run->n, full, run->n, run->n == 1 ? "" : "s",
              nparts == 1 ? "" : "s");
    for (int p = 0, said = 0; p < NPARTS; p++)
        if (v->cfg->parts[p])
            mk_printf(m, "%s %s", said++ ? "," : "", part_label(p));
    mk_printf(m, "). <strong>%d</strong> %s full core marks (every part's core points); %d lost "
                 "points somewhere, hard cases included; <strong>%d</strong> need%s a person "
                 "(<a href=\"#people\">below</a>).", full, full == 1 ? "has" : "have", lost, people,
              people == 1 ? "s" : "");
    if (graded < run->n)
        mk_printf(m, " %d could not be graded.", run->n - graded);
    int top = -1;
    for (int r = 0; r < v->ncauses; r++)
        top = top < 0 || v->causes[r].count > v->causes[top].count ? r : top;
    if (top >= 0) {
        const char *text = v->causes[top].text;
        mk_printf(m, " The most common cause, in %d: Part %s, &ldquo;", v->causes[top].count,
                  part_label(v->causes[top].part));
        mk_textf(m, "%.*s", (int)clause_length(text), text);
        mk_printf(m, "&rdquo;.");
    }
    mk_printf(m, "</p>\n");
}

static void cost(Markup *m, const ClassView *v)
{
    int n = v->run->n;
    mk_printf(m, "<h2 id=\"cost\">What the run cost</h2>\n<table class=\"scores\">\n"
                 "<tr><td>time</td><td class=\"num\">%.1f s</td><td>from the start of "
                 "<code>make grade-all</code>'s grading to this page</td></tr>\n"
                 "<tr><td>CPU</td><td class=\"num\">%.1f s</td><td>the grader and every program it "
                 "ran (compilers, the students' code): %.2f s a submission</td></tr>\n"
                 "<tr><td>compiled</td><td class=\"num\">%d</td><td>stage files</td></tr>\n"
                 "<tr><td>this page</td><td class=\"num\">%.2f s</td><td>reading what each "
                 "grading found, counting it and drawing it (after the time above)</td></tr>\n"
                 "</table>\n", v->seconds, v->cpu, n ? v->cpu / n : 0, v->compiled,
              sandbox_now() - v->page_start);
}

int class_page_write(const char *path, const ClassView *v, char *err, size_t errlen)
{
    Markup m;
    report_page_begin(&m, "The class at a glance", NULL, class_style);
    mk_printf(&m, "<h1>The class at a glance</h1>\n");
    summary(&m, v);
    mk_printf(&m, "<nav><a href=\"#scores\">Scores</a><a href=\"#causes\">What went wrong</a>"
                  "<a href=\"#tests\">Tests most failed</a><a href=\"#people\">Need a person</a>%s"
                  "<a href=\"#cost\">Cost</a><a href=\"gradebook.csv\">gradebook.csv</a>"
                  "<a href=\"causes.csv\">causes.csv</a></nav>\n",
              v->run->previous[0] ? "<a href=\"#changes\">Since the previous run</a>" : "");
    class_scores(&m, v);
    class_causes(&m, v);
    class_tests(&m, v);
    class_people(&m, v);
    class_changes(&m, v);
    cost(&m, v);
    return report_page_end(&m, "Written by the kit's grader (tests/grader) at the end of <code>make "
                               "grade-all</code>, from what each submission's grading found: the same grading "
                               "as its results file and its page. This page names every student: it is "
                               "readable by its owner alone.", path, 0600, err, errlen);
}
