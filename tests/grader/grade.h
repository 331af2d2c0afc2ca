/*
 * grade.h - grading one submission: every part on its own.
 */
#ifndef GRADE_H
#define GRADE_H

#include "build.h"
#include "config.h"
#include "grader.h"

typedef struct {
    const char *submission;    /* directory holding some or all stage files   */
    bool parts[NPARTS];        /* which parts to grade                        */
    const GradeConfig *cfg;
    const BuildConfig *build;
    bool verbose;              /* progress on stderr                          */
    const char *keep_objects;  /* a directory that receives the student's
                                  compiled stage objects (build_keep_objects),
                                  for the report's render; NULL: none        */
} GradeOptions;

typedef struct {
    const TestList *tests;
    TestResult *results;       /* one per test; max_score 0 where not graded  */
    bool graded[NPARTS];
    char *build_messages[NPARTS];
    bool build_refused[NPARTS];  /* its file never reached the compiler (Build) */
    bool built[NPARTS];        /* it built: build_messages are warnings, if any */
    /* Per part, when it lost points: the causes its probes confirmed, as
     * text for the student (malloc'd, NULL when none was confirmed): of
     * the core tests' failures, and apart, of those that explain hard
     * cases alone (the extra credit); and every cause's key,
     * space-separated (tests/selftest/README.md lists them). */
    char *diagnosis[NPARTS];
    char *diagnosis_hard[NPARTS];
    char *causes[NPARTS];
    double core[NPARTS], core_max[NPARTS];
    double hard[NPARTS], hard_max[NPARTS];
    double total, total_max;   /* core, plus hard when it is not a bonus      */
    double bonus, bonus_max;   /* hard points when they are a bonus           */
    double seconds;
    /* Where the children's CPU time went (user and system seconds):
     * compiling the stage files, linking the parts' programs, running the
     * tests (in one child per part, then one per test that one did not
     * pass) and the diagnosis's probes.  grade --cost adds the grader's own
     * (the whole process's, reading the tests included). */
    double cpu_compile, cpu_link, cpu_tests, cpu_probes;
} Grade;

/* Grades; 0 on success, -1 when the grader itself could not run (then
 * grade_free frees what g holds so far). */
int grade_submission(const GradeOptions *opt, const TestList *tests, Grade *g,
                     char *err, size_t errlen);
void grade_free(Grade *g);

/* Whether part p built with something said by the compiler or linker
 * (warnings: build_messages[p]), for the reports. */
bool grade_warned(const Grade *g, int p);

/* Why part p's tests could not run, when its file did not build, for the
 * reports: "your part1_image_plane.c did not build" or, for a file the
 * grader did not hand to the compiler (missing, refused), "the grader did
 * not compile your part1_image_plane.c".  Written into out; capital: its
 * first word with a capital letter, to begin a sentence. */
void grade_unbuilt_why(const Grade *g, int p, bool capital, char *out, size_t n);

#endif
