/*
 * diagnose.h - why a part lost points: probes run against the student's
 * function, and the causes they confirm.
 *
 * When a part of Parts 1-3b fails a test, the grader runs a few targeted
 * probes through the same sandboxed program (a hit just ahead of the
 * origin, the same ray with its direction scaled by 3, a field of view
 * near 180 degrees, ...).  Each cause has a model, the answer the cause
 * gives to any case, computed here in plain double; a cause is named only
 * when its probes' answers are the model's and not the right ones.  The
 * diagnosis states each confirmed cause once, with the evidence, and how
 * many of the part's failing cases the causes explain.  A part whose
 * probes confirm nothing gets no diagnosis: a guess could send a student
 * the wrong way.  Causes' keys are listed in tests/selftest/README.md.
 */
#ifndef DIAGNOSE_H
#define DIAGNOSE_H

#include <stdbool.h>
#include "grader.h"

/* Runs test t in a fresh sandboxed child of the part's program and judges
 * its answers into a; returns 0 when the child ran (whatever it did). */
typedef int (*ProbeRun)(void *ctx, const Test *t, Answers *a);

typedef struct {
    ProbeRun run;
    void *ctx;
    bool own_part3a;           /* Part 3b's program calls the student's 3a  */
    bool part3a_failed;        /* ... and that Part 3a lost points          */
    bool full_hints;           /* a hard case's cause gives the challenge's
                                  answer (weights.conf's "hints full"); by
                                  default it says what fails and why, and
                                  points to the handout's challenge       */
} Probes;

/* Diagnoses part (PART1 .. PART3B) from its tests' results and its probes.
 * *text receives the explanation for the student of the core tests'
 * failures, *hard_text that of causes which explain hard cases alone (the
 * extra credit, told apart), and *keys every cause's key, space-separated,
 * in the order of the two texts' "- " lines (*text's first); each
 * malloc'd, or NULL when nothing is confirmed. */
void diagnose_part(int part, const TestList *tests, const TestResult *results, const Probes *probes,
                   char **text, char **hard_text, char **keys);

#endif
