/*
 * oracle.c - the exact answers of oracle.h, in double-double (dd.h).
 *
 * Each answer is computed from the exact double inputs with about 106-bit
 * arithmetic and rounded to double once.  Inputs are first scaled by powers
 * of two (exact) so that the intermediate values are near 1: the dd
 * products neither overflow nor lose their low parts, for any input a
 * double can hold.
 */
#include <float.h>
#include <stdlib.h>
#include "oracle.h"
#include "dd.h"

#define U ORACLE_U

/* ---- Part 1 -------------------------------------------------------------- */

void oracle_image_plane(double fov_degrees, double aspect, double d, double *w, double *h)
{
    /* fov / 2 is exact (a power-of-two scaling) unless fov is subnormal. */
    dd hh = dd_mul_d(dd_mul_d(dd_tan_degrees(fov_degrees / 2), d), 2);
    *h = dd_to_double(hh);
    *w = dd_to_double(dd_mul_d(hh, aspect));
}

/* ---- Part 2 -------------------------------------------------------------- */

/* w k / (2 n), correctly rounded: w k is exact as a dd (k is an integer
 * below 2^53), and dd_div_d computes its remainder exactly, so the one
 * rounding at the end is the only one. */
static double scaled_fraction(double w, long long k, long long n)
{
    return dd_to_double(dd_div_d(dd_two_prod(w, (double)k), 2.0 * (double)n));
}

Vec3 oracle_pixel(int i, int j, int nx, int ny, double w, double h, double d)
{
    long long kx = 2LL * i + 1 - nx;
    long long ky = (long long)ny - 1 - 2LL * j;
    return vec3(scaled_fraction(w, kx, nx), scaled_fraction(h, ky, ny), -d);
}

/* ---- Part 3a ------------------------------------------------------------- */

/*
 * The condition number of t.
 *
 * t solves g(t) = |f + t r|^2 - R^2 = 0 (f = e - c).  Perturb the inputs as
 * a backward-stable double method does: f by at most u |f| (the one
 * rounding of e - c, then the method's own), r by u |r|, R by u R.  With
 * p = f + t r the hit point (|p| = R) and g'(t) = 2 r.p = +-2 |r| s, where
 * s = sqrt(R^2 - l.l) is the exact half-chord (a length) and l the offset
 * from the centre to the line's closest point,
 *     dg = 2 p.df + 2 t p.dr - 2 R dR,  |dg| <= 2 u R (|f| + t |r| + R),
 *     |dt| = |dg| / |g'(t)| <= u R (|f| + R + L) / (|r| s),   L = t |r|,
 * so, adding 1 for the final rounding of t,
 *     kappa = 1 + R (|f| + R + L) / (L s).
 *
 * numerics.md's criterion 1 + R/s + (f.f + R^2) / |f.f - R^2| has the right
 * size for the NEAR root (there L (L + 2s) = |f.f - R^2|, and both grow like
 * R / h at height h above the surface, like R / s at grazing incidence, and
 * stay about 3 for a far sphere), but not for the FAR root: from an origin
 * at height h above (or depth h below) the surface, looking through the
 * sphere, its last term is about R / (2h) while the far root's true
 * condition is about (1 + cos a) / cos^2 a (a the angle from the normal).
 * The far root is computed without C (as q, without cancellation), so a
 * good method gets it to a few u; the old criterion would let a far root
 * off by 10^8 u pass at h = 1e-9 R.  The formula above is right for both.
 *
 * Near tangency (s -> 0) the first-order bound breaks down: a method's
 * s^2 is off by about u R (|f| + R), so its s by up to sqrt of that.  s is
 * therefore floored at sigma = sqrt(u R (|f| + R)); only hits within the
 * silhouette's ambiguity band have s that small.
 *
 * Written as an absolute tolerance, K u kappa t = K u (t + R (|f| + R + L) /
 * (|r| s)), which stays finite as t -> 0: that is how an answer near t = 0
 * (the origin on the surface) is judged.
 */

