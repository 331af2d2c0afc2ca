/*
 * testgen_flat.c - the building blocks of the tests of Parts 4 and 5:
 * one case of a plane, of a triangle, of a ray at a closed mesh, with the
 * oracle's answer (flat.c) and the outputs of known mistakes, written here
 * in plain double as a student writes them; and the hard cases as tests.
 *
 * Tolerances: core tests accept any correct formula (relative 1e-9 for t,
 * or the oracle's bound when larger); hard tests the oracle's bound, a few
 * units of roundoff times the condition number of t.
 */
#include "testgen.h"
#include "oracle.h"
#include "hard.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static Vec3 v3(const double a[3])
{
    return vec3(a[0], a[1], a[2]);
}

/* The oracle's answer into c: want, tol, the flag for doubt and, for a ray
 * parallel within rounding, the smallest t accepted (alt[1]). */
static void expect(Test *t, Case *c, const OracleFlat *o)
{
    c->want[0] = o->hit ? 1 : 0;
    c->want[1] = o->hit || o->ambiguous ? o->t : 0;
    c->tol[1] = o->hit || o->ambiguous ? o->tol : 0;
    if (o->hit && !t->hard)
        c->tol[1] = fmax(c->tol[1], TG_CORE_REL * o->t);
    if (o->ambiguous) {
        c->flags |= CASE_EITHER_HIT;
        c->alt[1] = o->t_min;
    }
}

/* A mistake's answer (hit, t) as a hint, unless it is the right answer
 * anyway or a hint with the same text already has it.  Another mistake's
 * hint with the same output is kept: check.c names a mistake when it alone
 * explains every answer, so each mistake needs all its outputs. */
static void hint_hit(Case *c, const char *text, bool hit, double t)
{
    double out[2] = { hit ? 1 : 0, hit ? t : 0 };
    if (c->nhints == CASE_MAX_HINTS)
        return;
    bool same = true;
    for (int k = 0; k < 2; k++)
        same = same && fabs(out[k] - c->want[k]) <= 1e-6 * fabs(c->want[k]) + c->tol[k];
    for (int h = 0; h < c->nhints && !same; h++)
        same = strcmp(c->hints[h].text, text) == 0 && out[0] == c->hints[h].out[0]
               && out[1] == c->hints[h].out[1];
    if (same)
        return;
    Hint *h = case_add_hint(c);
    if (strlen(text) >= sizeof h->text) {      /* a hint cut short would mislead */
        fprintf(stderr, "testgen: a hint longer than %zu bytes: %s\n", sizeof h->text - 1, text);
        abort();
    }
    snprintf(h->text, sizeof h->text, "%s", text);
    memcpy(h->out, out, sizeof out);
}

/* ---- Part 4 ----------------------------------------------------------------- */
/* The hints of a case are every known mistake whose answer differs from the
 * right one; check.c names the mistake that explains all the cases of a
 * test when it is the only one (flat_mistake). */

/* A hit answer of a formula that checks t > 0 and nothing else. */
static bool positive(double t)
{
    return t > 0 && t < INFINITY;
}

