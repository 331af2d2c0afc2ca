/*
 * public_flat.c - the public tests of Parts 4 and 5, shipped to students as
 * tests/public/part4.tests and part5.tests.  As in public.c, every test
 * mixes certain hits with certain misses, so that no fixed answer passes
 * any of them; a test's cases are ordered so that the first one a known
 * mistake gets wrong is one whose hint names that mistake.
 */
#include "testgen.h"
#include "oracle.h"

#include <math.h>

#define O V(0, 0, 0)

static void part4(TestList *l)
{
    Test *t = tg_test(l, PART4, KIND_PLANEHIT, 1, "Part 4: the worked example (the ground y = -1)",
                      "(p - e).n = -2 and r.n = -1, so t = 2: the point (0, -1, -2)");
    tg_planehit(t, V(0, -1, 0), V(0, 2, 0), O, V(0, -0.5, -1));
    tg_planehit(t, V(0, -1, 0), V(0, 2, 0), O, V(0, 0.5, -1));
    tg_planehit(t, V(0, -1, 0), V(0, 2, 0), O, V(0.5, -1, -1));

    t = tg_test(l, PART4, KIND_PLANEHIT, 2, "Part 4: hits and misses",
                "t = (p - e).n / (r.n); a ray heading away from the plane misses it");
    tg_planehit(t, V(0, 0, -5), V(0, 0, 1), O, V(0.6, 0, -0.8));
    tg_planehit(t, V(3, 0, 0), V(1, 0, 0), O, V(1, 1, 1));
    tg_planehit(t, V(1, 2, -6), V(1, 1, 1), O, V(0, 0, -1));
    tg_planehit(t, V(0, 0, -5), V(0, 0, 1), O, V(0, 0, 1));
    tg_planehit(t, V(0, 2, 0), V(0, -1, 0), O, V(0, -1, 0));

    t = tg_test(l, PART4, KIND_PLANEHIT, 1, "Part 4: both sides of the plane count",
                "a ray that meets the plane from behind its normal (r.n > 0) hits it too");
    tg_planehit(t, V(0, 0, -5), V(0, 0, 1), O, V(0, 0, -1));
    tg_planehit(t, V(0, 0, -5), V(0, 0, -1), O, V(0, 0, -1));
    tg_planehit(t, V(0, -1, 0), V(0, -3, 0), O, V(0.5, -1, -2));
    tg_planehit(t, V(0, 0, 5), V(0, 0, -1), O, V(0, 0, -1));

    t = tg_test(l, PART4, KIND_PLANEHIT, 1, "Part 4: normals and directions that are not unit length",
                "t does not depend on |n|; it scales as 1 / |r|");
    tg_planehit(t, V(0, 0, -10), V(0, 0, 4), O, V(0, 0, -2));
    tg_planehit(t, V(0, 0, -10), V(0, 0, 0.25), O, V(0, 0, -0.5));
    tg_planehit(t, V(0, 0, -13), V(3, 4, 12), O, V(0.5, 1, -1.5));
    tg_planehit(t, V(0, 0, -13), V(3, 4, 12), O, V(-0.5, -1, 1.5));

    t = tg_test(l, PART4, KIND_PLANEHIT, 1, "Part 4: planes behind the ray are misses",
                "t < 0: the plane is behind the ray's origin");
    tg_planehit(t, V(0, 0, -8), V(0, 1, 1), O, V(0, 0, -1));
    tg_planehit(t, V(0, 0, 5), V(0, 0, 1), O, V(0, 0, -1));
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), O, V(0, 1, -1));
    tg_planehit(t, V(2, 2, 8), V(0.48, 0.6, 0.64), O, V(0.48, 0.6, -0.64));

    t = tg_test(l, PART4, KIND_PLANEHIT, 1, "Part 4: parallel rays, rays in the plane, zero and NaN input",
                "r.n = 0: no single point to hit (and no division by zero); NaN input is a miss");
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), O, V(0, -0.25, -1));
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), O, V(0, 0, -1));
    tg_planehit(t, V(0, 1, 0), V(0, 1, 0), O, V(0, 0, -1));   /* above: (p - e).n / r.n = +inf */
    tg_planehit(t, V(0, 0, 0), V(0, 1, 0), O, V(1, 0, 0));
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), O, V(0, 0, 0));
    tg_planehit(t, V(0, -1, 0), V(0, 0, 0), O, V(0, -1, -1));
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), O, V(NAN, -1, -1));

    t = tg_test(l, PART4, KIND_PLANEHIT, 1, "Part 4: rays that start anywhere, and hits close to the origin",
                "p - e uses the ray's own origin e; tmin = 0, so a hit at t = 1e-4 counts");
    tg_planehit(t, V(1, 2, -3), V(0, 0, 1), V(1, 2, 3), V(0, 0, -1));
    tg_planehit(t, V(0, 0, 0), V(1, 0, 0), V(5, -1, 0), V(-1, 0, 0));
    tg_planehit(t, V(0, 0, 0), V(1, 0, 0), V(5, -1, 0), V(1, 0, 0));
    tg_planehit(t, V(0, 0, -1e-4), V(0, 0, 1), O, V(0, 0, -1));
    tg_planehit(t, V(0, -1e-7, 0), V(0, 1, 0), O, V(0, -1, -1));

    t = tg_test(l, PART4, KIND_PLANEHIT, 1, "Part 4: a ray that starts on the plane",
                "t = 0 is the ray's own origin: only t > 0 is a hit ahead of it");
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), V(0, 1, 0), V(0, -1, 0));
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), V(0, -1, 0), V(0, -1, -1));
    tg_planehit(t, V(0, -1, 0), V(0, 1, 0), V(0, -1, 0), V(0, 1, -1));
}

