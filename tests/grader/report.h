/*
 * report.h - what the grader tells people: a table on stdout for humans and
 * the Gradescope results.json.
 */
#ifndef REPORT_H
#define REPORT_H

#include <stdio.h>
#include "config.h"
#include "grade.h"

/* The table: per part score / max, each test PASS or FAIL, and for each
 * failure what went wrong (input, expected, got, tolerance, hint). */
void report_table(FILE *f, const Grade *g, const GradeConfig *cfg, const char *submission);

/* Writes results.json through a temporary file and rename; 0 or -1. */
int report_json(const char *path, const Grade *g, const GradeConfig *cfg,
                const char *submission, char *err, size_t errlen);

/* A results.json for a submission the grader could not grade at all. */
int report_json_error(const char *path, const char *message, char *err, size_t errlen);

#endif
