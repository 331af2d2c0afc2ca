/*
 * harness_serve.h - a prebuilt runner as a server of tests (Linux; see
 * serve_protocol.h).  `runner --serve OBJECT` starts once per part, in the
 * sandbox the grader gives any test, and forks a fresh child for each test
 * the grader sends: the child then loads OBJECT and runs the test exactly
 * as `runner OBJECT` would.  A fork of this small process costs a fraction
 * of starting the runner anew (no exec, no dynamic linking of the C
 * library), and the server itself never loads the student's object nor
 * runs a test, so each test still starts from the same untouched state.
 */
#ifndef HARNESS_SERVE_H
#define HARNESS_SERVE_H

/* Serves tests on the socket sock until the grader closes it, then exits.
 * Returns only in a test's child: its stdin, stdout, stderr and fd 3 are
 * the test's, nothing else is open, it leads a process group of its own
 * and the test's limits are set. */
void harness_serve(int sock);

#endif