static void plane_hints(Case *c, const Plane *pl, const Ray *ray)
{
    Vec3 p = pl->point, n = pl->normal, e = ray->origin, r = ray->direction;
    double rn = vec3_dot(r, n), t = vec3_dot(vec3_sub(p, e), n) / rn;
    double len_n = vec3_length(n), len_r = vec3_length(r);
    bool right = positive(t);

    if (rn != 0 && t >= 1e-300 && t < 1e-3)
        hint_hit(c, "hits at small t count: is there a tmin such as 0.001? In this lab tmin = 0", false, 0);
    if (rn != 0 && t == 0)
        hint_hit(c, "t = 0 is the ray's own origin: a hit needs t > 0, not t >= 0", true, 0);
    if (rn != 0 && t < 0)
        hint_hit(c, "a hit at or behind the ray's origin (t <= 0): only t > 0 is a hit", true, t);
    /* No check of r.n, and "t <= 0: miss": a quotient by r.n = 0 (+infinity,
     * or NaN for 0 / 0) and NaN input both get through.  No check of r.n,
     * and "!(t > 0): miss": only +infinity does (a ray parallel to the
     * plane, off it, on the side where (p - e).n / +0 is +infinity). */
    if (!(t <= 0) && !(t < INFINITY))
        hint_hit(c, "r.n = 0 (parallel to the plane, or in it) is a miss: check it before dividing; and "
                    "\"t <= 0: miss\" lets NaN through: write it as !(t > 0)", true, t);
    if (t == INFINITY)
        hint_hit(c, "a hit at t = inf is no point of the ray: r.n = 0 (a ray parallel to the plane) is a "
                    "miss: check it before dividing, or require t < inf", true, t);
    if (right && rn > 0)
        hint_hit(c, "the plane has two sides: a ray that meets it from behind (r.n > 0) hits too", false, 0);
    /* The other side alone: Scratchapixel's test, denom = n.r > 1e-6, takes
     * the normal to point along the ray, and misses the side it faces. */
    if (right && rn < 0)
        hint_hit(c, "the plane has two sides: a ray that meets it on the side its normal faces (r.n < 0) "
                    "hits too", false, 0);
    /* Scratchapixel's test, denom > 1e-6, made two-sided: short or grazing
     * rays and normals lost (the same for 1e-4 or 1e-8 where r.n is far
     * smaller than any of them, as in the hard case of tiny lengths). */
    if (right && fabs(rn) < 1e-6)
        hint_hit(c, "a hit was missed where r.n is small (short r or n, or a grazing ray): no epsilon on "
                    "r.n (such as 1e-6), compare it with 0", false, 0);
    double ts = vec3_dot(vec3_sub(e, p), n) / rn;
    hint_hit(c, "the sign: t = (p - e).n / (r.n), so that e + t r is on the plane", positive(ts), ts);
    double tw = vec3_dot(vec3_sub(n, e), p) / vec3_dot(r, p);
    hint_hit(c, "the point p and the normal n are swapped: t = (p - e).n / (r.n)", positive(tw), tw);
    if (right && len_n != 1)
        hint_hit(c, "t is off by the factor |n|: use the same n above and below the fraction line",
                 true, t / len_n);
    if (right && len_r != 1)
        hint_hit(c, "t is the ray parameter, not a distance: do not normalise r (t scales as 1 / |r|)",
                 true, t * len_r);
}

void tg_planehit(Test *t, const double p[3], const double n[3], const double e[3], const double r[3])
{
    Case *c = test_add_case(t);
    memcpy(c->in, p, 3 * sizeof *p);
    memcpy(c->in + 3, n, 3 * sizeof *n);
    memcpy(c->in + 6, e, 3 * sizeof *e);
    memcpy(c->in + 9, r, 3 * sizeof *r);
    Plane pl = { v3(p), v3(n), vec3(1, 1, 1) };
    Ray ray = { v3(e), v3(r) };
    OracleFlat o = oracle_plane(&pl, &ray);
    expect(t, c, &o);
    plane_hints(c, &pl, &ray);
}

/* ---- Part 5 ----------------------------------------------------------------- */

/* Moller-Trumbore as the skeleton's comment writes it, with the checks a
 * student may leave out or get wrong switched by flags. */
enum {
    MT_NO_SUM = 1,       /* beta + gamma <= 1 not checked       */
    MT_NO_T = 2,         /* t > 0 not checked                    */
    MT_NO_DET = 4,       /* det = 0 not checked; "t <= 0: miss" (NaN passes) */
    MT_CULL = 8,         /* det < 0 a miss (one-sided)           */
    MT_EPS = 16,         /* |det| < 1e-8 a miss                  */
    MT_STRICT = 32,      /* beta > 0, gamma > 0, beta + gamma < 1 */
    MT_TMIN = 64,        /* t > 0.001                            */
    MT_GAMMA_SIGN = 128, /* e1 x s for s x e1                    */
    MT_S_SIGN = 256,     /* s = a - e                            */
    MT_T_ZERO = 512,     /* t >= 0: t = 0 a hit                  */
    MT_STRICT_BEHIND = 1024, /* MT_STRICT where det < 0 alone        */
};

