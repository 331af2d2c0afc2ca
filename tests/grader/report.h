/*
 * report.h - what the grader tells people: a table on stdout for humans,
 * the Gradescope results.json, and a page with pictures (HTML) for the
 * student to look at.
 */
#ifndef REPORT_H
#define REPORT_H

#include <stdbool.h>
#include <stdio.h>
#include "build.h"
#include "config.h"
#include "grade.h"
#include "kit/image.h"
#include "markup.h"
#include "../tools/json.h"

/* The table: per part score / max, each test PASS or FAIL, and for each
 * failure what went wrong (input, expected, got, tolerance, hint): short
 * (report_table.c), or with every_failure every failure in full. */
void report_table(FILE *f, const Grade *g, const GradeConfig *cfg, const char *submission,
                  bool every_failure);

/* Writes results.json through a temporary file and rename; 0 or -1. */
int report_json(const char *path, const Grade *g, char *err, size_t errlen);

/* A results.json for a submission the grader could not grade at all. */
int report_json_error(const char *path, const char *message, char *err, size_t errlen);
/* Its end, which PrairieLearn's shares: the message as the output, no
 * tests, the object closed; then written to path and j freed (0 or -1). */
int report_json_error_end(JsonWriter *j, const char *path, const char *message, char *err, size_t errlen);

/* ---- the page (report_render.c, report_html.c) -------------------------- */

/* What the page's renders are made from. */
typedef struct {
    const BuildConfig *build;
    const char *submission;
    const char *kept_objects;  /* objects kept by grading (GradeOptions), or NULL */
    const char *scene;         /* the scene file, e.g. labs/scenes/default.scene  */
    const char *reference[2];  /* the reference render's PNG: the first of these
                                  that exists (NULL entries are skipped)        */
    double timeout;            /* seconds the submission's render may take      */
} ReportRenderOptions;

/* The scene drawn by the submission and by the reference. */
typedef struct {
    char scene[64];            /* the scene's name, e.g. "default"               */
    bool have_sub, have_ref;
    Image sub, ref;            /* each valid when its have_ flag is set         */
    char *ref_png;             /* with have_ref, the reference's file when it is
                                  a PNG (the page shows it as it is), or NULL   */
    size_t ref_png_len;
    char sub_note[2048];       /* when !have_sub: why (for the student)         */
    char ref_note[512];        /* when !have_ref: why                           */
    double seconds;            /* building and drawing them took                */
} ReportRenders;

/* Draws the scene with the submission's code (built and run in the
 * sandbox, with the limits of a test) and reads the reference's picture.
 * Returns 0 (each picture there or its note saying why not), or -1 when the
 * grader itself failed (err says why). */
int report_render(const ReportRenderOptions *o, ReportRenders *rr, char *err, size_t errlen);
void report_renders_free(ReportRenders *rr);

/* Writes the page (one self-contained HTML file: the pictures are inline
 * SVG and data: URIs) to path, through a temporary file and rename.
 * rr may be NULL (no renders).  Returns 0, or -1 with a reason in err. */
int report_html(const char *path, const Grade *g, const GradeConfig *cfg, const char *submission,
                const ReportRenders *rr, char *err, size_t errlen);

/* The style sheet of the pages (this one and the class page's). */
extern const char report_style[];
/* Starts m with a page in that style, up to its <body>: its title (title
 * then name, escaped; name may be NULL) and the style sheet, style after it. */
void report_page_begin(Markup *m, const char *title, const char *name, const char *style);
/* Ends m's page with its footer (footer, as it is), saves it to path with
 * mode (kit_save_file_mode) and frees m; 0, or -1 with "path: reason" in
 * err ("out of memory" when memory ran out on the way). */
int report_page_end(Markup *m, const char *footer, const char *path, unsigned mode, char *err,
                    size_t errlen);

/* The case a failing test's figure shows, and the answer drawn: the first
 * wrong case, else the case where the answers stopped (no answer: *got is
 * NULL), else -1 (nothing to draw). */
int report_figure_case(const Test *t, const TestResult *r, const double **got);

#endif