/* The worked example's triangle. */
#define WA V(-1, -1, -4)
#define WB V(1, -1, -4)
#define WC V(0, 1, -4)

static void part5(TestList *l)
{
    Test *t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: the worked example",
                      "the plane z = -4 at t = 2, the point (0, 0, -4) = a + 0.25 (b - a) + 0.5 (c - a)");
    tg_triangle(t, WA, WB, WC, O, V(0, 0, -2));
    tg_triangle(t, WA, WB, WC, O, V(0.5, 0.5, -4));
    tg_triangle(t, WA, WB, WC, O, V(-0.5, -0.5, -4));

    t = tg_test(l, PART5, KIND_TRIANGLE, 2, "Part 5: inside and outside each edge",
                "beta >= 0, gamma >= 0 and beta + gamma <= 1: one condition per edge");
    tg_triangle(t, WA, WB, WC, O, V(0, 0.8, -4));
    tg_triangle(t, WA, WB, WC, O, V(0, -1.5, -4));
    tg_triangle(t, WA, WB, WC, O, V(-0.75, 0.25, -4));
    tg_triangle(t, WA, WB, WC, O, V(0.75, 0.25, -4));
    tg_triangle(t, V(1, 0, -3), V(-1, 2, -5), V(0, -2, -4), O, V(0, 0, -1));
    tg_triangle(t, V(1, 0, -3), V(-1, 2, -5), V(0, -2, -4), O, V(0.5, -0.5, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: both sides count",
                "a ray that meets the triangle from behind (det < 0) hits it too");
    tg_triangle(t, WA, WB, WC, O, V(0, 0, -1));
    tg_triangle(t, WA, WC, WB, O, V(0, 0, -1));
    tg_triangle(t, WA, WB, WC, V(0, 0, -8), V(0, 0, 1));
    tg_triangle(t, WA, WB, WC, V(0, 0, -8), V(0, 0, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: edges and vertices belong to the triangle",
                "rays exactly through a vertex or an edge hit; just beside it, they miss");
    static const double front[][3] = { { 0.5, 0.5, 0 }, { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 2, 0, 0 },
                                       { 2.0625, 0, 0 }, { 1, -0.0625, 0 } };
    for (int k = 0; k < 7; k++)
        tg_triangle(t, V(0, 0, -4), V(2, 0, -4), V(0, 2, -4), front[k], V(0, 0, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: edges and vertices met from behind",
                "the triangle wound the other way (det < 0): its edges and vertices belong to it too");
    static const double back[][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 2, 0 } };
    for (int k = 0; k < 4; k++)
        tg_triangle(t, V(0, 0, -4), V(0, 2, -4), V(2, 0, -4), back[k], V(0, 0, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: triangles behind the ray are misses",
                "t < 0: the triangle is behind the ray's origin");
    tg_triangle(t, WA, WB, WC, O, V(0.1, 0, -1));
    tg_triangle(t, WA, WB, WC, O, V(0, 0, 1));
    tg_triangle(t, V(-1, -1, 4), V(1, -1, 4), V(0, 1, 4), O, V(0, 0, -1));
    tg_triangle(t, WA, WB, WC, O, V(0, 0.375, 1));
    tg_triangle(t, WA, WB, WC, O, V(0.4375, 0.375, 1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: directions that are not unit length",
                "t scales as 1 / |r|: e + t r is the hit point");
    tg_triangle(t, WA, WB, WC, O, V(0, 0, -0.5));
    tg_triangle(t, WA, WB, WC, O, V(0, 0, -8));
    tg_triangle(t, WA, WB, WC, O, V(0.3, -0.6, -6));
    tg_triangle(t, WA, WB, WC, O, V(3, 0.3, -6));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: parallel rays, rays in the plane, zero and NaN input",
                "det = 0: no single point to hit (and no division by zero); NaN input is a miss");
    tg_triangle(t, V(-1, -1, -2), V(1, -1, -2), V(0, -1, -4), V(0, 0, -3), V(0, -1, 0));
    tg_triangle(t, V(-1, -1, -2), V(1, -1, -2), V(0, -1, -4), O, V(0, 0, -1));
    tg_triangle(t, V(-1, -1, -2), V(1, -1, -2), V(0, -1, -4), V(0, -1, 0), V(0, 0, -1));
    tg_triangle(t, WA, WB, WC, O, V(0, 0, 0));
    tg_triangle(t, WA, WB, WC, O, V(0, NAN, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: zero-area triangles are misses",
                "two equal vertices, or three on a line: no area to hit (det = 0)");
    tg_triangle(t, WA, WB, WC, O, V(0.25, -0.25, -2));
    tg_triangle(t, V(0, 0, -4), V(0, 0, -4), V(1, 1, -4), V(0.5, 0.5, 0), V(0, 0, -1));
    tg_triangle(t, V(-1, 0, -4), V(0, 0, -4), V(1, 0, -4), V(0.5, 0, 0), V(0, 0, -1));
    tg_triangle(t, V(1, 2, -3), V(1, 2, -3), V(1, 2, -3), V(1, 2, 0), V(0, 0, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: small, thin and far triangles",
                "det is about |r| times twice the area: tiny for a small triangle, but not 0");
    tg_triangle(t, V(-1e-5, -1e-5, -1), V(1e-5, -1e-5, -1), V(0, 1e-5, -1), O, V(0, 0, -1));
    tg_triangle(t, V(-1, 0, -2), V(1, 0, -2), V(0, 1e-9, -2), O, V(0, 3e-10, -2));
    tg_triangle(t, V(-1, 0, -2), V(1, 0, -2), V(0, 1e-9, -2), O, V(0, -3e-10, -2));
    tg_triangle(t, V(-1e4, -1e4, -4e4), V(1e4, -1e4, -4e4), V(0, 1e4, -4e4), O, V(0.01, 0.02, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: rays that start anywhere, and hits close to the origin",
                "s = e - a uses the ray's own origin e; tmin = 0, so a hit at t = 1e-4 counts");
    tg_triangle(t, WA, WB, WC, V(0, 0, 4), V(0, 0, -1));
    tg_triangle(t, V(2, 0, 0), V(2, 2, 1), V(2, -1, 2), V(5, 0.5, 1), V(-1, 0, 0));
    tg_triangle(t, V(2, 0, 0), V(2, 2, 1), V(2, -1, 2), V(5, 0.5, 1), V(1, 0, 0));
    tg_triangle(t, V(-1, -1, -1e-4), V(1, -1, -1e-4), V(0, 1, -1e-4), O, V(0, 0, -1));
    tg_triangle(t, V(-1, -1, -1e-7), V(1, -1, -1e-7), V(0, 1, -1e-7), O, V(0.25, 0, -1));

    t = tg_test(l, PART5, KIND_TRIANGLE, 1, "Part 5: a ray that starts on the triangle",
                "t = 0 is the ray's own origin: only t > 0 is a hit ahead of it");
    tg_triangle(t, WA, WB, WC, V(0, 0, -2), V(0, 0, -1));
    tg_triangle(t, WA, WB, WC, V(0, 0, -4), V(0, 0, -1));
    tg_triangle(t, WA, WB, WC, V(0.25, -0.5, -4), V(0, 0, 1));
}

void testgen_public_flat(TestList *list)
{
    part4(list);
    part5(list);
    tg_hard_flat(list, PUBLIC_HARD_SEED, 2, false);
}
