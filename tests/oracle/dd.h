/*
 * dd.h - double-double arithmetic: a number is the unevaluated sum hi + lo
 * of two doubles with |lo| <= ulp(hi) / 2, about 106 significant bits.
 *
 * Portable ISO C: the exact product of two doubles comes from fma(), the
 * exact sum from Knuth's two-sum, so the results are the same on every
 * IEEE-754 machine that rounds to nearest (x86-64, arm64, with or without
 * a wider long double).  Build with -ffp-contract=off and never with
 * -ffast-math: both would break the error-free transformations below.
 *
 * Accuracy (relative, for results that neither overflow nor underflow):
 *   dd_add, dd_sub        about 2^-105 (the "accurate" version: also when
 *                         the operands cancel)
 *   dd_mul, dd_sqr        about 2^-104
 *   dd_div, dd_sqrt       about 2^-104
 *   dd_mul_d, dd_div_d    about 2^-105
 * The error-free transformations dd_two_sum, dd_two_diff, dd_quick_two_sum
 * and dd_two_prod are exact.
 *
 * The elementary functions (constants pi and pi / 180, sin, cos, tan, and
 * tan of an angle in degrees) are in dd.c.
 *
 * Everything here is static inline: include the header and use it.
 */
#ifndef DD_H
#define DD_H

#include <limits.h>
#include <math.h>
#include <stdbool.h>

typedef struct {
    double hi, lo;       /* the value is hi + lo, |lo| <= ulp(hi) / 2 */
} dd;

/* ---- error-free transformations ------------------------------------------ */

/* a + b = s.hi + s.lo exactly, s.hi = fl(a + b) (Knuth; any a, b). */
static inline dd dd_two_sum(double a, double b)
{
    double s = a + b;
    double bb = s - a;
    double err = (a - (s - bb)) + (b - bb);
    dd r = { s, err };
    return r;
}

/* a - b exactly, as dd_two_sum(a, -b). */
static inline dd dd_two_diff(double a, double b)
{
    return dd_two_sum(a, -b);
}

/* a + b exactly, when |a| >= |b| or a == 0 (Dekker). */
static inline dd dd_quick_two_sum(double a, double b)
{
    double s = a + b;
    double err = b - (s - a);
    dd r = { s, err };
    return r;
}

/* a * b = p.hi + p.lo exactly (barring underflow of p.lo), p.hi = fl(a b). */
static inline dd dd_two_prod(double a, double b)
{
    double p = a * b;
    dd r = { p, fma(a, b, -p) };
    return r;
}

/* ---- conversions ------------------------------------------------------- */

static inline dd dd_make(double hi, double lo)
{
    return dd_quick_two_sum(hi, lo);
}

/* The double a, exactly. */
static inline dd dd_from(double a)
{
    dd r = { a, 0.0 };
    return r;
}

/* hi + lo rounded once to the nearest double (for a normalized dd that is hi). */
static inline double dd_to_double(dd a)
{
    return a.hi + a.lo;
}

/* The exponent e with max |v[k]| in [2^(e-1), 2^e), or 0 when all are 0:
 * inputs divided by 2^e (exact) lie near 1. */
static inline int dd_max_exponent(const double *v, int n)
{
    int emax = INT_MIN;
    for (int k = 0; k < n; k++) {
        if (v[k] != 0) {
            int e;
            frexp(v[k], &e);
            if (e > emax)
                emax = e;
        }
    }
    return emax == INT_MIN ? 0 : emax;
}

/* NaN among v[0..n-1]: 1; else infinity: 2; else 0. */
static inline int dd_bad_input(const double *v, int n)
{
    int bad = 0;
    for (int k = 0; k < n; k++) {
        if (isnan(v[k]))
            return 1;
        if (isinf(v[k]))
            bad = 2;
    }
    return bad;
}

/* ---- arithmetic ---------------------------------------------------------- */

static inline dd dd_neg(dd a)
{
    dd r = { -a.hi, -a.lo };
    return r;
}

