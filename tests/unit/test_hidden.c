/*
 * test_hidden.c - the hidden tests (tests/hidden) test what they say
 * whatever the seed: an instructor changes the seed every term, and a
 * mistake must not pass a hidden test by the luck of one.
 */
#include "check.h"
#include "../grader/grader.h"
#include "../oracle/testgen.h"
#include "kit/scene.h"
#include "raytracer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* How many seeds each test draws (the sanitized build, which checks the
 * code rather than the seeds, draws fewer: the Makefile). */
#ifndef SEEDS
#define SEEDS 300           /* every hidden test of Parts 1-3b: 2.6 ms a seed */
#endif
#ifndef SEEDS_FLAT
#define SEEDS_FLAT 1000     /* the random tests of Parts 4 and 5 alone: 1.2 ms a seed */
#endif
/* The seeds drawn are 1, 2, ... as weights.conf would give them, salted as
 * the grader salts them (testgen.h). */

static const Test *find(const TestList *l, const char *name)
{
    for (int k = 0; k < l->n; k++)
        if (strcmp(l->tests[k].name, name) == 0)
            return &l->tests[k];
    return NULL;
}

/* ---- Parts 1 and 2: no hard family passes a mistake by one case's luck ----- */

/* The mistakes of the p1-* and p2-* self-tests that are right on some
 * inputs: a square image, a middle row, i = j, an aspect of 1. */
enum { W_H_SWAPPED, ASPECT_INVERTED, SHORTER_AXIS, Y_NOT_FLIPPED, I_J_SWAPPED, NX_FOR_Y, CAMERA_MISTAKES };
static const char *const camera_mistake[CAMERA_MISTAKES] = {
    "w and h swapped", "w = h / aspect", "the field of view along the shorter side (rw-pbrt-camera)",
    "rows counted from the bottom (y not flipped)",
    "i and j swapped", "nx for ny in y",
};

/* Part 1's (w, h) or Part 2's (x, y, z) as mistake m gives them for case c. */
static void camera_mistaken(int m, const double *in, double *out)
{
    if (m <= SHORTER_AXIS) {
        double fov = in[0], aspect = in[1], d = in[2], side = 2 * d * tan(fov * M_PI / 360);
        double w = aspect * side, h = side;                 /* right */
        if (m == W_H_SWAPPED)
            w = side, h = aspect * side;
        else if (m == ASPECT_INVERTED)
            w = side / aspect;
        else if (aspect < 1)                                /* shorter axis: the width */
            w = side, h = side / aspect;
        out[0] = w, out[1] = h;
        return;
    }
    double i = in[0], j = in[1], nx = in[2], ny = in[3], w = in[4], h = in[5], d = in[6];
    out[0] = -w / 2 + w * ((m == I_J_SWAPPED ? j : i) + 0.5) / nx;
    out[1] = m == Y_NOT_FLIPPED ? -h / 2 + h * (j + 0.5) / ny
           : m == I_J_SWAPPED   ? h / 2 - h * (i + 0.5) / ny
                                : h / 2 - h * (j + 0.5) / nx;
    out[2] = -d;
}

static bool camera_families_catch_every_mistake(const TestList *l, uint64_t seed)
{
    for (int k = 0; k < l->n; k++) {
        const Test *t = &l->tests[k];
        if (!t->hard || (t->part != PART1 && t->part != PART2))
            continue;
        int first = t->part == PART1 ? 0 : Y_NOT_FLIPPED, end = t->part == PART1 ? Y_NOT_FLIPPED : CAMERA_MISTAKES;
        for (int m = first; m < end; m++) {
            int failed = 0;
            for (int c = 0; c < t->ncases; c++) {
                double out[3];
                camera_mistaken(m, t->cases[c].in, out);
                failed += !case_is_right(t->kind, &t->cases[c], out);
            }
            CHECK_MSG(failed > 0, "seed %llu: \"%s\" (%d cases) passes %s", (unsigned long long)seed, t->name,
                      t->ncases, camera_mistake[m]);
            if (failed == 0)
                return false;
        }
    }
    return true;
}

/* ---- Part 3a: where a tmin is tested, and where not ------------------------ */

/* Every seed's random rays at random spheres hit at t >= 0.01 or miss, so
 * that a tmin up to 0.01 loses that test never; and every seed's rays from
 * just outside have hits at t < 0.001, so that a tmin of 0.001 loses that
 * one always. */
