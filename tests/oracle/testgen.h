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

/* The relative tolerance of the core tests (hard tests: the oracle's). */
#define TG_CORE_REL 1e-9

/* A point or a vector written out, as the tg_ functions take them; V3, a
 * Vec3's. */
#define V(x, y, z) ((const double[3]){ x, y, z })
#define V3(v) V((v).x, (v).y, (v).z)

/* The public tests, core and hard, in a fixed order; their hard cases are
 * drawn from this seed. */
void testgen_public(TestList *list);
#define PUBLIC_HARD_SEED 20261122u

/* The hidden tests (tests/hidden/hidden.c): fixed cases and cases drawn
 * from seed, so the same seed always gives the same tests. */
void testgen_hidden(TestList *list, uint64_t seed);

/* A test of list, of the given weight, with the note shown beside it. */
Test *tg_test(TestList *list, int part, Kind kind, double weight, const char *name, const char *note);

/* Building blocks, shared by the public and hidden tests.  Each adds one
 * case to t with its expected value, tolerance and hints. */
void tg_plane(Test *t, double fov, double aspect, double d);
void tg_pixel(Test *t, int i, int j, int nx, int ny, double w, double h, double d);
void tg_sphere(Test *t, const double c[3], double R, const double e[3], const double r[3]);
void tg_camera(Test *t, const double eye[3], const double pixel[3]);
void tg_color(Test *t, const double e[3], const double r[3]);   /* t's scene */
/* An image test of the scene file at nx x ny: one case per pixel. */
Test *tg_image(TestList *list, const char *name, const char *scene_path, int nx, int ny);

/* The hard cases of hard.c, the first `rounds` rounds of every family
 * (Parts 3a and 3b: two cases a round, Parts 1 and 2: four), as tests
 * tagged hard. */
void tg_hard(TestList *list, uint64_t seed, int rounds, bool hidden);

/* A test of the hard-case group ("Part P: [hidden: ]hard: FAMILY"), and the
 * one of this family among the tests from index first on (made if none). */
Test *tg_hard_test(TestList *list, int part, Kind kind, const char *family, bool hidden);
Test *tg_family_test(TestList *list, int first, int part, Kind kind, const char *family, bool hidden);

/* A family of misses alone (spheres behind, grazing rays) would give the
 * always-miss skeleton points: adds a plain hit to every hit test from
 * index first on that has no case whose certain answer is a hit. */
void tg_add_plain_hits(TestList *list, int first);

/* ---- Parts 4 and 5 (testgen_flat.c) ---- */

/* One case of plane_intersect (p, n, e, r) or of triangle_intersect
 * (a, b, c, e, r). */
void tg_planehit(Test *t, const double p[3], const double n[3], const double e[3], const double r[3]);
void tg_triangle(Test *t, const double a[3], const double b[3], const double c[3],
                 const double e[3], const double r[3]);

/* The hard cases of Part 5 (hard_flat.c) as tests tagged hard, as tg_hard
 * does for the others; Part 4's families as core tests, which the
 * lecture's formula meets (Part 4 has no challenge of its own). */
void tg_hard_flat(TestList *list, uint64_t seed, int rounds, bool hidden);

/* The random hidden cases' seeds: tests/weights.conf's seed, mixed with
 * the first constant for Parts 1-3b and the second for Parts 4-5.  Not
 * with the submission's files: every submission meets the same cases, so
 * one that changes only a comment or a space cannot draw other (easier)
 * ones where its score is shown at once (PrairieLearn), and the same code
 * gets the same grade whoever wrote it.  Change the seed each term. */
#define HIDDEN_SALT_CORE 0xcbf29ce484222325u
#define HIDDEN_SALT_FLAT 0x9e3779b97f4a7c15u

/* The public and hidden tests of Parts 4 and 5. */
void testgen_public_flat(TestList *list);
void testgen_hidden_flat(TestList *list, uint64_t seed);
/* Its random tests alone, without the hard cases (tests/unit/test_hidden.c). */
void testgen_hidden_flat_random(TestList *list, uint64_t seed);

#endif
