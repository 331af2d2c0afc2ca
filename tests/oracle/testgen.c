/*
 * testgen.c - the public tests and the building blocks of every test.
 *
 * Expected values come from the oracle (double-double, oracle.c); the
 * hints of known mistakes (Parts 4 and 5) are in testgen_flat.c.
 * Tolerances: core tests accept any correct double formula (relative 1e-9,
 * or the oracle's conditioning bound for t when that is larger); hard tests
 * accept a few units of roundoff times the problem's condition number (see
 * oracle.h).
 */
#include "testgen.h"
#include "oracle.h"
#include "hard.h"
#include "../../labs/kit/scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define U ORACLE_U

/* ---- Part 1 ---------------------------------------------------------------- */

void tg_plane(Test *t, double fov, double aspect, double d)
{
    Case *c = test_add_case(t);
    c->in[0] = fov, c->in[1] = aspect, c->in[2] = d;
    oracle_image_plane(fov, aspect, d, &c->want[0], &c->want[1]);
    double rel = t->hard ? HARD_PART1_REL_TOL : TG_CORE_REL;
    c->tol[0] = rel * fabs(c->want[0]);
    c->tol[1] = rel * fabs(c->want[1]);
}

/* ---- Part 2 ---------------------------------------------------------------- */

void tg_pixel(Test *t, int i, int j, int nx, int ny, double w, double h, double d)
{
    Case *c = test_add_case(t);
    double in[7] = { i, j, nx, ny, w, h, d };
    memcpy(c->in, in, sizeof in);
    Vec3 p = oracle_pixel(i, j, nx, ny, w, h, d);
    c->want[0] = p.x, c->want[1] = p.y, c->want[2] = p.z;
    /* Hard: relative to the coordinate itself (hard.h), the centre column
     * and row exact; core: to the plane's size. */
    c->tol[0] = t->hard ? HARD_PART2_TOL_U * U * fabs(p.x) : TG_CORE_REL * fabs(w);
    c->tol[1] = t->hard ? HARD_PART2_TOL_U * U * fabs(p.y) : TG_CORE_REL * fabs(h);
    /* z = -d exactly is a hard case's demand; a core test takes z as it
     * takes x and y, so that a pixel unprojected through the inverse of a
     * projection matrix (gluUnProject), -d within an ulp, is right. */
    c->tol[2] = t->hard ? 0 : TG_CORE_REL * fabs(d);
}

/* ---- Part 3a ---------------------------------------------------------------- */

void tg_sphere(Test *t, const double c3[3], double R, const double e[3], const double r[3])
{
    Case *c = test_add_case(t);
    Sphere s = { vec3(c3[0], c3[1], c3[2]), R, vec3(1, 1, 1) };
    Ray ray = { vec3(e[0], e[1], e[2]), vec3(r[0], r[1], r[2]) };
    memcpy(c->in, c3, 3 * sizeof *c3);
    c->in[3] = R;
    memcpy(c->in + 4, e, 3 * sizeof *e);
    memcpy(c->in + 7, r, 3 * sizeof *r);
    OracleHit o = oracle_sphere(&s, &ray);
    c->want[0] = o.hit ? 1 : 0;
    c->want[1] = o.hit ? o.t : 0;
    if (o.ambiguous)
        c->flags |= CASE_EITHER_HIT;
    if (o.hit) {
        double tol = oracle_sphere_t_tolerance(&s, &ray, &o);
        c->tol[1] = t->hard ? tol : fmax(tol, TG_CORE_REL * o.t);
        /* In doubt, every hit the oracle accepts: those near o.t widen the
         * tolerance, another apart (the far root from an origin on the
         * surface) goes to alt as an interval. */
        double near_tol = c->tol[1], lo, hi;
        if (o.ambiguous && oracle_sphere_other_hits(&s, &ray, &o, c->tol[1], &near_tol, &lo, &hi)) {
            c->alt[0] = lo;
            c->alt[1] = hi;
        }
        c->tol[1] = fmax(c->tol[1], near_tol);
    }
}

/* ---- Part 3b ---------------------------------------------------------------- */

void tg_camera(Test *t, const double eye[3], const double pixel[3])
{
    Case *c = test_add_case(t);
    memcpy(c->in, eye, 3 * sizeof *eye);
    memcpy(c->in + 3, pixel, 3 * sizeof *pixel);
    Vec3 u = oracle_unit(vec3(pixel[0] - eye[0], pixel[1] - eye[1], pixel[2] - eye[2]));
    double want[6] = { eye[0], eye[1], eye[2], u.x, u.y, u.z };
    memcpy(c->want, want, sizeof want);
    for (int k = 3; k < 6; k++)
        c->tol[k] = t->hard ? HARD_PART3B_DIR_TOL_U * U : TG_CORE_REL;
}