/*
 * An exact tangent that no usual method can get wrong.  The silhouette band
 * makes every ray within rounding of tangency ambiguous; but when the ray
 * is exactly tangent and every quantity the lecture's formula, the closest-
 * point form (Ray Tracing Gems, pbrt) and a normalize-first variant compute
 * is a double without rounding (f, A, B, C, B^2, A C, b = B/A, l, l.l, R^2,
 * |r| and r/|r|, each dot product in any order), they all find
 * disc = 0 exactly: the hit is certain, not ambiguous.  Small-integer
 * examples such as c = (2, 0, -10), R = 2, r = (0, 0, -1) are of this kind.
 */
#define EXACT_MIN 0x1p-960          /* below this a rounding may hide */

static bool exact_mul(double x, double y, double *out)
{
    double p = x * y;
    *out = p;
    if (p == 0)
        return x == 0 || y == 0;
    return fabs(p) >= EXACT_MIN && fabs(p) <= DBL_MAX && fma(x, y, -p) == 0;
}

static bool exact_add(double x, double y, double *out)
{
    dd s = dd_two_sum(x, y);
    *out = s.hi;
    return s.lo == 0 && isfinite(s.hi);
}

static bool exact_div(double x, double y, double *out)
{
    double q = x / y;
    *out = q;
    if (q == 0)
        return x == 0 && y != 0;
    return fabs(q) >= EXACT_MIN && fabs(q) <= DBL_MAX && fma(q, y, -x) == 0;
}

/* a.b without rounding, whatever the order of the additions. */
static bool exact_dot(const double *a, const double *b, double *out)
{
    double p[3], s;
    for (int k = 0; k < 3; k++)
        if (!exact_mul(a[k], b[k], &p[k]))
            return false;
    return exact_add(p[0], p[1], &s) && exact_add(p[1], p[2], &s) && exact_add(p[0], p[2], &s)
        && exact_add(p[0] + p[1], p[2], out);
}

/*
 * An origin exactly on the surface that no usual method can get wrong: f,
 * f.f, R^2 and C = f.f - R^2 = 0 are doubles without rounding, and so are
 * B^2, f.f - B^2 (the geometric form's d^2), the closest-point form's
 * b = B/A, l = f - b r, l.l, |l| and (R - |l|)(R + |l|) (pbrt's), and the
 * same for the normalize-first variant's r/|r|: every method finds one
 * root exactly t = 0, which is not ahead of the ray (t > 0), and the other
 * is the answer.  Axis directions through the centre, such as e = (0, 0, 0),
 * c = (0, 0, -1), R = 1, r = (0, 0, -1), are of this kind; an origin on the
 * surface where |l| is irrational (sqrt 13) is not, and stays ambiguous.
 */
static bool exact_for(const double f[3], double R, const double r[3], bool surface)
{
    double A, B, ff, R2, C, BB, AC, d2, b, br, l[3], ll, nl, lo, hi, disc;
    if (!exact_dot(r, r, &A) || !exact_dot(f, r, &B) || !exact_dot(f, f, &ff) || !exact_mul(R, R, &R2)
        || !exact_add(ff, -R2, &C) || !exact_mul(B, B, &BB) || !exact_div(B, A, &b))
        return false;
    if (surface ? C != 0 || !exact_add(ff, -BB, &d2) : !exact_mul(A, C, &AC) || BB != AC)
        return false;
    for (int k = 0; k < 3; k++)
        if (!exact_mul(b, r[k], &br) || !exact_add(f[k], -br, &l[k]))
            return false;
    if (!exact_dot(l, l, &ll))
        return false;
    if (!surface)
        return ll == R2;
    nl = sqrt(ll);
    return fma(nl, nl, -ll) == 0 && exact_add(R, -nl, &lo) && exact_add(R, nl, &hi) && exact_mul(lo, hi, &disc);
}

/* An exact tangent (surface false) or an origin exactly on the surface
 * (true), as above: exact_for holds for f = e - c (itself exact), for the
 * ray's r and for the normalize-first variant's r/|r| (|r| and r/|r| exact
 * too). */