/* a + b, accurate also under cancellation (two two-sums, then renormalize). */
static inline dd dd_add(dd a, dd b)
{
    dd s = dd_two_sum(a.hi, b.hi);
    dd t = dd_two_sum(a.lo, b.lo);
    s.lo += t.hi;
    s = dd_quick_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    return dd_quick_two_sum(s.hi, s.lo);
}

static inline dd dd_sub(dd a, dd b)
{
    return dd_add(a, dd_neg(b));
}

/* a + b for a double b. */
static inline dd dd_add_d(dd a, double b)
{
    dd s = dd_two_sum(a.hi, b);
    s.lo += a.lo;
    return dd_quick_two_sum(s.hi, s.lo);
}

/* a * b (the product of the lo parts, about 2^-106 relative, is dropped). */
static inline dd dd_mul(dd a, dd b)
{
    dd p = dd_two_prod(a.hi, b.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;
    return dd_quick_two_sum(p.hi, p.lo);
}

/* a * b for a double b. */
static inline dd dd_mul_d(dd a, double b)
{
    dd p = dd_two_prod(a.hi, b);
    p.lo += a.lo * b;
    return dd_quick_two_sum(p.hi, p.lo);
}

/* a * a */
static inline dd dd_sqr(dd a)
{
    dd p = dd_two_prod(a.hi, a.hi);
    p.lo += 2 * a.hi * a.lo;
    return dd_quick_two_sum(p.hi, p.lo);
}

/* a / b: three quotient digits by long division. */
static inline dd dd_div(dd a, dd b)
{
    double q1 = a.hi / b.hi;
    dd r = dd_sub(a, dd_mul_d(b, q1));
    double q2 = r.hi / b.hi;
    r = dd_sub(r, dd_mul_d(b, q2));
    double q3 = r.hi / b.hi;
    dd q = dd_quick_two_sum(q1, q2);
    return dd_add_d(q, q3);
}

/* a / b for a double b.  The remainder a - q1 b is computed exactly, so a
 * quotient that fits in a dd (a midpoint between two doubles, say) comes
 * out exactly. */
static inline dd dd_div_d(dd a, double b)
{
    double q1 = a.hi / b;
    dd p = dd_two_prod(q1, b);
    dd s = dd_two_diff(a.hi, p.hi);
    s.lo -= p.lo;
    s.lo += a.lo;
    double q2 = (s.hi + s.lo) / b;
    return dd_quick_two_sum(q1, q2);
}

/* sqrt(a) for a >= 0 (NaN for a < 0): the correctly rounded sqrt of a.hi
 * and one Newton correction with the exact residual a - y^2. */
static inline dd dd_sqrt(dd a)
{
    if (a.hi <= 0) {
        dd r = { a.hi == 0 ? 0.0 : NAN, 0.0 };
        return r;
    }
    double y = sqrt(a.hi);
    dd res = dd_sub(a, dd_two_prod(y, y));
    return dd_quick_two_sum(y, res.hi / (2 * y));
}

/* ---- comparisons (of normalized values) ----------------------------------- */

/* -1, 0 or +1 by the sign of a (0 for zero and NaN). */
static inline int dd_sign(dd a)
{
    if (a.hi != 0) return a.hi > 0 ? 1 : (a.hi < 0 ? -1 : 0);
    return a.lo > 0 ? 1 : (a.lo < 0 ? -1 : 0);
}

static inline bool dd_lt(dd a, dd b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }

/* ---- elementary functions (dd.c) ------------------------------------------ */

/* pi and pi / 180, each within 1e-33 relative. */
extern const dd dd_pi;
extern const dd dd_pi_180;

/* sin x and cos x together, for |x| <= pi / 4 (Taylor series; relative
 * error about 1e-31).  Larger |x| converge too, less accurately. */
void dd_sin_cos(dd x, dd *s, dd *c);

/* tan of an angle in DEGREES, for |deg| < 90, relative error about 1e-30.
 * The reduction is exact: above 45 degrees tan(deg) = 1 / tan(90 - deg)
 * and 90 - deg is a double without rounding, so angles close to 90 keep
 * every digit.  +-inf at +-90, NaN beyond. */
dd dd_tan_degrees(double deg);

#endif
