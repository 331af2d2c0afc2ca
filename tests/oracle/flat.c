/*
 * flat.c - the oracle of Parts 4 and 5: planes and triangles (oracle.h).
 *
 * Every decision is the exact sign of a polynomial in the double inputs,
 * computed with expansions (expansion.h), so hit or miss is the answer of
 * exact arithmetic; t is the exact quotient rounded once (its numerator and
 * denominator are exact expansions, divided in double-double).
 *
 * With o the ray's origin, d its direction, and A = a - o, B = b - o,
 * C = c - o the vertices seen from o:
 *   - the line meets the plane of the triangle at t = A.(B x C) / (d.n),
 *     n = (b - a) x (c - a), and d.n = s_a + s_b + s_c with
 *         s_a = d.(B x C),  s_b = d.(C x A),  s_c = d.(A x B),
 *     the signed volumes of the ray with each edge (bc, ca, ab): s_a is the
 *     barycentric coordinate of a times d.n, and so on;
 *   - the line goes through the closed triangle when s_a, s_b, s_c are all
 *     >= 0 or all <= 0 and d.n != 0 (d.n = 0: parallel, in the plane, a
 *     zero direction or a zero-area triangle);
 *   - a plane (x - p).n = 0 is met at t = (p - o).n / (d.n).
 *
 * Ambiguity.  A correct double method rounds its inputs' differences and
 * products, which is like moving every input coordinate by a few units of
 * roundoff.  A quantity q of the above then moves by up to about u S(q),
 * S(q) = sum over the inputs x of |dq/dx| |x| (its sensitivity to relative
 * changes of the inputs, computed in double: a scale, not an answer).  So
 *   - the ray grazes an edge (hit or miss in doubt) when |s| <= K u S(s) for
 *     an edge value s whose sign could turn the answer;
 *   - it is parallel within rounding when |d.n| <= K u S(d.n);
 *   - its origin is on the plane within rounding when |num| <= K u S(num);
 * and then either answer is accepted.  K is ORACLE_K_FLAT_BAND, measured in
 * tests/unit/test_flat.c against several correct methods.  Where every
 * input is a small dyadic number and the direction (and a plane's normal)
 * lies along an axis, every usual method computes those quantities without
 * rounding, even after normalising (and, for a triangle whose d.n is a
 * power of two, after dividing by it): nothing is then in doubt (a ray
 * through a vertex hits; a ray along a plane misses).
 *
 * The tolerance for t: t = num / den, so its relative error is about
 * u (S(num) / |num| + S(den) / |den|), plus one rounding; ORACLE_K_T times
 * that, written as an absolute tolerance that stays finite as t -> 0.
 */
#include <float.h>
#include "oracle.h"
#include "expansion.h"

#define U ORACLE_U

/* A small dyadic number: a multiple of 1/16 below 256 in size.  Sums and
 * products of three such numbers, and their differences, are exact. */
static bool small_dyadic(double x)
{
    return fabs(x) < 256 && 16 * x == floor(16 * x);
}

/* At most one nonzero component: normalising it is exact. */
static bool along_axis(const double v[3])
{
    return (v[0] != 0) + (v[1] != 0) + (v[2] != 0) <= 1;
}

static bool all_small_dyadic(const double *v, int n)
{
    for (int k = 0; k < n; k++)
        if (!small_dyadic(v[k]))
            return false;
    return true;
}

static void cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* sum |g_k| |x_k|: one input's share of a sensitivity. */
static double share(const double g[3], const double x[3])
{
    return fabs(g[0] * x[0]) + fabs(g[1] * x[1]) + fabs(g[2] * x[2]);
}

static void sub3(const double a[3], const double b[3], double out[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] - b[k];
}

/* The answer, once the exact signs and the scales are known. */
typedef struct {
    int bad;                   /* NaN input: 1; else infinite input: 2 (dd.h) */
    bool lost;                 /* inexact arithmetic                          */
    bool exact_den, exact_num; /* d.n and num computed without rounding by every
                                  usual method, even after normalising         */
    bool exact_edges;          /* the same for the edge values and barycentric
                                  coordinates                                  */
    int sden, snum;            /* exact signs of den and num                  */
    double den, num;           /* their values (scaled units)                  */
    double sens_den, sens_num; /* their sensitivities (scaled units)           */
    int scale;                 /* t = (num / den) * 2^scale                    */
    double t;                  /* num / den, rounded, unscaled (when den != 0) */
    bool inside;               /* the line goes through the closed triangle    */
    bool edge_doubt;           /* ... but within rounding of an edge           */
} Flat;