static bool tmin_is_tested(const TestList *l, uint64_t seed)
{
    const Test *any = find(l, "Part 3a: hidden: random rays at random spheres");
    const Test *near = find(l, "Part 3a: hidden: random rays from just outside spheres");
    CHECK_MSG(any && near, "no hidden tests of random rays at spheres");
    double least_any = INFINITY, least_near = INFINITY;
    int hits = 0;
    for (int c = 0; any && c < any->ncases; c++)
        if (any->cases[c].want[0] == 1) {
            hits++;
            least_any = fmin(least_any, any->cases[c].want[1]);
        }
    for (int c = 0; near && c < near->ncases; c++)
        if (near->cases[c].want[0] == 1)
            least_near = fmin(least_near, near->cases[c].want[1]);
    bool ok = any && near && hits >= 30 && least_any >= 0.01 && least_near < 0.001;
    CHECK_MSG(ok, "seed %llu: %d hits at random spheres, the nearest at t = %g (want >= 0.01); the "
              "nearest from just outside at t = %g (want < 0.001)", (unsigned long long)seed, hits,
              least_any, least_near);
    return ok;
}

/* ---- Part 3b: ray_color's mistakes, as the self-tests write them ----------- */

enum { BACKGROUND_IGNORED, PAST_END, FIRST_HIT, LAST_HIT, FARTHEST_HIT, MISTAKES };
static const char *const mistake_name[MISTAKES] = {
    "the background ignored (black where nothing is hit)",
    "a read past the last sphere (the grader's marker sphere, around everything, where nothing else is hit)",
    "the first sphere listed that is hit, not the nearest",
    "the last sphere listed that is hit, not the nearest",
    "the farthest hit, not the nearest",
};

static Vec3 mistaken_color(const Scene *scene, const Ray *ray, int mistake)
{
    Vec3 color = scene->background;
    if (mistake == BACKGROUND_IGNORED)
        color = vec3(0, 0, 0);
    if (mistake == PAST_END)
        color = scene_guard_sphere().color;
    double best = mistake == FARTHEST_HIT ? -INFINITY : INFINITY;
    bool found = false;
    for (int k = 0; k < scene->nspheres; k++) {
        double tt;
        if (!sphere_intersect(&scene->spheres[k], ray, &tt))
            continue;
        bool take = mistake == FIRST_HIT ? !found : mistake == LAST_HIT ? true
                  : mistake == FARTHEST_HIT ? tt > best : tt < best;
        if (take) {
            best = tt;
            color = scene->spheres[k].color;
        }
        found = true;
    }
    return color;
}

/* The test's scene as ray_color reads it (spheres malloc'd). */
static Scene scene_of_test(const Test *t)
{
    Scene scene = { 0 };
    scene.background = vec3(t->background[0], t->background[1], t->background[2]);
    scene.spheres = calloc((size_t)t->nspheres, sizeof *scene.spheres);
    scene.nspheres = t->nspheres;
    for (int k = 0; k < t->nspheres; k++) {
        const TestSphere *s = &t->spheres[k];
        scene.spheres[k] = (Sphere){ vec3(s->c[0], s->c[1], s->c[2]), s->R,
                                     vec3(s->color[0], s->color[1], s->color[2]) };
    }
    return scene;
}

/* How many cases of t the reference (m < 0) or mistake m answers wrongly. */
static int wrong_cases(const Test *t, const Scene *scene, int m)
{
    int failed = 0;
    for (int c = 0; c < t->ncases; c++) {
        const Case *cs = &t->cases[c];
        Ray ray = { vec3(cs->in[0], cs->in[1], cs->in[2]), vec3(cs->in[3], cs->in[4], cs->in[5]) };
        Vec3 got = m < 0 ? ray_color(scene, &ray) : mistaken_color(scene, &ray, m);
        failed += !case_is_right(t->kind, cs, (const double[3]){ got.x, got.y, got.z });
    }
    return failed;
}