static void colour_of(const Test *t, int k, double out[3])
{
    memcpy(out, k < 0 ? t->background : t->spheres[k].color, 3 * sizeof *out);
}

static Scene scene_of(const Test *t, Sphere *spheres)
{
    Scene s;
    memset(&s, 0, sizeof s);
    s.background = vec3(t->background[0], t->background[1], t->background[2]);
    for (int k = 0; k < t->nspheres; k++) {
        const TestSphere *ts = &t->spheres[k];
        spheres[k] = (Sphere){ vec3(ts->c[0], ts->c[1], ts->c[2]), ts->R,
                               vec3(ts->color[0], ts->color[1], ts->color[2]) };
    }
    s.spheres = spheres;
    s.nspheres = t->nspheres;
    return s;
}

/* Expected colour of a ray in t's scene, with the hints for its mistakes. */
static void colour_case(Test *t, Case *c, const Scene *scene, Ray ray)
{
    bool ambiguous = false;
    int alt = -1;
    int k = oracle_closest(scene, &ray, &ambiguous, &alt);
    colour_of(t, k, c->want);
    if (ambiguous) {
        c->flags |= CASE_EITHER_HIT;
        colour_of(t, alt, c->alt);
    }
    /* tol stays 0: ray_color returns a sphere's colour unchanged */
}

void tg_color(Test *t, const double e[3], const double r[3])
{
    Case *c = test_add_case(t);
    memcpy(c->in, e, 3 * sizeof *e);
    memcpy(c->in + 3, r, 3 * sizeof *r);
    Sphere *spheres = calloc((size_t)t->nspheres + 1, sizeof *spheres);
    Scene scene = scene_of(t, spheres);
    colour_case(t, c, &scene, (Ray){ vec3(e[0], e[1], e[2]), vec3(r[0], r[1], r[2]) });
    free(spheres);
}

Test *tg_test(TestList *list, int part, Kind kind, double weight, const char *name, const char *note)
{
    Test *t = testlist_add(list, part, kind, name);
    t->weight = weight;
    snprintf(t->note, sizeof t->note, "%s", note);
    return t;
}

Test *tg_image(TestList *list, const char *name, const char *scene_path, int nx, int ny)
{
    Scene file;
    char err[512];
    if (scene_load(&file, scene_path, err, sizeof err) != 0) {
        fprintf(stderr, "testgen: %s\n", err);
        exit(2);
    }
    Test *t = testlist_add(list, PART3B, KIND_IMAGE, name);
    t->image_nx = nx;
    memcpy(t->background, V3(file.background), sizeof t->background);
    for (int k = 0; k < file.nspheres; k++)
        test_add_sphere(t, V3(file.spheres[k].center), file.spheres[k].radius, V3(file.spheres[k].color));
    double w, h;
    oracle_image_plane(file.fov_degrees, (double)nx / ny, file.d, &w, &h);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            Vec3 p = oracle_pixel(i, j, nx, ny, w, h, file.d);
            Case *c = test_add_case(t);
            c->in[0] = p.x, c->in[1] = p.y, c->in[2] = p.z;
            colour_case(t, c, &file, (Ray){ vec3(0, 0, 0), p });
        }
    scene_free(&file);
    return t;
}

/* ---- the hard cases (hard.c), as tests tagged "hard" ------------------------ */

Test *tg_hard_test(TestList *l, int part, Kind kind, const char *family, bool hidden)
{
    char name[128];
    snprintf(name, sizeof name, "Part %s: %shard: %s", part_label(part), hidden ? "hidden: " : "", family);
    Test *t = testlist_add(l, part, kind, name);
    t->hard = true;
    t->hidden = hidden;
    snprintf(t->note, sizeof t->note, "%s", "a hard case: see the handout's hard-case challenge");
    return t;
}

/* Finds the test of this family made by this call, or makes it. */
Test *tg_family_test(TestList *l, int first, int part, Kind kind, const char *family, bool hidden)
{
    for (int k = first; k < l->n; k++)
        if (l->tests[k].part == part && strstr(l->tests[k].name, family))
            return &l->tests[k];
    return tg_hard_test(l, part, kind, family, hidden);
}