static bool exact_both_ways(const Sphere *sp, const Ray *ray, bool surface)
{
    double e[3] = { ray->origin.x, ray->origin.y, ray->origin.z };
    double c[3] = { sp->center.x, sp->center.y, sp->center.z };
    double r[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    double f[3], A, n, unit[3];
    for (int k = 0; k < 3; k++)
        if (!exact_add(e[k], -c[k], &f[k]))
            return false;
    if (!exact_for(f, sp->radius, r, surface) || !exact_dot(r, r, &A))
        return false;
    n = sqrt(A);
    if (fma(n, n, -A) != 0)
        return false;
    for (int k = 0; k < 3; k++)
        if (!exact_div(r[k], n, &unit[k]))
            return false;
    return exact_for(f, sp->radius, unit, surface);
}

/* Everything oracle_sphere knows about one sphere and ray. */
typedef struct {
    bool hit;          /* a root t > 0                                         */
    bool ambiguous;    /* silhouette, surface, overflow or infinite input     */
    bool silhouette;   /* the line passes within rounding of the silhouette   */
    bool surface;      /* the origin is within rounding of the surface        */
    bool overflow;     /* the smallest root t > 0 is beyond DBL_MAX           */
    bool real_roots;   /* the line meets the sphere (disc >= 0)               */
    double t;          /* on a hit, the smallest root t > 0, rounded once     */
    double root[2];    /* with real_roots: both roots, ascending, rounded     */
    double t_closest;  /* the line's closest point to the centre              */
    /* Geometry in scaled units (lengths times 2^-ep, r times 2^-er), used
     * for kappa; t = t_scaled * 2^scale. */
    double nf, radius, nr, s_eff;
    int scale;
} SphereSolution;

/* What a sphere's and a ray's numbers alone decide (pos: the origin, the
 * centre and |R|; dir: the direction): -1 a miss, 1 either answer, 0
 * neither (solve it). */
static int input_verdict(const double pos[7], const double dir[3])
{
    int bad = dd_bad_input(pos, 7) | dd_bad_input(dir, 3);
    if (bad & 1)                        /* NaN input: a miss, no doubt */
        return -1;
    if (bad)                            /* infinite: outside the contract, anything goes */
        return 1;
    if (dir[0] == 0 && dir[1] == 0 && dir[2] == 0)
        return -1;                      /* zero direction: a miss */
    return 0;
}

static void solve_sphere(const Sphere *sp, const Ray *ray, SphereSolution *S)
{
    SphereSolution zero = { 0 };
    *S = zero;

    double pos[7] = { ray->origin.x, ray->origin.y, ray->origin.z,
                      sp->center.x, sp->center.y, sp->center.z, fabs(sp->radius) };
    double dir[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    int verdict = input_verdict(pos, dir);
    if (verdict != 0) {
        S->ambiguous = verdict > 0;
        return;
    }

    /* Scale positions so the largest is in [1/2, 1), the direction so its
     * largest component is: exact (barring components 2^1000 times smaller
     * than the largest, which contribute nothing at this precision). */
    int ep = dd_max_exponent(pos, 7), er = dd_max_exponent(dir, 3);
    dd f[3];
    double r[3];
    for (int k = 0; k < 3; k++) {
        f[k] = dd_two_diff(ldexp(pos[k], -ep), ldexp(pos[k + 3], -ep));   /* exact */
        r[k] = ldexp(dir[k], -er);
    }
    double R = ldexp(pos[6], -ep);
    S->scale = ep - er;

    dd A = dd_add(dd_add(dd_two_prod(r[0], r[0]), dd_two_prod(r[1], r[1])), dd_two_prod(r[2], r[2]));
    dd B = dd_add(dd_add(dd_mul_d(f[0], r[0]), dd_mul_d(f[1], r[1])), dd_mul_d(f[2], r[2]));
    dd ff = dd_add(dd_add(dd_sqr(f[0]), dd_sqr(f[1])), dd_sqr(f[2]));
    dd R2 = dd_two_prod(R, R);
    dd C = dd_sub(ff, R2);
    dd b = dd_div(B, A);                /* the closest point is at t = -b */
    dd ll = dd_from(0);
    for (int k = 0; k < 3; k++)
        ll = dd_add(ll, dd_sqr(dd_sub(f[k], dd_mul_d(b, r[k]))));
    dd disc = dd_sub(R2, ll);           /* s^2 = R^2 - l.l, a length squared */

    S->nf = sqrt(ff.hi);
    S->nr = sqrt(A.hi);
    S->radius = R;
    double t_closest = -dd_to_double(b);
    S->t_closest = ldexp(t_closest, S->scale);

    /* Ambiguity: |l| - R = -disc / (|l| + R), accurate near the silhouette. */
    double lnorm = sqrt(ll.hi);
    double gap = lnorm + R > 0 ? -dd_to_double(disc) / (lnorm + R) : 0;
    S->silhouette = fabs(gap) <= ORACLE_K_SILHOUETTE * U * (S->nf + R) && t_closest > 0
                    && !exact_both_ways(sp, ray, false);
    S->surface = fabs(dd_to_double(C)) <= ORACLE_K_SURFACE * U * (ff.hi + R2.hi)
                 && !exact_both_ways(sp, ray, true);

    double s = 0;
    dd t_hit = dd_from(0);
    if (dd_sign(disc) >= 0) {
        S->real_roots = true;
        s = sqrt(disc.hi);
        /* Roots -b -+ h, h = sqrt(disc / A).  q = -(b + sign(b) h) has no
         * cancellation; the other root is (C / A) / q (their product). */
        dd hpar = dd_sqrt(dd_div(disc, A));
        dd q = dd_sign(b) >= 0 ? dd_neg(dd_add(b, hpar)) : dd_sub(hpar, b);
        dd t1 = q, t2 = q;              /* q == 0: a double root at 0 */
        if (dd_sign(q) != 0)
            t2 = dd_div(dd_div(C, A), q);
        dd lo = dd_lt(t1, t2) ? t1 : t2, hi = dd_lt(t1, t2) ? t2 : t1;
        S->root[0] = ldexp(dd_to_double(lo), S->scale);
        S->root[1] = ldexp(dd_to_double(hi), S->scale);
        if (dd_sign(lo) > 0) {
            S->hit = true;
            t_hit = lo;
        } else if (dd_sign(hi) > 0) {
            S->hit = true;
            t_hit = hi;
        }
    }
    S->s_eff = fmax(s, sqrt(U * R * (S->nf + R)));
    if (S->hit) {
        S->t = ldexp(dd_to_double(t_hit), S->scale);
        if (isinf(S->t)) {              /* no double holds the answer */
            S->hit = false;
            S->overflow = true;
        }
    }
    S->ambiguous = S->silhouette || S->surface || S->overflow;
}

/* kappa at t (unscaled), as derived above. */
static double sphere_kappa(const SphereSolution *S, double t)
{
    double ts = ldexp(t, -S->scale), L = ts * S->nr;
    if (S->radius == 0)                 /* a point: no silhouette to graze */
        return 1;
    return 1 + S->radius * (S->nf + S->radius + L) / (L * S->s_eff);
}

/* ORACLE_K_T u kappa t at t (unscaled), finite also at t = 0. */
static double sphere_tolerance(const SphereSolution *S, double t)
{
    double ts = ldexp(t, -S->scale), L = ts * S->nr;
    if (S->radius == 0)
        return ldexp(ORACLE_K_T * U * ts, S->scale);
    double tol = ORACLE_K_T * U * (ts + S->radius * (S->nf + S->radius + L) / (S->nr * S->s_eff));
    return ldexp(tol, S->scale);
}

OracleHit oracle_sphere(const Sphere *sphere, const Ray *ray)
{
    SphereSolution S;
    solve_sphere(sphere, ray, &S);
    OracleHit res = { .hit = S.hit, .t = 0, .ambiguous = S.ambiguous, .kappa = 1 };
    if (S.hit) {
        res.t = S.t;
        res.kappa = sphere_kappa(&S, S.t);
    } else if (S.overflow) {
        res.t = INFINITY;
    } else if (S.ambiguous && S.t_closest > 0) {
        res.t = S.t_closest;
        res.kappa = sphere_kappa(&S, S.t_closest);
    } else if (S.ambiguous) {
        res.kappa = INFINITY;           /* t = 0: the origin on the surface */
    }
    return res;
}

double oracle_sphere_t_tolerance(const Sphere *sphere, const Ray *ray, const OracleHit *hit)
{
    SphereSolution S;
    solve_sphere(sphere, ray, &S);
    if (!isfinite(hit->t) || S.nr == 0)
        return INFINITY;
    return sphere_tolerance(&S, hit->t);
}

/* The t values an ambiguous case allows besides the oracle's own, in this
 * order: either root >= 0, 0 from an origin within rounding of the
 * surface, the closest point at the silhouette.  Returns how many. */
static int other_candidates(const SphereSolution *S, double cand[4])
{
    int n = 0;
    if (S->real_roots)
        for (int k = 0; k < 2; k++)
            if (S->root[k] >= 0)
                cand[n++] = S->root[k];
    if (S->surface)
        cand[n++] = 0;
    if (S->silhouette && S->t_closest > 0)
        cand[n++] = S->t_closest;
    return n;
}

static bool near_root(const SphereSolution *S, double root, double t)
{
    return fabs(t - root) <= sphere_tolerance(S, root);
}

bool oracle_sphere_accepts(const Sphere *sphere, const Ray *ray, bool hit, double t)
{
    SphereSolution S;
    solve_sphere(sphere, ray, &S);
    if (!hit)
        return !S.hit || S.ambiguous;
    if (!(t > 0 && t <= DBL_MAX))       /* a hit's t is finite and positive */
        return false;
    if (S.hit && near_root(&S, S.t, t))
        return true;
    if (!S.ambiguous || S.nr == 0)
        return false;
    if (S.overflow)
        return near_root(&S, DBL_MAX, t);
    double cand[4];
    int n = other_candidates(&S, cand);
    for (int k = 0; k < n; k++)
        if (near_root(&S, cand[k], t))
            return true;
    return false;
}

/* Grows [*lo, *hi] by every window [clo[k], chi[k]] not yet used that
 * reaches it, until none does, marking those used. */
static void grow_window(int n, const double clo[], const double chi[], bool used[], double *lo, double *hi)
{
    for (bool grew = true; grew;) {
        grew = false;
        for (int k = 0; k < n; k++)
            if (!used[k] && clo[k] <= *hi && chi[k] >= *lo) {
                *lo = fmin(*lo, clo[k]);
                *hi = fmax(*hi, chi[k]);
                used[k] = grew = true;
            }
    }
}

bool oracle_sphere_other_hits(const Sphere *sphere, const Ray *ray, const OracleHit *hit,
                              double tol, double *near_tol, double *lo, double *hi)
{
    SphereSolution S;
    solve_sphere(sphere, ray, &S);
    *near_tol = tol;
    *lo = INFINITY;
    *hi = -INFINITY;
    if (!S.ambiguous || S.nr == 0 || S.overflow || !isfinite(hit->t))
        return false;
    double clo[4] = { 0 }, chi[4] = { 0 }, cand[4];
    int n = other_candidates(&S, cand);
    for (int k = 0; k < n; k++) {
        double ct = sphere_tolerance(&S, cand[k]);
        clo[k] = cand[k] - ct;
        chi[k] = cand[k] + ct;
    }
    /* Grow hit->t's window by every window that reaches it, until none
     * does; what is left apart, the nearest first, gives [lo, hi]. */
    double wlo = hit->t - tol, whi = hit->t + tol;
    bool used[4] = { false };
    grow_window(n, clo, chi, used, &wlo, &whi);
    *near_tol = fmax(hit->t - wlo, whi - hit->t);
    int best = -1;
    for (int k = 0; k < n; k++)
        if (!used[k] && (best < 0 || fabs(cand[k] - hit->t) < fabs(cand[best] - hit->t)))
            best = k;
    if (best < 0)
        return false;
    *lo = clo[best];
    *hi = chi[best];
    grow_window(n, clo, chi, used, lo, hi);       /* and the windows that reach that one */
    return true;
}

/* ---- Part 3b ------------------------------------------------------------- */

Vec3 oracle_unit(Vec3 v)
{
    double c[3] = { v.x, v.y, v.z };
    if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2]))
        return vec3(NAN, NAN, NAN);
    if (c[0] == 0 && c[1] == 0 && c[2] == 0)
        return v;                       /* zero stays zero, as vec3_normalize */
    int e = dd_max_exponent(c, 3);
    for (int k = 0; k < 3; k++)
        c[k] = ldexp(c[k], -e);
    dd n2 = dd_add(dd_add(dd_two_prod(c[0], c[0]), dd_two_prod(c[1], c[1])), dd_two_prod(c[2], c[2]));
    dd n = dd_sqrt(n2);
    return vec3(dd_to_double(dd_div(dd_from(c[0]), n)),
                dd_to_double(dd_div(dd_from(c[1]), n)),
                dd_to_double(dd_div(dd_from(c[2]), n)));
}

