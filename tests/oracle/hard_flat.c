/*
 * hard_flat.c - the hard cases of Parts 4 and 5 (hard.h): planes,
 * triangles and closed meshes.  Every case draws from its own stream
 * (draw.h); the oracle (flat.c) gives the expected answers.
 */
#include <stdio.h>
#include <string.h>
#include "draw.h"
#include "hard.h"

/* ---- Part 4: planes ------------------------------------------------------- */

static const char *const fam4[HARD_PART4_FAMILIES] = {
    "ordinary planes",
    "grazing ray, 1e-12..1e-3 off the plane",
    "origin just off the plane, 1e-15..1e-6",
    "far from the world's origin, 1e3..1e9",
    "normal and direction lengths 2^-200..2^200",
    "parallel, in front of the plane (exact dyadic)",
    "parallel, behind the plane (exact dyadic)",
    "in the plane (exact dyadic)",
};

/* Families from this one on are the exact dyadic ones (parallel rays). */
#define FIRST_EXACT4 5

/* A dyadic number k / 16, |k| <= n. */
static double dyadic(uint64_t *s, int n)
{
    return draw_int(s, -n, n) / 16.0;
}

/* A point of three dyadic coordinates, drawn z, y, x (the order the stored
 * tests were drawn in). */
static Vec3 dyadic_point(uint64_t *s)
{
    double z = dyadic(s, 64), y = dyadic(s, 64), x = dyadic(s, 64);
    return vec3(x, y, z);
}

/* The unit vector along axis k, times v. */
static Vec3 axis(int k, double v)
{
    return vec3(k == 0 ? v : 0, k == 1 ? v : 0, k == 2 ? v : 0);
}

/* A ray from o at the point q of a plane (towards it on a hit, away from
 * it on a miss), of length len. */
static Vec3 at_point(Vec3 o, Vec3 q, bool want_hit, double len)
{
    Vec3 d = vec3_sub(q, o);
    d = vec3_scale(d, len / vec3_length(d));
    return want_hit ? d : vec3_negate(d);
}

static void gen4(uint64_t *s, int fam, bool want_hit, Plane *pl, Ray *ray)
{
    Vec3 p = draw_point(s, 5);
    double nlen = draw_len(s);
    Vec3 n = vec3_scale(draw_unit(s), nlen), o = draw_point(s, 5), d;
    Vec3 nh = vec3_normalize(n), w = draw_perp(s, n);
    if (fam == 0 || fam == 3 || fam == 4) {         /* ordinary, shifted, scaled */
        Vec3 q = vec3_add(p, vec3_scale(w, draw_uni(s, 0, 5)));
        double len = draw_len(s);
        if (fam == 4) {
            int binade = draw_int(s, -200, 200);
            n = vec3_scale(nh, ldexp(1 + hard_rng_uniform(s), binade));
            binade = draw_int(s, -200, 200);
            len = ldexp(1 + hard_rng_uniform(s), binade);
        }
        d = at_point(o, q, want_hit, len);
        if (fam == 3) {
            double far = draw_log(s, 1e3, 1e9);
            Vec3 off = vec3_scale(draw_unit(s), far);
            p = vec3_add(p, off);
            o = vec3_add(o, off);
        }
    } else if (fam == 1) {                          /* grazing */
        double sideways = draw_uni(s, 0, 5);
        o = vec3_add(vec3_add(p, vec3_scale(nh, draw_uni(s, 1, 10))), vec3_scale(w, sideways));
        double eps = draw_log(s, 1e-12, 1e-3);
        Vec3 along = draw_perp(s, n);
        d = vec3_scale(vec3_add(along, vec3_scale(nh, want_hit ? -eps : eps)), draw_len(s));
    } else if (fam == 2) {                          /* origin just off the plane */
        double L = draw_uni(s, 1, 100), h = L * draw_log(s, 1e-15, 1e-6);
        if (hard_rng_next(s) % 2)
            h = -h;
        o = vec3_add(vec3_add(p, vec3_scale(w, L)), vec3_scale(nh, h));
        double across = draw_uni(s, 0, 2);
        Vec3 side = vec3_scale(draw_perp(s, n), across);
        Vec3 towards = vec3_scale(nh, (h > 0) == want_hit ? -1 : 1);
        d = vec3_scale(vec3_add(towards, side), draw_len(s));
    } else {                                        /* exact dyadic: parallel, in the plane */
        /* n and r lie along axes k and j, so that r.n is an exact zero,
         * and +0 whatever the order of the sum (the third axis adds
         * +0 * +0). The height h of e above the plane, along n, is
         * positive (fam 5, in front), negative (6, behind) or zero (7):
         * dividing by r.n unchecked gives -inf, +inf and NaN, and every
         * round has each. */
        int k = draw_int(s, 0, 2), j = (k + draw_int(s, 1, 2)) % 3;
        int binade = draw_int(s, -4, 4);
        double nk = ldexp(hard_rng_next(s) % 2 ? 1 : -1, binade);
        n = axis(k, nk);
        p = dyadic_point(s);
        o = dyadic_point(s);
        double h = fam == 7 ? 0 : draw_int(s, 1, 64) / 16.0 * (fam == 5 ? 1 : -1);
        double *ok = k == 0 ? &o.x : k == 1 ? &o.y : &o.z;
        *ok = (k == 0 ? p.x : k == 1 ? p.y : p.z) + (nk > 0 ? h : -h);
        binade = draw_int(s, -4, 4);
        d = axis(j, ldexp(hard_rng_next(s) % 2 ? 1 : -1, binade));
        if (want_hit && h != 0)                     /* tilted towards the plane */
            d = vec3_add(d, axis(k, (nk > 0) == (h > 0) ? -0.5 : 0.5));
    }
    pl->point = p;
    pl->normal = n;
    pl->color = vec3(1, 1, 1);
    ray->origin = o;
    ray->direction = d;
}

