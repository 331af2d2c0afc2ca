/*
 * testgen.h - the autograder's tests, built with the oracle's expected
 * values and the hints of known mistakes.  Instructor only: the public
 * tests are written out as tests/public/partN.tests (make public-tests), the
 * hidden ones (tests/hidden) are drawn when grading.
 */
#ifndef TESTGEN_H
#define TESTGEN_H

#include <stdbool.h>
#include <stdint.h>
#include "../grader/grader.h"

/* The public tests, core and hard, in a fixed order. */
void testgen_public(TestList *list);

/* The hidden tests (tests/hidden/hidden.c): fixed cases and cases drawn
 * from seed, so the same seed always gives the same tests. */
void testgen_hidden(TestList *list, uint64_t seed);

/* Building blocks, shared by the public and hidden tests.  Each adds one
 * case to t with its expected value, tolerance and hints. */
void tg_plane(Test *t, double fov, double aspect, double d);
void tg_pixel(Test *t, int i, int j, int nx, int ny, double w, double h, double d);
void tg_sphere(Test *t, const double c[3], double R, const double e[3], const double r[3]);
void tg_camera(Test *t, const double eye[3], const double pixel[3]);
void tg_color(Test *t, const double e[3], const double r[3]);   /* t's scene */
/* An image test of the scene file at nx x ny: one case per pixel. */
Test *tg_image(TestList *list, const char *name, const char *scene_path, int nx, int ny);

/* The hard cases of hard.c for rounds first_round .. first_round + rounds - 1
 * of every family (Part 3a: twice as many), as tests tagged hard. */
void tg_hard(TestList *list, uint64_t seed, int first_round, int rounds, bool hidden);

/* A small deterministic random number generator (splitmix64). */
typedef struct { uint64_t s; } TgRandom;
double tg_uniform(TgRandom *r, double lo, double hi);
double tg_log_uniform(TgRandom *r, double lo, double hi);
int tg_int(TgRandom *r, int lo, int hi);              /* lo .. hi inclusive */

#endif