/* The interval of t values a correct method may report for a sphere: the
 * oracle's hit, and for an ambiguous one every other candidate too. */
static void hit_interval(const SphereSolution *S, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    double cand[5];
    int n = 0;
    if (S->hit)
        cand[n++] = S->t;
    if (S->ambiguous)
        n += other_candidates(S, cand + n);
    for (int k = 0; k < n; k++) {
        double tol = sphere_tolerance(S, cand[k]);
        *lo = fmin(*lo, cand[k] - tol);
        *hi = fmax(*hi, cand[k] + tol);
    }
}

/*
 * The closest sphere.  Ambiguous when
 *   - the best sphere's own answer is ambiguous (it may be missed: the
 *     alternative is then the next hit, or the background), or
 *   - another sphere's possible t values reach below the best one's
 *     largest possible t (two hits that agree to rounding, or a sphere
 *     grazed within rounding of its silhouette in front of the best):
 *     the alternative is the one whose possible t starts lowest.
 * Each sphere is solved once, and its solution kept for the second look:
 * in kept[] for a scene of up to CLOSEST_KEPT spheres, else in a malloc'd
 * array (solved again where there is no memory for one).
 */
#define CLOSEST_KEPT 16

/* Sphere k's solution: sol[k], or, with no array, solved into *scratch. */
static const SphereSolution *closest_solution(const Scene *scene, const Ray *ray,
                                              const SphereSolution *sol, int k,
                                              SphereSolution *scratch)
{
    if (sol)
        return &sol[k];
    solve_sphere(&scene->spheres[k], ray, scratch);
    return scratch;
}