/* The plane's normal turned (the same plane) so that the ray meets its
 * front (r.n < 0) or its back; r.n = 0 is left as it is. */
static void face(Plane *pl, const Ray *ray, bool front)
{
    double rn = vec3_dot(ray->direction, pl->normal);
    if (rn != 0 && (rn < 0) != front)
        pl->normal = vec3_negate(pl->normal);
}

int hard_part4(uint64_t seed, HardCase4 *cases, int max)
{
    for (int k = 0; k < max; k++) {
        uint64_t s = draw_stream(seed, 4, k);
        HardCase4 *c = &cases[k];
        int fam = k % HARD_PART4_FAMILIES, round_k = k / (2 * HARD_PART4_FAMILIES);
        bool want_hit = (k / HARD_PART4_FAMILIES) % 2 == 0;
        gen4(&s, fam, want_hit, &c->plane, &c->ray);
        /* Not drawn: in round r family f meets the front when f + r is
         * even, so that a one-sided test fails the same families in every
         * round whatever the seed.  The exact families keep the normal
         * their heights are measured along. */
        if (fam < FIRST_EXACT4)
            face(&c->plane, &c->ray, (fam + round_k) % 2 == 0);
        draw_family(c->family, fam4[fam]);
        c->expect = oracle_plane(&c->plane, &c->ray);
    }
    return max > 0 ? max : 0;
}

/* ---- Part 5: triangles ---------------------------------------------------- */

static const char *const fam5[HARD_PART5_FAMILIES] = {
    "ordinary triangles",
    "tiny triangle far away, size 1e-8..1e-4",
    "sliver triangle, width 1e-12..1e-4",
    "grazing ray, 1e-9..1e-3 off the plane",
    "ray near an edge, 2^-48..2^-30 of the size",
    "far from the world's origin, 1e3..1e6",
    "through a vertex or an edge (exact dyadic)",
};