/* The exact den and num into F: their signs, their values, and (when
 * den != 0) t = num / den in double-double, rounded once. */
static void set_quotient(Flat *F, const Expansion *den, const Expansion *num)
{
    F->lost |= !exp_ok(den) || !exp_ok(num);
    F->sden = exp_sign(den);
    F->snum = exp_sign(num);
    F->den = dd_to_double(exp_to_dd(den));
    F->num = dd_to_double(exp_to_dd(num));
    if (F->sden != 0)
        F->t = dd_to_double(dd_div(exp_to_dd(num), exp_to_dd(den)));
}

static OracleFlat answer(const Flat *F)
{
    OracleFlat o = { .hit = false, .ambiguous = false, .t = 0, .tol = 0, .t_min = 0, .kappa = 1 };
    if (F->bad & 1)
        return o;                                   /* NaN: a miss, no doubt */
    if (F->bad || F->lost) {
        o.ambiguous = true;                         /* outside what we can judge */
        o.t_min = 0;
        o.tol = INFINITY;
        return o;
    }
    double band = ORACLE_K_FLAT_BAND * U;
    bool parallel = fabs(F->den) <= band * F->sens_den && !F->exact_den;
    bool surface = fabs(F->num) <= band * F->sens_num && !F->exact_num;
    o.ambiguous = parallel || surface || F->edge_doubt;
    /* Parallel: a method that does not round d.n to 0 finds t of at least
     * |num| / (K u S(den)) (half that, to be safe). */
    double t_min = ldexp(fabs(F->num) / (2 * band * F->sens_den), F->scale);
    if (F->sden == 0) {
        o.t_min = t_min;
        return o;
    }
    double t = F->t;
    o.kappa = 1 + F->sens_num / fabs(F->num) + F->sens_den / fabs(F->den);
    o.tol = ldexp(ORACLE_K_T * U * (fabs(t) * (1 + F->sens_den / fabs(F->den))
                                    + F->sens_num / fabs(F->den)), F->scale);
    o.t = ldexp(t, F->scale);
    bool ahead = F->snum * F->sden > 0;
    o.hit = ahead && F->inside && o.t <= DBL_MAX;
    if (ahead && F->inside && !(o.t <= DBL_MAX)) {
        o.ambiguous = true;                         /* no double holds t */
        o.t = DBL_MAX;
    }
    o.t_min = parallel ? t_min : INFINITY;
    return o;
}

/* ---- planes --------------------------------------------------------------- */

