/*
 * report_class.h - the class at a glance, after grade --all: OUT/index.html
 * (the class page: the scores' distributions, the causes the diagnosis
 * named, the tests most failed, the submissions that need a person, what
 * changed since a previous run, what the run cost) and OUT/causes.csv
 * (part,cause,text,count,submissions).  Both are written for the
 * instructor alone (mode 0600): they name every student.
 *
 * Each submission's grading writes a small record for it (its causes,
 * builds, failed tests and their answers) to a path grade --all gives it;
 * grade --all then hands each submission's summary to the class, and
 * writes the page once every submission is graded:
 *
 *     ClassRun *run = class_begin(out, previous);          (NULL: no page)
 *     ... the child for submission k: --class-record class_record_path(run, k)
 *     ... class_record_write(path, &g, cfg.timeout, ...)   (in the child)
 *     class_add(run, k, name, values, status, no_stage_file);   (for each k, in order)
 *     class_finish(run, &cfg, load_tests);                 (frees run)
 */
#ifndef REPORT_CLASS_H
#define REPORT_CLASS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include "config.h"
#include "grade.h"

typedef struct ClassRun ClassRun;

/* Starts a class in the output directory out; previous is a previous run's
 * output directory to compare with, or NULL: its gradebook.csv is read now,
 * before this run writes over it when out is the same folder.  Makes a
 * private directory for the records.  NULL (said on stderr) when it
 * cannot: grading goes on without a class page. */
ClassRun *class_begin(const char *out, const char *previous);

/* Where submission k's grading writes its record (buf, n bytes). */
const char *class_record_path(const ClassRun *run, int k, char *buf, size_t n);

/* Writes g's record to path (in the grading child); timeout is a test's
 * limit in seconds.  0, or -1 with a reason in err. */
int class_record_write(const char *path, const Grade *g, double timeout, char *err, size_t errlen);

/* Writes to path the record of a grading that stopped without a grade:
 * msg, why (the class page shows it); nothing when it cannot. */
void class_record_write_error(const char *path, const char *msg);

/* Submission k (0, 1, ... in the order graded, which is the gradebook's),
 * named name: values is its summary (each part's core points, then the
 * hard-case points and the total), or NULL when its grading reported none
 * (a grader error); status its grading's exit status; no_stage_file when
 * the folder holds no stage file where the grader looks. */
void class_add(ClassRun *run, int k, const char *name, const double *values, int status,
               bool no_stage_file);

/* Reads the tests a submission is graded with (grade_main.c's loader). */
typedef int (*ClassLoadTests)(TestList *list, const GradeConfig *cfg, const bool parts[NPARTS],
                              char *err, size_t errlen);

/* Writes OUT/causes.csv and OUT/index.html, says so on stdout (or why not
 * on stderr), removes the records and frees run.  Returns 0, or -1 when a
 * file was not written; the grades never depend on it. */
int class_finish(ClassRun *run, const GradeConfig *cfg, ClassLoadTests load_tests);

#endif
