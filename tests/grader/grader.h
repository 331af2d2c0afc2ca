/*
 * grader.h - the autograder's model: parts, tests, cases and their results.
 *
 * A test is one run of a fresh child process built from the submission's
 * file for one part; it holds many cases and passes only when every case
 * does.  Expected values come from outside that process: from the test
 * files under tests/public and tests/hidden (written by tests/oracle), or,
 * in the instructor's kit, from the oracle at grading time.
 */
#ifndef GRADER_H
#define GRADER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

enum { PART1, PART2, PART3A, PART3B, PART4, PART5, NPARTS };

/* Parts 4 and 5 are optional: graded only where tests/weights.conf's
 * "parts" line lists them, or when asked for by name (PART=4). */
#define NCORE_PARTS 4

/* What a test's child computes for each case. */
typedef enum {
    KIND_PLANE,       /* Part 1:  in fov aspect d           -> w h          */
    KIND_PIXEL,       /* Part 2:  in i j nx ny w h d        -> x y z        */
    KIND_SPHERE,      /* Part 3a: in cx cy cz R ex ey ez rx ry rz -> hit t  */
    KIND_CAMERA,      /* Part 3b: in eye(3) pixel(3)        -> origin(3) direction(3) */
    KIND_COLOR,       /* Part 3b: in ray origin(3) dir(3)   -> colour(3), with the test's scene */
    KIND_IMAGE,       /* Part 3b: in pixel centre(3)        -> colour(3), eye at the origin,
                         through the child's camera_ray and ray_color            */
    KIND_PLANEHIT,    /* Part 4:  in p(3) n(3) e(3) r(3)    -> hit t            */
    KIND_TRIANGLE,    /* Part 5:  in a(3) b(3) c(3) e(3) r(3) -> hit t          */
    KIND_MESH,        /* Part 5:  in e(3) r(3)              -> hit t, the first hit
                         over the test's triangles (a closed mesh)              */
    NKINDS
} Kind;

#define CASE_MAX_IN   15
#define CASE_MAX_OUT  6
#define CASE_MAX_HINTS 12
#define TEST_MAX_WEIGHT 1e6       /* a test's weight, in a test file        */
#define TEST_MAX_NX   16384       /* an image test's width, as a scene's     */

/* Case flags */
#define CASE_EITHER_HIT 1u     /* hit or miss both acceptable (rounding); for
                                  Parts 4 and 5 a hit then needs t within tol
                                  of want, or t >= alt[1] (parallel rays)     */

typedef struct {
    char text[160];                /* the known mistake, as told to the student */
    double out[CASE_MAX_OUT];      /* what that mistake produces                */
} Hint;

typedef struct {
    double in[CASE_MAX_IN];
    double want[CASE_MAX_OUT];     /* expected outputs                          */
    double tol[CASE_MAX_OUT];      /* accepted |got - want| per output           */
    double alt[CASE_MAX_OUT];      /* KIND_COLOR/IMAGE: another acceptable colour
                                      when the flag CASE_EITHER_HIT is set;
                                      KIND_SPHERE with that flag: a hit at t in
                                      [alt[0], alt[1]] is right too (none when
                                      alt[0] >= alt[1]);
                                      Parts 4 and 5: alt[1] is the smallest t
                                      accepted for a ray parallel within rounding */
    unsigned flags;
    int nhints;                    /* at most CASE_MAX_HINTS                    */
    Hint *hints;                   /* malloc'd (case_add_hint); most cases have
                                      none, and a case with room for all of them
                                      inline made the tests' lists seven times
                                      larger, paid in page faults per grading  */
} Case;

typedef struct {
    double c[3], R, color[3];
} TestSphere;

typedef struct {
    double v[9];                   /* a(3) b(3) c(3) */
} TestTriangle;

typedef struct {
    char name[128];                /* starts with "Part 1: " etc.               */
    int part;
    Kind kind;
    bool hard;                     /* the hard-case group (tag "hard")          */
    bool hidden;                   /* visibility after_published                */
    double weight;                 /* share of the part's (or group's) points   */
    char note[160];                /* what the test is about, shown on failure  */
    /* KIND_COLOR and KIND_IMAGE: the scene */
    double background[3];
    int nspheres;
    TestSphere *spheres;
    int image_nx;                  /* KIND_IMAGE: image width, for messages     */
    int ntriangles;                /* KIND_MESH: the mesh                       */
    TestTriangle *triangles;
    int ncases, cap;
    Case *cases;
} Test;

typedef struct {
    int n, cap;
    Test *tests;
} TestList;

/* Number of numbers in and out for a kind. */
int kind_nin(Kind kind);
int kind_nout(Kind kind);
const char *kind_name(Kind kind);        /* "plane", "pixel", ... as the test files say */
const char *part_label(int part);        /* "1", "2", "3a", "3b", "4", "5" */
const char *part_title(int part);        /* "Part 1: image plane size"   */
int part_from_label(const char *label);  /* -1 if unknown                */
/* A number of points as people read them: rounded to two decimals, with no
 * trailing zeros ("22.94", "20", "2.5").  The table, the page and the
 * results' text show points so; the results' scores and the gradebook keep
 * the numbers as they are.  Use the .s of the value returned. */