/* A triangle about S across around c, not too thin. */
static Triangle random_triangle(uint64_t *s, Vec3 c, double S)
{
    for (;;) {
        Triangle tr;
        Vec3 *corner[3] = { &tr.a, &tr.b, &tr.c };
        for (int k = 0; k < 3; k++) {
            double far = S * draw_uni(s, 0.5, 1);
            *corner[k] = vec3_add(c, vec3_scale(draw_unit(s), far));
        }
        tr.color = vec3(1, 1, 1);
        Vec3 n = vec3_cross(vec3_sub(tr.b, tr.a), vec3_sub(tr.c, tr.a));
        if (vec3_length(n) > 0.2 * S * S)
            return tr;
    }
}

/* The point alpha a + beta b + gamma c. */
static Vec3 bary(const Triangle *tr, double alpha, double beta, double gamma)
{
    return vec3_add(vec3_add(vec3_scale(tr->a, alpha), vec3_scale(tr->b, beta)), vec3_scale(tr->c, gamma));
}

/* A point of the triangle's plane: inside (each weight >= 0.05) or
 * outside, beyond the edge opposite vertex `beyond` (0 a, 1 b, 2 c): that
 * weight -0.05 .. -0.45, the others 0.5 .. 1, so that each of those stays
 * under 1 and only their sum tells the miss. */
static Vec3 plane_point(uint64_t *s, const Triangle *tr, bool inside, int beyond)
{
    double w[3];
    for (;;) {
        for (int k = 0; k < 3; k++)
            w[k] = inside ? draw_uni(s, 0.05, 1) : draw_uni(s, 0.5, 1);
        if (!inside)
            w[beyond] = -draw_uni(s, 0.05, 0.45);
        double sum = w[0] + w[1] + w[2];
        if (sum > 0.1)
            return bary(tr, w[0] / sum, w[1] / sum, w[2] / sum);
    }
}

/* The exact dyadic family: a ray along an axis through a vertex, the
 * middle of an edge, or the line of an edge beyond the triangle; d.n is a
 * power of two, so every usual method computes the answer exactly. */
static void exact_triangle(uint64_t *s, bool want_hit, Triangle *tr, Ray *ray)
{
    int k = draw_int(s, 0, 2), i = (k + 1) % 3, j = (k + 2) % 3;
    if (hard_rng_next(s) % 2) {
        int swap = i;
        i = j;
        j = swap;
    }
    double sgn = hard_rng_next(s) % 2 ? 1 : -1;
    double o[3];
    for (int q = 0; q < 3; q++)
        o[q] = dyadic(s, 64);
    double depth = draw_int(s, 16, 128) / 16.0;
    int how = draw_int(s, 0, 2);          /* 0 vertex, 1 edge middle, 2 edge line outside */
    bool behind = !want_hit && how != 2;
    double a[3], b[3], c[3];
    a[k] = o[k] + sgn * (behind ? -depth : depth);
    a[i] = o[i];
    a[j] = o[j];
    int m1 = draw_int(s, -2, 3), m2 = draw_int(s, -2, 3);
    double e1 = ldexp(hard_rng_next(s) % 2 ? 1 : -1, m1), e2 = ldexp(hard_rng_next(s) % 2 ? 1 : -1, m2);
    if (how == 1)
        a[i] -= e1 / 2;                   /* the middle of ab is on the ray */
    else if (how == 2)
        a[i] += want_hit ? 0 : e1;        /* a miss: on the line of ab, beyond a */
    b[i] = a[i] + e1;
    b[j] = a[j];
    b[k] = a[k] + dyadic(s, 16);
    c[i] = a[i] + dyadic(s, 32);
    c[j] = a[j] + e2;
    c[k] = a[k] + dyadic(s, 16);
    tr->a = vec3(a[0], a[1], a[2]);
    tr->b = vec3(b[0], b[1], b[2]);
    tr->c = vec3(c[0], c[1], c[2]);
    tr->color = vec3(1, 1, 1);
    ray->origin = vec3(o[0], o[1], o[2]);
    ray->direction = axis(k, sgn * ldexp(1, draw_int(s, -3, 3)));
}

/* beyond: the vertex whose edge a miss lies beyond (plane_point), not
 * drawn: hard_part5. */