static bool mt(const Triangle *tr, const Ray *ray, unsigned flags, double *t)
{
    Vec3 e1 = vec3_sub(tr->b, tr->a), e2 = vec3_sub(tr->c, tr->a);
    Vec3 s = flags & MT_S_SIGN ? vec3_sub(tr->a, ray->origin) : vec3_sub(ray->origin, tr->a);
    Vec3 q = vec3_cross(ray->direction, e2);
    double det = vec3_dot(e1, q);
    if (!(flags & MT_NO_DET) && det == 0)
        return false;
    if ((flags & MT_CULL) && det < 0)
        return false;
    if ((flags & MT_EPS) && fabs(det) < 1e-8)
        return false;
    double inv = 1 / det;
    double beta = vec3_dot(s, q) * inv;
    Vec3 sx = flags & MT_GAMMA_SIGN ? vec3_cross(e1, s) : vec3_cross(s, e1);
    double gamma = vec3_dot(ray->direction, sx) * inv;
    *t = vec3_dot(e2, sx) * inv;
    if ((flags & MT_STRICT) || ((flags & MT_STRICT_BEHIND) && det < 0)) {
        if (!(beta > 0 && gamma > 0 && beta + gamma < 1))
            return false;
    } else if (beta < 0 || gamma < 0 || (!(flags & MT_NO_SUM) && beta + gamma > 1)) {
        return false;
    }
    if (flags & MT_NO_T)
        return true;
    if (flags & MT_NO_DET)
        return !(*t <= 0);
    if (flags & MT_TMIN)
        return *t > 1e-3 && *t < INFINITY;
    if (flags & MT_T_ZERO)
        return *t >= 0 && *t < INFINITY;
    return *t > 0 && *t < INFINITY;
}

static void triangle_hints(Case *c, const Triangle *tr, const Ray *ray, const OracleFlat *o)
{
    static const struct {
        unsigned flags;
        const char *text;
    } mistakes[] = {
        { MT_TMIN, "hits at small t count: is there a tmin such as 0.001? In this lab tmin = 0" },
        { MT_STRICT, "edges and vertices belong to the triangle: beta >= 0, gamma >= 0, beta + gamma <= 1" },
        { MT_EPS, "a hit was missed where det is small (a small or far triangle, or a grazing ray): no epsilon on det = -(e1 x e2).r (such as 1e-8): compare it with 0" },
        { MT_NO_T, "a hit at or behind the ray's origin (t <= 0): only t > 0 is a hit" },
        { MT_NO_SUM, "beta + gamma <= 1 is missing: the ray passed outside the edge bc and still hit" },
        { MT_NO_DET, "det = 0 (parallel to the triangle, or in its plane) is a miss: check it before dividing by it" },
        { MT_CULL, "both sides count: a ray that meets the triangle from behind (det < 0) hits too" },
        { MT_GAMMA_SIGN, "gamma = r.(s x e1) / det and t = e2.(s x e1) / det: the order of a cross product matters" },
        { MT_S_SIGN, "s = e - a (the ray's origin minus a), not a - e: it flips beta, gamma and t" },
        { MT_T_ZERO, "t = 0 is the ray's own origin: a hit needs t > 0, not t >= 0" },
        { MT_STRICT_BEHIND, "edges and vertices met from behind (det < 0) belong to the triangle too: where the signs flip, 0 is still inside (<= 0, not < 0)" },
    };
    for (size_t k = 0; k < sizeof mistakes / sizeof mistakes[0]; k++) {
        double t = 0;
        bool hit = mt(tr, ray, mistakes[k].flags, &t);
        /* A hint needs a different answer from a clear case: near an edge
         * rounding alone may flip the right formula's answer. */
        if (!o->ambiguous)
            hint_hit(c, mistakes[k].text, hit, t);
    }
    double len_r = vec3_length(ray->direction);
    if (o->hit && len_r != 1)
        hint_hit(c, "t is the ray parameter, not a distance: do not normalise r (t scales as 1 / |r|)",
                 true, o->t * len_r);
}

void tg_triangle(Test *t, const double a[3], const double b[3], const double cc[3],
                 const double e[3], const double r[3])
{
    Case *c = test_add_case(t);
    memcpy(c->in, a, 3 * sizeof *a);
    memcpy(c->in + 3, b, 3 * sizeof *b);
    memcpy(c->in + 6, cc, 3 * sizeof *cc);
    memcpy(c->in + 9, e, 3 * sizeof *e);
    memcpy(c->in + 12, r, 3 * sizeof *r);
    Triangle tr = { v3(a), v3(b), v3(cc), vec3(1, 1, 1) };
    Ray ray = { v3(e), v3(r) };
    OracleFlat o = oracle_triangle(&tr, &ray);
    expect(t, c, &o);
    triangle_hints(c, &tr, &ray, &o);
}

