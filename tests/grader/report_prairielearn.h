/*
 * report_prairielearn.h - results.json in PrairieLearn's external-grader
 * format (its documentation, "External Grading", "Grading results").
 */
#ifndef REPORT_PRAIRIELEARN_H
#define REPORT_PRAIRIELEARN_H

#include <stddef.h>
#include "grade.h"

/* Writes the results through a temporary file and rename:
 *   gradable     true when some test of a graded part ran; false when none
 *                could (every graded part's file missing or not compiling),
 *                so that PrairieLearn counts no attempt ("invalid, not
 *                gradable"), with format_errors saying why.
 *   score        core points / core maximum, in [0, 1] (the hard cases are
 *                not in it).
 *   message      the score in words; output: the points of each part.
 *   tests        each test of the graded parts: name, description, points,
 *                max_points, message, output.  Hard-case tests have
 *                max_points 0 (PrairieLearn shows them neutrally and counts
 *                them in no sum); hidden tests keep their details to
 *                themselves.
 * Returns 0, or -1 with the reason in err. */
int report_prairielearn(const char *path, const Grade *g, char *err, size_t errlen);

/* Results for a submission the grader could not grade at all: gradable
 * false, with the message. */
int report_prairielearn_error(const char *path, const char *message, char *err, size_t errlen);

#endif