static void gen5(uint64_t *s, int fam, bool want_hit, int beyond, Triangle *tr, Ray *ray)
{
    Vec3 o = draw_point(s, 5), X;
    if (fam == 6) {
        exact_triangle(s, want_hit, tr, ray);
        return;
    }
    if (fam == 0 || fam == 5) {                     /* ordinary, far from the origin */
        double size = draw_uni(s, 0.5, 2);
        *tr = random_triangle(s, draw_point(s, 3), size);
        X = plane_point(s, tr, want_hit, beyond);
    } else if (fam == 1) {                          /* tiny, far */
        double S = draw_log(s, 1e-8, 1e-4);
        double far = draw_log(s, 1, 1e4);
        *tr = random_triangle(s, vec3_add(o, vec3_scale(draw_unit(s), far)), S);
        X = plane_point(s, tr, want_hit, beyond);
    } else if (fam == 2) {                          /* sliver */
        Vec3 c = draw_point(s, 3), u1 = draw_unit(s), u2 = draw_perp(s, u1);
        double S = draw_uni(s, 0.5, 2), width = S * draw_log(s, 1e-12, 1e-4);
        tr->a = vec3_add(c, vec3_scale(u1, S));
        tr->b = vec3_sub(c, vec3_scale(u1, S));
        tr->c = vec3_add(c, vec3_scale(u2, width));
        tr->color = vec3(1, 1, 1);
        double g = want_hit ? draw_uni(s, 0.1, 0.8) : -draw_uni(s, 0.1, 0.9);
        double al = draw_uni(s, 0.1, 0.9) * (1 - g);
        X = bary(tr, al, 1 - g - al, g);
    } else if (fam == 3) {                          /* grazing */
        double size = draw_uni(s, 1, 10);
        *tr = random_triangle(s, draw_point(s, 3), size);
        X = plane_point(s, tr, want_hit, beyond);
        Vec3 n = vec3_normalize(vec3_cross(vec3_sub(tr->b, tr->a), vec3_sub(tr->c, tr->a)));
        Vec3 w = draw_perp(s, n);
        double L = draw_uni(s, 1, 10) * vec3_length(vec3_sub(tr->b, tr->a));
        double eps = draw_log(s, 1e-9, 1e-3);
        if (hard_rng_next(s) % 2 == 0)
            eps = -eps;
        o = vec3_sub(X, vec3_scale(vec3_add(w, vec3_scale(n, eps)), L));
    } else {                                        /* near an edge */
        double spread = draw_uni(s, 0.5, 2);
        *tr = random_triangle(s, draw_point(s, 3), spread);
        int e = draw_int(s, 0, 2);
        if (!want_hit)
            e = (beyond + 1) % 3;                   /* the edge opposite that vertex */
        Vec3 P = e == 0 ? tr->a : e == 1 ? tr->b : tr->c;
        Vec3 Q = e == 0 ? tr->b : e == 1 ? tr->c : tr->a;
        Vec3 R = e == 0 ? tr->c : e == 1 ? tr->a : tr->b;
        Vec3 on = vec3_add(P, vec3_scale(vec3_sub(Q, P), draw_uni(s, 0.1, 0.9)));
        Vec3 pq = vec3_normalize(vec3_sub(Q, P)), in = vec3_sub(R, on);
        in = vec3_normalize(vec3_sub(in, vec3_scale(pq, vec3_dot(in, pq))));
        double size = vec3_length(vec3_sub(Q, P));
        int binade = -draw_int(s, 30, 48);
        double delta = size * ldexp(1 + hard_rng_uniform(s), binade);
        X = vec3_add(on, vec3_scale(in, want_hit ? delta : -delta));
        Vec3 n = vec3_normalize(vec3_cross(vec3_sub(tr->b, tr->a), vec3_sub(tr->c, tr->a)));
        double back = size * draw_uni(s, 1, 10), tilt = draw_uni(s, 0, 1);
        o = vec3_add(X, vec3_scale(vec3_add(n, vec3_scale(draw_perp(s, n), tilt)), back));
    }
    Vec3 d = vec3_sub(X, o);
    d = vec3_scale(d, draw_len(s) / vec3_length(d));
    if (fam == 5) {
        double far = draw_log(s, 1e3, 1e6);
        Vec3 off = vec3_scale(draw_unit(s), far);
        tr->a = vec3_add(tr->a, off);
        tr->b = vec3_add(tr->b, off);
        tr->c = vec3_add(tr->c, off);
        o = vec3_add(o, off);
    }
    ray->origin = o;
    ray->direction = d;
}