static bool random_scene_catches_every_mistake(const TestList *l, uint64_t seed)
{
    const Test *t = find(l, "Part 3b: hidden: ray_color in a random scene of 8 spheres");
    CHECK_MSG(t != NULL, "no hidden test of ray_color in a random scene");
    if (!t)
        return false;
    Scene scene = scene_of_test(t);
    int ref = wrong_cases(t, &scene, -1);
    CHECK_MSG(ref == 0, "seed %llu: the reference fails %d cases of the hidden test of ray_color",
              (unsigned long long)seed, ref);
    bool ok = ref == 0;
    for (int m = 0; m < MISTAKES && ok; m++) {
        ok = wrong_cases(t, &scene, m) > 0;
        CHECK_MSG(ok, "seed %llu: the hidden test of ray_color passes %s", (unsigned long long)seed,
                  mistake_name[m]);
    }
    free(scene.spheres);
    return ok;
}

/* Every seed's hidden hard scenes of Part 3b hold both variants of each
 * family: in the room, a sphere before the wall and one beyond it, where
 * the last sphere hit in the list (the small one) is wrong. */
static bool hard_scenes_hold_both_variants(const TestList *l, uint64_t seed)
{
    int scenes = 0, failed = 0;
    for (int k = 0; k < l->n; k++) {
        const Test *t = &l->tests[k];
        if (!t->hard || t->part != PART3B || !strstr(t->name, "eye inside a big sphere"))
            continue;
        Scene scene = scene_of_test(t);
        CHECK_MSG(wrong_cases(t, &scene, -1) == 0, "seed %llu: the reference fails \"%s\"",
                  (unsigned long long)seed, t->name);
        scenes++;
        failed += wrong_cases(t, &scene, LAST_HIT) > 0;
        free(scene.spheres);
    }
    bool ok = scenes > 0 && failed > 0;
    CHECK_MSG(ok, "seed %llu: the hidden hard family \"eye inside a big sphere\" (%d scenes) passes %s",
              (unsigned long long)seed, scenes, mistake_name[LAST_HIT]);
    return ok;
}

/* And each mistake of the order of the hits fails the same hidden hard
 * scenes of Part 3b with every seed (the scenes are named alike whatever
 * the seed), and some: where the draw decided, the touching spheres' odd
 * scene (which of the two is entered first) and the nested ones (whether
 * the ray met the small sphere), a ray_color that took the first sphere hit
 * in the list got 1.56 to 1.83 of the 2.5 hard points over the seeds 1-16. */
static bool hard_scenes_fail_alike(const TestList *l, uint64_t seed)
{
    static const int order_mistakes[] = { FIRST_HIT, LAST_HIT, FARTHEST_HIT };
    enum { N = sizeof order_mistakes / sizeof order_mistakes[0], LEN = 4096 };
    static char first[N][LEN];
    static bool have_first;
    char now[N][LEN];
    memset(now, 0, sizeof now);
    for (int k = 0; k < l->n; k++) {
        const Test *t = &l->tests[k];
        if (!t->hard || t->part != PART3B || t->kind != KIND_COLOR)
            continue;
        Scene scene = scene_of_test(t);
        for (int m = 0; m < N; m++)
            if (wrong_cases(t, &scene, order_mistakes[m]) > 0) {
                const char *name = strstr(t->name, "hard: ") ? strstr(t->name, "hard: ") + 6 : t->name;
                size_t len = strlen(now[m]);
                snprintf(now[m] + len, LEN - len, "%s\"%s\"", len ? ", " : "", name);
            }
        free(scene.spheres);
    }
    bool ok = true;
    for (int m = 0; m < N && ok; m++) {
        if (!have_first)
            memcpy(first[m], now[m], LEN);
        ok = now[m][0] != 0 && strcmp(now[m], first[m]) == 0;
        CHECK_MSG(ok, "seed %llu: %s fails the hidden hard scenes %s; with seed 1, %s", (unsigned long long)seed,
                  mistake_name[order_mistakes[m]], now[m][0] ? now[m] : "(none)", first[m]);
    }
    have_first = true;
    return ok;
}

/* ---- Parts 1-3b: the checks above, on one drawing of each seed ----------- */

/* Drawing a seed's hidden tests is the cost (2.6 ms a seed): each seed is
 * drawn once and given to every check, and a check stops at its first
 * failing seed. */