void tg_add_plain_hits(TestList *l, int first)
{
    for (int k = first; k < l->n; k++) {
        Test *t = &l->tests[k];
        bool certain_hit = false;
        for (int c = 0; c < t->ncases; c++)
            certain_hit = certain_hit || (t->cases[c].want[0] == 1 && !(t->cases[c].flags & CASE_EITHER_HIT));
        if (certain_hit)
            continue;
        if (t->kind == KIND_SPHERE)
            tg_sphere(t, V(0, 0, -8), 2, V(0, 0, 0), V(0.06, 0.08, -1));
        else if (t->kind == KIND_PLANEHIT)
            tg_planehit(t, V(0, -1, 0), V(0, 1, 0), V(0, 0, 0), V(0.25, -0.5, -1));
        else if (t->kind == KIND_TRIANGLE)
            tg_triangle(t, V(-1, -1, -4), V(1, -1, -4), V(0, 1, -4), V(0, 0, 0), V(0.1, 0.05, -1));
    }
}

/* Parts 1 and 2's cases cost nothing to run: a round holds four of each
 * family, so that no family is passed by the luck of one case (a square
 * image for i and j swapped, a middle row for rows counted from the
 * bottom).  Parts 3a's and 3b's rounds hold two cases of each: a hit
 * and a miss, or the family's two scenes. */
#define SMALL_PER_ROUND 4

void tg_hard(TestList *l, uint64_t seed, int rounds, bool hidden)
{
    int first = l->n;
    int n1 = rounds * SMALL_PER_ROUND * HARD_PART1_FAMILIES;
    HardCase1 *c1 = calloc((size_t)n1, sizeof *c1);
    hard_part1(seed, c1, n1);
    for (int k = 0; k < n1; k++)
        tg_plane(tg_family_test(l, first, PART1, KIND_PLANE, c1[k].family, hidden),
                 c1[k].fov_degrees, c1[k].aspect, c1[k].d);
    free(c1);

    int n2 = rounds * SMALL_PER_ROUND * HARD_PART2_FAMILIES;
    HardCase2 *c2 = calloc((size_t)n2, sizeof *c2);
    hard_part2(seed, c2, n2);
    for (int k = 0; k < n2; k++)
        tg_pixel(tg_family_test(l, first, PART2, KIND_PIXEL, c2[k].family, hidden),
                 c2[k].i, c2[k].j, c2[k].nx, c2[k].ny, c2[k].w, c2[k].h, c2[k].d);
    free(c2);

    int n3 = 2 * rounds * HARD_PART3A_FAMILIES;
    HardCase3a *c3 = calloc((size_t)n3, sizeof *c3);
    hard_part3a(seed, c3, n3);
    for (int k = 0; k < n3; k++)
        tg_sphere(tg_family_test(l, first, PART3A, KIND_SPHERE, c3[k].family, hidden),
                  V3(c3[k].sphere.center), c3[k].sphere.radius,
                  V3(c3[k].ray.origin), V3(c3[k].ray.direction));
    free(c3);
    tg_add_plain_hits(l, first);

    /* Part 3b: the camera rays in one test; each colour case has its own
     * scene, so its own test.  Two scenes a round, the family's two
     * variants (hard.c: even and odd), so that a hidden round holds both. */
    int scenes = 2 * rounds;
    int n4 = 2 * rounds * HARD_PART3B_FAMILIES;
    HardCase3b *c4 = calloc((size_t)n4, sizeof *c4);
    hard_part3b(seed, c4, n4);
    /* By index: adding the colour tests may move the list. */
    int cam = l->n;
    tg_hard_test(l, PART3B, KIND_CAMERA, "camera rays through pixels of huge images", hidden);
    for (int k = 0; k < n4; k++) {
        double e[3] = { c4[k].eye.x, c4[k].eye.y, c4[k].eye.z };
        tg_camera(&l->tests[cam], e, V3(c4[k].pixel));
        /* Numbered, so that no two tests share a name. */
        char family[sizeof c4[k].family + 32];
        int scene = k / HARD_PART3B_FAMILIES;
        snprintf(family, sizeof family, "%s (scene %d of %d)", c4[k].family, scene + 1, scenes);
        Test *t = tg_hard_test(l, PART3B, KIND_COLOR, family, hidden);
        t->weight = 1.0 / scenes;
        memcpy(t->background, V3(c4[k].background), sizeof t->background);
        for (int s = 0; s < c4[k].nspheres; s++)
            test_add_sphere(t, V3(c4[k].spheres[s].center), c4[k].spheres[s].radius,
                            V3(c4[k].spheres[s].color));
        tg_color(t, e, V3(c4[k].ray.direction));
        /* and a ray at the last sphere's centre, so the background alone never passes */
        const Sphere *last = &c4[k].spheres[c4[k].nspheres - 1];
        double at[3] = { last->center.x - e[0], last->center.y - e[1], last->center.z - e[2] };
        tg_color(t, e, at);
    }
    free(c4);
}