/* Which side of the triangle a round's ray meets it from is not drawn: in
 * round r, family f's ray meets the side that a, b, c wind counter-
 * clockwise around (d.n < 0, n = (b - a) x (c - a)) when f + r is even,
 * the other side when it is odd (b and c swapped, the same triangle).  So
 * every round's hits meet both sides, the same number of families each
 * whatever the seed, and a one-sided test fails as many of them in every
 * round. */
static void wind(Triangle *tr, const Ray *ray, bool front)
{
    double dn = vec3_dot(ray->direction, vec3_cross(vec3_sub(tr->b, tr->a), vec3_sub(tr->c, tr->a)));
    if ((dn < 0) != front) {
        Vec3 b = tr->b;
        tr->b = tr->c;
        tr->c = b;
    }
}

int hard_part5(uint64_t seed, HardCase5 *cases, int max)
{
    for (int k = 0; k < max; k++) {
        uint64_t s = draw_stream(seed, 5, k);
        HardCase5 *c = &cases[k];
        int fam = k % HARD_PART5_FAMILIES, round_k = k / (2 * HARD_PART5_FAMILIES);
        bool want_hit = (k / HARD_PART5_FAMILIES) % 2 == 0;
        /* A miss lies beyond each edge in turn: beyond bc, where only
         * beta + gamma <= 1 tells it, in the same families of a round
         * whatever the seed (wind keeps a, so keeps that edge). */
        gen5(&s, fam, want_hit, (fam + round_k) % 3, &c->tri, &c->ray);
        wind(&c->tri, &c->ray, (fam + round_k) % 2 == 0);
        draw_family(c->family, fam5[fam]);
        c->expect = oracle_triangle(&c->tri, &c->ray);
    }
    return max > 0 ? max : 0;
}

/* ---- closed meshes -------------------------------------------------------- */

static const char *const fam_mesh[HARD_MESH_FAMILIES] = {
    "closed mesh: rays through shared edges",
    "closed mesh: rays through shared vertices",
    "closed mesh at offsets 1e3..1e6",
};