typedef struct { char s[32]; } PointsText;
PointsText points_text(double points);
/* Appends printf-style text to a malloc'd string (left as it was if memory
 * runs out). */
void appendf(char **s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A file written as a stream: save_open opens one in memory (NULL, with
 * "path: out of memory" in err, when it cannot), save_close closes it and
 * saves what was written to path with mode (less the umask,
 * kit_save_file_mode); 0, or -1 with "path: reason" in err and path as it
 * was. */
typedef struct {
    FILE *f;
    char *data;
    size_t len;
} SaveStream;
FILE *save_open(SaveStream *s, const char *path, char *err, size_t errlen);
int save_close(SaveStream *s, const char *path, unsigned mode, char *err, size_t errlen);

Test *testlist_add(TestList *list, int part, Kind kind, const char *name);
Case *test_add_case(Test *test);
/* A new hint at the end of the case's (nhints < CASE_MAX_HINTS). */
Hint *case_add_hint(Case *c);
void test_add_sphere(Test *test, const double c[3], double R, const double color[3]);
void test_add_triangle(Test *test, const double v[9]);
/* Whether a kind's answer is (hit, t): Parts 3a, 4 and 5. */
bool kind_is_hit(Kind kind);
void testlist_free(TestList *list);
/* Removes the hard-case tests of each part p with drop[p] (a part whose
 * hard cases are worth nothing has none), keeping the others in order. */
void testlist_drop_hard(TestList *list, const bool drop[NPARTS]);

/* Reads or writes the test files' text format (see cases.c). */
int tests_read(TestList *list, const char *path, bool hidden, char *err, size_t errlen);
int tests_write(const TestList *list, const char *path, const char *header, char *err, size_t errlen);

/* A child's answers to a test's cases, as the parent read and judged them. */
typedef struct {
    int answered;                  /* cases answered before the answers stopped */
    int failed;                    /* of those, the wrong ones                  */
    int first_bad;                 /* the first wrong case, or -1               */
    bool complete;                 /* every case answered, then "end N"         */
    double (*got)[CASE_MAX_OUT];   /* one row per case answered (malloc'd)      */
    bool *ok;                      /* per case answered: right?  (malloc'd)     */
    const char *named;             /* Parts 4 and 5: the known mistake that
                                      explains the answers (a hint text of the
                                      test), or NULL                            */
} Answers;

void answers_free(Answers *a);

/* The outcome of one test. */
typedef struct {
    bool ran;                      /* the child ran (answers holds its answers) */
    bool passed;
    double score, max_score;
    char *output;                  /* what the student is told (malloc'd)      */
    size_t verdict_at, verdict_len; /* where in output the judging of the
                                      answers is (check_answers_in_part's
                                      message); 0, 0 when none              */
    double seconds;
    Answers answers;
} TestResult;

/* Checks a child's answers against the test.  answers holds one line per
 * case ("%a ..." numbers) and the final "end N" line.  Returns true when
 * every case is right; out receives the message for the student, and a,
 * when not NULL, every answer and whether it was right. */
bool check_answers(const Test *test, const char *answers, size_t len, char **out, Answers *a);
/* What the same code did in the other tests of a part, for the hints of
 * Parts 4 and 5 (check.c): a known mistake a passed test rules out is not
 * named, and of two that fit, the one named for another failed test is. */
typedef struct {
    const Test *const *passed;     /* the tests of the part it passed          */
    int npassed;
    const char *const *named;      /* the mistakes named for its other failed
                                      tests judged so far (check_part_again:
                                      all of them)                              */
    int nnamed;
} PartSoFar;

/* The same, for a test judged beside the other tests of its part (part may
 * be NULL: none). */
bool check_answers_in_part(const Test *test, const char *answers, size_t len,
                           const PartSoFar *part, char **out, Answers *a);
/* A failed test of Parts 4 and 5 whose answers a named no mistake, judged
 * again once its part's every test is: part lists the tests passed and the
 * mistakes named for the part's other failed tests, those judged after it
 * too.  True when a mistake is named now (a->named), with the message for
 * the student in out; false, out untouched, when not. */
bool check_name_again(const Test *test, Answers *a, const PartSoFar *part, char **out);
/* After every test of part (grader.h's numbering) is judged: each failed
 * test of Parts 4 and 5 that named no mistake judged again with what the
 * whole part showed (check_name_again), again until nothing changes, so
 * that the order of the tests' files does not matter; a mistake named now
 * replaces the test's verdict in its output (verdict_at, verdict_len). */
void check_part_again(const TestList *tests, TestResult *results, int part);
/* A batch's answers (every test of a part, run in one child), split after
 * each line that starts "end ": from[k] and size[k] are the k-th test's
 * answers.  Returns ntests when the answers split into exactly ntests
 * pieces with nothing after the last, else -1 (then each test runs
 * alone).  Reads only answers[0 .. len). */
int batch_split(const char *answers, size_t len, int ntests, const char **from, size_t *size);

/* Is got the right answer to case c of a test of this kind? */
bool case_is_right(Kind kind, const Case *c, const double *got);

#endif
