/*
 * report_classroom.h - the results for GitHub Classroom's grading reporter
 * (classroom-resources/autograding-grading-reporter).
 */
#ifndef REPORT_CLASSROOM_H
#define REPORT_CLASSROOM_H

#include <stddef.h>
#include "grade.h"

/* Appends to path one line NAME=BASE64 per reporter runner: NAME is the
 * runner's id and BASE64 its results, the base64 of one line of JSON
 *   {"version": 1, "status": "pass"|"fail"|"error", "max_score": N,
 *    "tests": [{"name", "status", "score", "message", "line_no", "test_code"}]}
 * In a workflow path is $GITHUB_OUTPUT, so that the reporter's step reads
 * each runner as ${{ steps.<id>.outputs.NAME }}.
 *
 * The runners: one per core test of each graded part, in part order and
 * then the tests' order, named part<P>test<k> (k from 1 within the part),
 * with max_score the test's points and one test whose score is those
 * points or 0; then "hard", max_score 0, holding every hard-case test.
 * Why both of the reporter's totals are then the kit's core score, and the
 * hard cases count in neither: tests/classroom/README.md.
 *
 * The lines are written with one append; returns 0, or -1 with the reason
 * in err. */
int report_classroom(const char *path, const Grade *g, char *err, size_t errlen);

#endif