/* The shapes, as vertices and faces (counter-clockwise seen from outside). */
#define GOLDEN 1.6180339887498949
static const double cube_v[8][3] = {
    { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 },
};
static const int cube_f[12][3] = {
    { 0, 2, 1 }, { 0, 3, 2 }, { 4, 5, 6 }, { 4, 6, 7 }, { 0, 1, 5 }, { 0, 5, 4 },
    { 3, 7, 6 }, { 3, 6, 2 }, { 0, 4, 7 }, { 0, 7, 3 }, { 1, 2, 6 }, { 1, 6, 5 },
};
static const double octa_v[6][3] = {
    { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
};
static const int octa_f[8][3] = {
    { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 },
    { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 },
};
static const double ico_v[12][3] = {
    { -1, GOLDEN, 0 }, { 1, GOLDEN, 0 }, { -1, -GOLDEN, 0 }, { 1, -GOLDEN, 0 },
    { 0, -1, GOLDEN }, { 0, 1, GOLDEN }, { 0, -1, -GOLDEN }, { 0, 1, -GOLDEN },
    { GOLDEN, 0, -1 }, { GOLDEN, 0, 1 }, { -GOLDEN, 0, -1 }, { -GOLDEN, 0, 1 },
};
static const int ico_f[20][3] = {
    { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
    { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 },
    { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 },
};

void hard_mesh_make(uint64_t *s, int shape, double size, Vec3 offset, HardMesh *m)
{
    const double (*v)[3] = shape == 0 ? cube_v : shape == 1 ? octa_v : ico_v;
    const int (*f)[3] = shape == 0 ? cube_f : shape == 1 ? octa_f : ico_f;
    int nv = shape == 0 ? 8 : shape == 1 ? 6 : 12, nf = shape == 0 ? 12 : shape == 1 ? 8 : 20;

    /* A random rotation, from a random unit quaternion (w, x, y, z). */
    double q[4], n2;
    do {
        n2 = 0;
        for (int k = 0; k < 4; k++) {
            q[k] = draw_uni(s, -1, 1);
            n2 += q[k] * q[k];
        }
    } while (n2 < 0.01 || n2 > 1);
    double inv = 1 / sqrt(n2), w = q[0] * inv, x = q[1] * inv, y = q[2] * inv, z = q[3] * inv;
    double R[3][3] = {
        { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
        { 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
        { 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) },
    };
    /* Each vertex is placed once, so triangles that share it share its
     * coordinates exactly. */
    Vec3 placed[12];
    for (int i = 0; i < nv; i++) {
        double p[3];
        for (int r = 0; r < 3; r++)
            p[r] = size * (R[r][0] * v[i][0] + R[r][1] * v[i][1] + R[r][2] * v[i][2]);
        placed[i] = vec3_add(offset, vec3(p[0], p[1], p[2]));
    }
    m->ntris = nf;
    for (int k = 0; k < nf; k++) {
        m->tris[k].a = placed[f[k][0]];
        m->tris[k].b = placed[f[k][1]];
        m->tris[k].c = placed[f[k][2]];
        m->tris[k].color = vec3(1, 1, 1);
    }
    m->centre = offset;
}

Ray hard_mesh_ray_at(uint64_t *s, const HardMesh *m, bool vertex, double *t_entry)
{
    const Triangle *tr = &m->tris[draw_int(s, 0, m->ntris - 1)];
    int e = draw_int(s, 0, 2);
    Vec3 P = e == 0 ? tr->a : e == 1 ? tr->b : tr->c;
    Vec3 Q = e == 0 ? tr->b : e == 1 ? tr->c : tr->a;
    Vec3 X = vertex ? P : vec3_add(P, vec3_scale(vec3_sub(Q, P), draw_uni(s, 0.05, 0.95)));
    /* From outside, beyond X as seen from the centre, a little to the side:
     * the ray enters at X and goes on into the interior. */
    Vec3 out = vec3_sub(X, m->centre);
    double dist = vec3_length(out);
    double across = dist * draw_uni(s, 0, 0.3);
    Vec3 side = vec3_scale(draw_perp(s, out), across);
    Vec3 o = vec3_add(vec3_add(X, vec3_scale(out, draw_uni(s, 0.5, 3))), side);
    Vec3 d = vec3_sub(X, o);
    double len = draw_len(s), dist_x = vec3_length(d);
    Ray ray = { o, vec3_scale(d, len / dist_x) };
    *t_entry = dist_x / len;
    return ray;
}

int hard_meshes(uint64_t seed, HardMesh *meshes, int max)
{
    for (int k = 0; k < max; k++) {
        uint64_t s = draw_stream(seed, 6, k);
        HardMesh *m = &meshes[k];
        int fam = k % HARD_MESH_FAMILIES;
        int shape = (int)((seed + (uint64_t)(k / HARD_MESH_FAMILIES)) % HARD_MESH_SHAPES);
        double far = fam == 2 ? draw_log(&s, 1e3, 1e6) : 0;
        Vec3 offset = fam == 2 ? vec3_scale(draw_unit(&s), far) : draw_point(&s, 10);
        double size = fam == 2 ? draw_log(&s, 0.5, 2) : draw_log(&s, 0.1, 10);
        hard_mesh_make(&s, shape, size, offset, m);
        draw_family(m->family, fam_mesh[fam]);
        for (int r = 0; r < HARD_MESH_RAYS; r++) {
            bool vertex = fam == 1 || (fam == 2 && r % 2);
            double t_entry;
            m->rays[r] = hard_mesh_ray_at(&s, m, vertex, &t_entry);
            m->expect[r] = oracle_mesh(m->tris, m->ntris, &m->rays[r]);
        }
    }
    return max > 0 ? max : 0;
}