/* One case of a ray at the closed mesh of t's triangles. */
static void mesh_ray(Test *t, const Ray *ray)
{
    Case *c = test_add_case(t);
    memcpy(c->in, V3(ray->origin), 3 * sizeof c->in[0]);
    memcpy(c->in + 3, V3(ray->direction), 3 * sizeof c->in[0]);
    Triangle *tris = calloc((size_t)t->ntriangles + 1, sizeof *tris);
    for (int k = 0; k < t->ntriangles; k++) {
        const double *v = t->triangles[k].v;
        tris[k] = (Triangle){ v3(v), v3(v + 3), v3(v + 6), vec3(1, 1, 1) };
    }
    OracleFlat o = oracle_mesh(tris, t->ntriangles, ray);
    free(tris);
    expect(t, c, &o);
    /* A miss, or a first hit beyond the crossing (the far side of the
     * mesh): the ray went between the triangles that share an edge or a
     * vertex.  Both show as an answer that the checker reports with the
     * watertightness hint (check.c), whatever the t. */
}

/* ---- the hard cases as tests ------------------------------------------------ */

/* Part 4's test of one family of rounding, made core: the lecture's
 * formula in double meets every one of them (the handout's table), so
 * they are no challenge, but a test of its own care (no epsilon on r.n,
 * parallel rays, t in double).  The families together weigh 2 of the
 * part's core tests: they are not the part's main question. */
static Test *part4_rounding_test(TestList *l, int first, const char *family, bool hidden)
{
    int made = l->n;
    Test *t = tg_family_test(l, first, PART4, KIND_PLANEHIT, family, hidden);
    if (l->n == made)
        return t;
    snprintf(t->name, sizeof t->name, "Part 4: %srounding: %s", hidden ? "hidden: " : "", family);
    t->hard = false;
    t->weight = 2.0 / HARD_PART4_FAMILIES;
    snprintf(t->note, sizeof t->note, "%s",
             "where rounding is large: the lecture's formula in double, with no epsilon, meets it");
    return t;
}

void tg_hard_flat(TestList *l, uint64_t seed, int rounds, bool hidden)
{
    int first = l->n;
    int n4 = 2 * rounds * HARD_PART4_FAMILIES;
    HardCase4 *c4 = calloc((size_t)n4, sizeof *c4);
    hard_part4(seed, c4, n4);
    for (int k = 0; k < n4; k++)
        tg_planehit(part4_rounding_test(l, first, c4[k].family, hidden), V3(c4[k].plane.point),
                    V3(c4[k].plane.normal), V3(c4[k].ray.origin), V3(c4[k].ray.direction));
    free(c4);

    int n5 = 2 * rounds * HARD_PART5_FAMILIES;
    HardCase5 *c5 = calloc((size_t)n5, sizeof *c5);
    hard_part5(seed, c5, n5);
    for (int k = 0; k < n5; k++)
        tg_triangle(tg_family_test(l, first, PART5, KIND_TRIANGLE, c5[k].family, hidden), V3(c5[k].tri.a),
                    V3(c5[k].tri.b), V3(c5[k].tri.c), V3(c5[k].ray.origin), V3(c5[k].ray.direction));
    free(c5);
    tg_add_plain_hits(l, first);

    /* Closed meshes: one test per mesh family, its mesh's rays as cases
     * (a test holds one mesh, so each round's mesh is a test of its own,
     * weighted so that a family counts once). */
    int nm = rounds * HARD_MESH_FAMILIES;
    HardMesh *m = calloc((size_t)nm, sizeof *m);
    hard_meshes(seed, m, nm);
    for (int k = 0; k < nm; k++) {
        char family[HARD_FAMILY_LEN + 32];
        snprintf(family, sizeof family, "%s (%s)", m[k].family,
                 m[k].ntris == 12 ? "a cube" : m[k].ntris == 8 ? "an octahedron" : "an icosahedron");
        Test *t = tg_hard_test(l, PART5, KIND_MESH, family, hidden);
        t->weight = 1.0 / rounds;
        snprintf(t->note, sizeof t->note, "%s",
                 "a hard case: rays into a closed mesh through the edges and vertices its triangles share");
        for (int i = 0; i < m[k].ntris; i++) {
            const Triangle *tr = &m[k].tris[i];
            test_add_triangle(t, (const double[9]){ tr->a.x, tr->a.y, tr->a.z, tr->b.x, tr->b.y, tr->b.z,
                                                    tr->c.x, tr->c.y, tr->c.z });
        }
        for (int r = 0; r < HARD_MESH_RAYS; r++)
            mesh_ray(t, &m[k].rays[r]);
    }
    free(m);
}