int oracle_closest(const Scene *scene, const Ray *ray, bool *ambiguous, int *alternative)
{
    SphereSolution kept[CLOSEST_KEPT], scratch;
    int n = scene->nspheres;
    SphereSolution *sol = n <= CLOSEST_KEPT ? kept : malloc((size_t)n * sizeof *sol);
    int best = -1, next = -1;
    double tbest = INFINITY, tnext = INFINITY;
    for (int k = 0; k < n; k++) {
        SphereSolution *S = sol ? &sol[k] : &scratch;
        solve_sphere(&scene->spheres[k], ray, S);
        if (!S->hit)
            continue;
        if (S->t < tbest) {
            next = best;
            tnext = tbest;
            best = k;
            tbest = S->t;
        } else if (S->t < tnext) {
            next = k;
            tnext = S->t;
        }
    }

    bool amb = false;
    int alt = -1;
    double best_hi = INFINITY;
    if (best >= 0) {
        const SphereSolution *S = closest_solution(scene, ray, sol, best, &scratch);
        double lo;
        hit_interval(S, &lo, &best_hi);
        if (S->ambiguous) {
            amb = true;
            alt = next;
        }
    }
    double lowest = INFINITY;
    for (int k = 0; k < n; k++) {
        if (k == best)
            continue;
        const SphereSolution *S = closest_solution(scene, ray, sol, k, &scratch);
        if (!S->hit && !S->ambiguous)
            continue;
        double lo, hi;
        hit_interval(S, &lo, &hi);
        if (lo <= best_hi && lo < lowest) {
            amb = true;
            alt = k;
            lowest = lo;
        }
    }
    if (sol != kept)
        free(sol);
    if (ambiguous)
        *ambiguous = amb;
    if (alternative)
        *alternative = amb ? alt : -1;
    return best;
}