OracleFlat oracle_plane(const Plane *plane, const Ray *ray)
{
    double pos[6] = { plane->point.x, plane->point.y, plane->point.z,
                      ray->origin.x, ray->origin.y, ray->origin.z };
    double nrm[3] = { plane->normal.x, plane->normal.y, plane->normal.z };
    double dir[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    Flat F = { .bad = dd_bad_input(pos, 6) | dd_bad_input(nrm, 3) | dd_bad_input(dir, 3) };
    if (F.bad)
        return answer(&F);
    /* Small dyadic inputs: every product and sum is exact, and a normalised
     * n or d is exact along an axis; d.n = 0 then stays 0 when d or n lies
     * along an axis, (p - o).n = 0 when n does or p = o. */
    bool dyadic = all_small_dyadic(pos, 6) && all_small_dyadic(nrm, 3) && all_small_dyadic(dir, 3);
    bool same = pos[0] == pos[3] && pos[1] == pos[4] && pos[2] == pos[5];
    F.exact_den = dyadic && (along_axis(nrm) || along_axis(dir));
    F.exact_num = dyadic && (along_axis(nrm) || same);

    /* Scale by powers of two (exact): positions, normal and direction each
     * to a largest component in [1/2, 1). */
    int ep = dd_max_exponent(pos, 6), en = dd_max_exponent(nrm, 3), ed = dd_max_exponent(dir, 3);
    double p[3], o[3], n[3], d[3];
    for (int k = 0; k < 3; k++) {
        p[k] = ldexp(pos[k], -ep);
        o[k] = ldexp(pos[k + 3], -ep);
        n[k] = ldexp(nrm[k], -en);
        d[k] = ldexp(dir[k], -ed);
    }
    F.scale = ep - ed;

    ExpVec po, nv;
    Expansion den, num;
    expv_diff(&po, p, o);
    for (int k = 0; k < 3; k++)
        exp_from(&nv.c[k], d[k]);
    expv_dot_d(&den, n, &nv);                       /* d.n */
    expv_dot_d(&num, n, &po);                       /* (p - o).n */
    set_quotient(&F, &den, &num);

    /* S(d.n) = sum |n_k d_k| twice (as d and as n); S(num) from p, o, n. */
    double pmo[3];
    sub3(p, o, pmo);
    F.sens_den = 2 * share(n, d);
    F.sens_num = share(n, p) + share(n, o) + share(pmo, n);
    F.inside = true;
    return answer(&F);
}

/* ---- triangles ------------------------------------------------------------ */

/* S(s) for the edge value s = d.(P x Q), P = p - o, Q = q - o. */
static double edge_sensitivity(const double p[3], const double q[3], const double o[3],
                               const double d[3])
{
    double P[3], Q[3], QP[3], g[3];
    sub3(p, o, P);
    sub3(q, o, Q);
    sub3(q, p, QP);
    double s = 0;
    cross(Q, d, g);                 /* ds/dp = Q x d */
    s += share(g, p);
    cross(d, P, g);                 /* ds/dq = d x P */
    s += share(g, q);
    cross(d, QP, g);                /* ds/do = d x (Q - P) */
    s += share(g, o);
    cross(P, Q, g);                 /* ds/dd = P x Q */
    s += share(g, d);
    return s;
}

OracleFlat oracle_triangle(const Triangle *tri, const Ray *ray)
{
    double pos[12] = { tri->a.x, tri->a.y, tri->a.z, tri->b.x, tri->b.y, tri->b.z,
                       tri->c.x, tri->c.y, tri->c.z, ray->origin.x, ray->origin.y, ray->origin.z };
    double dir[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    Flat F = { .bad = dd_bad_input(pos, 12) | dd_bad_input(dir, 3) };
    if (F.bad)
        return answer(&F);
    bool exact = all_small_dyadic(pos, 12) && all_small_dyadic(dir, 3) && along_axis(dir);

    int ep = dd_max_exponent(pos, 12), ed = dd_max_exponent(dir, 3);
    double v[3][3], o[3], d[3];
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < 3; i++)
            v[i][k] = ldexp(pos[3 * i + k], -ep);
        o[k] = ldexp(pos[9 + k], -ep);
        d[k] = ldexp(dir[k], -ed);
    }
    F.scale = ep - ed;

    /* The exact edge values s[i] (the edge opposite vertex i), their sum
     * d.n, and num = A.(B x C). */
    static _Thread_local ExpVec rel[3], cr[3];
    static _Thread_local Expansion s[3], den, num;
    for (int i = 0; i < 3; i++)
        expv_diff(&rel[i], v[i], o);
    for (int i = 0; i < 3; i++)
        expv_cross(&cr[i], &rel[(i + 1) % 3], &rel[(i + 2) % 3]);
    for (int i = 0; i < 3; i++) {
        expv_dot_d(&s[i], d, &cr[i]);
        F.lost |= !exp_ok(&s[i]);
    }
    exp_add(&den, &s[0], &s[1]);
    exp_add(&den, &den, &s[2]);
    expv_dot(&num, &rel[0], &cr[0]);
    set_quotient(&F, &den, &num);
    /* Barycentric coordinates are the edge values divided by d.n: exact
     * for every method only when d.n is a power of two (or 0). */
    int e2x;
    F.exact_edges = exact && (F.den == 0 || frexp(F.den, &e2x) == 0.5 || frexp(F.den, &e2x) == -0.5);
    F.exact_den = F.exact_num = F.exact_edges;

    /* Sensitivities: of each edge value, of d.n (their sum: the sum of
     * theirs bounds it) and of num = det[A, B, C]. */
    double sens[3], g[3], P[3][3];
    for (int i = 0; i < 3; i++) {
        sens[i] = edge_sensitivity(v[(i + 1) % 3], v[(i + 2) % 3], o, d);
        sub3(v[i], o, P[i]);
    }
    F.sens_den = sens[0] + sens[1] + sens[2];
    F.sens_num = 0;
    for (int i = 0; i < 3; i++) {
        cross(P[(i + 1) % 3], P[(i + 2) % 3], g);   /* d num / d v_i */
        F.sens_num += share(g, v[i]);
    }
    double n[3], e1[3], e2[3];
    sub3(v[1], v[0], e1);
    sub3(v[2], v[0], e2);
    cross(e1, e2, n);                               /* d num / d o = -n */
    F.sens_num += share(n, o);

    /* Inside or not, exactly; and in doubt when an edge value within its
     * band could take either sign (or 0) and so change the answer. */
    int sign[3], doubt[3];
    double band = ORACLE_K_FLAT_BAND * U;
    for (int i = 0; i < 3; i++) {
        sign[i] = exp_sign(&s[i]);
        double si = dd_to_double(exp_to_dd(&s[i]));
        doubt[i] = fabs(si) <= band * sens[i] && !F.exact_edges;
    }
    bool pos_any = false, neg_any = false;
    for (int i = 0; i < 3; i++) {
        pos_any |= sign[i] > 0;
        neg_any |= sign[i] < 0;
    }
    F.inside = !(pos_any && neg_any) && F.sden != 0;
    /* Try every sign of the doubtful values: could the answer differ? */
    bool can_in = false, can_out = false;
    for (int m = 0; m < 27; m++) {
        int trial[3], code = m;
        for (int i = 0; i < 3; i++, code /= 3)
            trial[i] = doubt[i] ? code % 3 - 1 : sign[i];
        bool p_any = trial[0] > 0 || trial[1] > 0 || trial[2] > 0;
        bool n_any = trial[0] < 0 || trial[1] < 0 || trial[2] < 0;
        bool in = !(p_any && n_any) && (p_any || n_any);
        can_in |= in;
        can_out |= !in;
    }
    F.edge_doubt = can_in && can_out;
    return answer(&F);
}