static void test_hidden_tests_whatever_the_seed(void)
{
    static bool (*const checks[])(const TestList *, uint64_t) = {
        camera_families_catch_every_mistake, tmin_is_tested, random_scene_catches_every_mistake,
        hard_scenes_hold_both_variants, hard_scenes_fail_alike,
    };
    enum { NCHECKS = sizeof checks / sizeof checks[0] };
    bool failed[NCHECKS] = { false };
    for (uint64_t seed = 1; seed <= SEEDS; seed++) {
        TestList l = { 0 };
        testgen_hidden(&l, seed ^ HIDDEN_SALT_CORE);
        for (int k = 0; k < NCHECKS; k++)
            if (!failed[k])
                failed[k] = !checks[k](&l, seed);
        testlist_free(&l);
    }
}

/* ---- Part 5: triangle_intersect's mistakes, as the self-tests write them -- */

enum { NO_SUM_CHECK = 1, NO_T_CHECK = 2, ONE_SIDED = 4, BETA_AT_MOST_1 = 8, DET_EPSILON = 16 };

/* Moller-Trumbore with the checks a mistake leaves out. */
static bool mistaken_triangle(const Triangle *tri, const Ray *ray, double *t, int mistake)
{
    Vec3 e1 = vec3_sub(tri->b, tri->a), e2 = vec3_sub(tri->c, tri->a), q = vec3_cross(ray->direction, e2);
    double det = vec3_dot(e1, q);
    if (mistake & ONE_SIDED ? det <= 0 : mistake & DET_EPSILON ? fabs(det) < 1e-8 : det == 0)
        return false;
    Vec3 s = vec3_sub(ray->origin, tri->a), r = vec3_cross(s, e1);
    double beta = vec3_dot(s, q) / det, gamma = vec3_dot(ray->direction, r) / det, tt = vec3_dot(e2, r) / det;
    if (beta < 0 || gamma < 0 || (!(mistake & NO_SUM_CHECK) && beta + gamma > 1) ||
        (mistake & BETA_AT_MOST_1 && beta > 1))
        return false;
    if (!(mistake & NO_T_CHECK) && !(tt > 0))
        return false;
    *t = tt;
    return true;
}

static void test_random_triangles_catch_every_mistake(void)
{
    static const struct { int flags; const char *name; } mistakes[] = {
        { NO_SUM_CHECK, "no check of beta + gamma <= 1" },
        { NO_SUM_CHECK | BETA_AT_MOST_1, "beta <= 1 checked, but not beta + gamma <= 1 (p5-no-sum-check)" },
        { NO_T_CHECK, "no check of t > 0" },
        { ONE_SIDED, "one side of the triangle only" },
        { DET_EPSILON, "|det| < 1e-8 taken for a miss (p5-det-epsilon)" },
    };
    for (uint64_t seed = 1; seed <= SEEDS_FLAT; seed++) {
        TestList l = { 0 };
        testgen_hidden_flat_random(&l, seed ^ HIDDEN_SALT_FLAT);
        const Test *t = find(&l, "Part 5: hidden: random rays at random triangles");
        CHECK_MSG(t != NULL, "no hidden test of random rays at random triangles");
        bool ok = t != NULL;
        for (int m = -1; ok && m < (int)(sizeof mistakes / sizeof mistakes[0]); m++) {
            int failed = 0;
            for (int c = 0; c < t->ncases; c++) {
                const double *in = t->cases[c].in;
                Triangle tri = { vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]), vec3(in[6], in[7], in[8]),
                                 vec3(1, 1, 1) };
                Ray ray = { vec3(in[9], in[10], in[11]), vec3(in[12], in[13], in[14]) };
                double tt = 0;
                bool hit = m < 0 ? triangle_intersect(&tri, &ray, &tt)
                                 : mistaken_triangle(&tri, &ray, &tt, mistakes[m].flags);
                failed += !case_is_right(t->kind, &t->cases[c], (const double[2]){ hit, tt });
            }
            ok = m < 0 ? failed == 0 : failed > 0;
            CHECK_MSG(ok, "seed %llu: the hidden test of random triangles %s %s", (unsigned long long)seed,
                      m < 0 ? "fails" : "passes", m < 0 ? "the reference" : mistakes[m].name);
        }
        testlist_free(&l);
        if (!ok)
            return;
    }
}

static const CheckTest tests[] = {
    CHECK_TEST(test_hidden_tests_whatever_the_seed),
    CHECK_TEST(test_random_triangles_catch_every_mistake),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
