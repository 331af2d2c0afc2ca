/*
 * class_model.h - what the class page is made from (report_class.h): each
 * submission as grade --all and its record saw it, and what the class
 * files count over them.  Shared by class_*.c and report_class.c.
 */
#ifndef CLASS_MODEL_H
#define CLASS_MODEL_H

#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include "config.h"
#include "grader.h"
#include "markup.h"
#include "report_class.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* ---- one submission ---------------------------------------------------- */

typedef struct {
    char key[32];              /* as in the results' extra_data          */
    char *text;                /* the sentence the student read          */
} ClassCause;

typedef struct {
    int test;                  /* the test's index in the run's list     */
    bool ran;                  /* it ran (its part built, it was started) */
    int c;                     /* the case its figure shows, or -1       */
    int nout;                  /* numbers in got: 0 when no answer there  */
    double got[CASE_MAX_OUT];
} ClassFail;

typedef struct {
    bool graded, built, refused;
    int ranout;                /* tests that ran out of time             */
    char *why;                 /* not built: what the build said         */
    int ncauses;
    ClassCause *causes;
} ClassPart;

typedef struct {
    char *name;                /* the folder's name, as it is            */
    bool summary;              /* its grading reported its points        */
    double core[NPARTS], hard, total;
    int status;                /* its grading's exit status              */
    bool no_stage_file;
    bool record;               /* its record was read whole              */
    char *error;               /* why its grading stopped without a grade, or NULL */
    ClassPart part[NPARTS];
    int nfails;
    ClassFail *fails;
} ClassSub;

/* Reads the record at path into s (class_record.c); false when there is
 * none or it is not whole (s then holds what was read, to be freed). */
bool class_record_read(const char *path, ClassSub *s);
void class_sub_free(ClassSub *s);

struct ClassRun {
    char out[PATH_MAX];
    char previous[PATH_MAX];   /* "" when none                           */
    char *previous_csv;        /* its gradebook.csv as it was when the run
                                  began (OUT may be the same folder), or
                                  NULL when it could not be read          */
    char records[PATH_MAX];
    double start;              /* monotonic seconds at class_begin       */
    int n;
    ClassSub *subs;            /* n of them, in the gradebook's order    */
};

/* ---- what the class page counts ----------------------------------------- */

typedef struct {
    int part;
    const char *key;
    const char *text;          /* its most common wording                */
    int count;                 /* submissions whose record names it      */
    int *subs;                 /* their indices, in the gradebook's order */
} ClassCauseRow;

typedef struct {
    int test;
    int built;                 /* submissions whose file of its part built */
    int failed;                /* of those, the ones that failed it      */
    int answers;               /* distinct wrong answers among them      */
    const ClassFail *common;   /* the most common wrong answer, or NULL  */
    int ncommon;
    int *common_subs;          /* the submissions that gave it           */
} ClassTestRow;

typedef struct {
    int sub;                   /* index in the run                       */
    double before[NPARTS + 2], after[NPARTS + 2];  /* parts, hard, total  */
} ClassChange;

typedef struct {
    bool have;                 /* a previous run was given and read      */
    char note[PATH_MAX + 128]; /* why not, when given and not read       */
    int compared;              /* submissions in both runs               */
    int nchanges;
    ClassChange *changes;      /* score changed, largest change first    */
    int nnew, ngone;
    char **gone;               /* names in the previous run alone        */
} ClassPrevious;

typedef struct {
    const ClassRun *run;
    const GradeConfig *cfg;
    const TestList *tests;     /* NULL when they could not be read       */
    char tests_note[300];
    int ncauses;
    ClassCauseRow *causes;     /* by part, then most common first        */
    int nworst;
    ClassTestRow *worst;       /* most failed first                      */
    ClassPrevious previous;
    int compiled;              /* files handed to the compiler (records)  */
    double seconds, cpu;       /* the run's wall-clock and CPU time       */
    double page_start;         /* when the page began to be counted       */
} ClassView;

/* The tests most failed that the page shows. */
#define CLASS_MAX_TESTS 10

/* ---- the page's pieces ---------------------------------------------------- */

/* The histograms of the scores, with their medians and quartiles, and the
 * table of them (class_hist.c). */
void class_scores(Markup *m, const ClassView *v);

/* The causes, the tests most failed, the submissions that need a person,
 * the changes (class_sections.c). */
void class_causes(Markup *m, const ClassView *v);
void class_tests(Markup *m, const ClassView *v);
void class_people(Markup *m, const ClassView *v);
void class_changes(Markup *m, const ClassView *v);

/* Writes the page (class_page.c); 0, or -1 with a reason in err. */
int class_page_write(const char *path, const ClassView *v, char *err, size_t errlen);

/* A link to submission s's report page, OUT/<name>.html, its name as the
 * text (escaped); the name alone when it has no page (class_page.c). */
void class_link(Markup *m, const ClassView *v, int s);
/* Up to max of the submissions subs[0 .. n-1], linked, then "and N more". */
void class_links(Markup *m, const ClassView *v, const int *subs, int n, int max);

/* Whether the handout of part lists the mistake whose sentence is text:
 * a row of its table of mistakes whose sentence column ("what went wrong
 * starts") begins text (class_handout.c).  The row's mistake goes into
 * mistake (n bytes). */
bool class_handout_lists(int part, const char *text, char *mistake, size_t n);

/* Reads the previous run's gradebook into v->previous (class_previous.c). */
void class_previous_read(ClassView *v);
void class_previous_free(ClassPrevious *p);

#endif