/* ---- judging an answer ---------------------------------------------------- */

bool oracle_flat_accepts(const OracleFlat *o, bool hit, double t)
{
    if (!hit)
        return !o->hit || o->ambiguous;
    if (!(t > 0 && t <= DBL_MAX))           /* a hit's t is finite and positive */
        return false;
    if (o->hit && fabs(t - o->t) <= o->tol)
        return true;
    if (!o->ambiguous)
        return false;
    if (fabs(t - o->t) <= o->tol)           /* grazing an edge, or t near 0 */
        return true;
    return t >= o->t_min;                   /* parallel within rounding: a far hit */
}

/* ---- closed meshes -------------------------------------------------------- */

OracleFlat oracle_mesh(const Triangle *tris, int n, const Ray *ray)
{
    OracleFlat best = { .hit = false, .ambiguous = false, .t = 0, .tol = 0,
                        .t_min = INFINITY, .kappa = 1 };
    static _Thread_local OracleFlat each[4096];
    if (n > 4096)
        n = 4096;
    for (int k = 0; k < n; k++) {
        each[k] = oracle_triangle(&tris[k], ray);
        if (each[k].hit && (!best.hit || each[k].t < best.t))
            best = each[k];
    }
    if (!best.hit)
        return best;
    double tol = best.tol, kappa = best.kappa;
    for (int k = 0; k < n; k++)
        if (each[k].hit && fabs(each[k].t - best.t) <= each[k].tol + best.tol) {
            tol = fmax(tol, each[k].tol);
            kappa = fmax(kappa, each[k].kappa);
        }
    best.tol = tol;
    best.kappa = kappa;
    best.ambiguous = false;
    best.t_min = INFINITY;
    return best;
}
