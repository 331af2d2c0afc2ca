/*
 * expansion.c - the exact arithmetic of expansion.h.
 *
 * Two error-free transformations do all the work: two-sum (Knuth, dd.h), whose
 * a + b = x + y holds exactly for any doubles, and two-product with fma,
 * a b = x + y exactly unless x under- or overflows.  A sum of expansions
 * merges their components by size and runs one two-sum over them
 * (Shewchuk's Fast-Expansion-Sum, with two-sum in every step); a product
 * by a double is Shewchuk's Scale-Expansion.  Zero components are dropped
 * as they appear, which keeps the expansions short.
 */
#include "expansion.h"

#include <math.h>
#include <string.h>

#define EXP_TINY 0x1p-960          /* a product below this may lose its error term */

/* x + y = a b exactly, x = fl(a b); false when that may not hold. */
static bool two_prod(double a, double b, double *x, double *y)
{
    double p = a * b;
    *x = p;
    *y = fma(a, b, -p);
    if (!isfinite(p))
        return false;
    if (p == 0)
        return a == 0 || b == 0;
    return fabs(p) >= EXP_TINY;
}

/* Appends a nonzero component; false when there is no room. */
static bool push(Expansion *h, double v)
{
    if (v == 0)
        return true;
    if (h->n == EXP_MAX)
        return false;
    h->e[h->n++] = v;
    return true;
}

/* h = x, copying only the components x holds (an expansion has room for
 * EXP_MAX, 4 KiB, and most hold a few). */
static void copy(Expansion *h, const Expansion *x)
{
    h->n = x->n;
    h->lost = x->lost;
    memmove(h->e, x->e, (size_t)x->n * sizeof x->e[0]);
}

void exp_from(Expansion *x, double a)
{
    x->n = 0;
    x->lost = !isfinite(a);
    push(x, a);
}

void exp_diff(Expansion *x, double a, double b)
{
    dd s = dd_two_diff(a, b);
    x->n = 0;
    x->lost = !isfinite(s.hi);
    push(x, s.lo);
    push(x, s.hi);
}

void exp_add(Expansion *h, const Expansion *e, const Expansion *f)
{
    /* Merge by magnitude into g, then sum from the smallest up: q is the
     * running total, each step's rounding error is an exact component. */
    static _Thread_local double g[2 * EXP_MAX];
    int i = 0, j = 0, n = 0;
    while (i < e->n || j < f->n) {
        if (j == f->n || (i < e->n && fabs(e->e[i]) <= fabs(f->e[j])))
            g[n++] = e->e[i++];
        else
            g[n++] = f->e[j++];
    }
    Expansion out;
    out.n = 0;
    out.lost = e->lost || f->lost;
    if (n > 0) {
        double q = g[0];
        for (int k = 1; k < n; k++) {
            dd s = dd_two_sum(q, g[k]);
            out.lost |= !push(&out, s.lo);
            q = s.hi;
        }
        out.lost |= !push(&out, q) || !isfinite(q);
    }
    copy(h, &out);
}

void exp_sub(Expansion *h, const Expansion *e, const Expansion *f)
{
    Expansion neg;
    neg.n = f->n;
    neg.lost = f->lost;
    for (int k = 0; k < neg.n; k++)
        neg.e[k] = -f->e[k];
    exp_add(h, e, &neg);
}

void exp_scale(Expansion *h, const Expansion *e, double b)
{
    Expansion out;
    out.n = 0;
    out.lost = e->lost || !isfinite(b);
    if (e->n > 0 && b != 0) {
        double q, low;
        out.lost |= !two_prod(e->e[0], b, &q, &low);
        out.lost |= !push(&out, low);
        for (int k = 1; k < e->n; k++) {
            double p1, p0;
            out.lost |= !two_prod(e->e[k], b, &p1, &p0);
            dd s = dd_two_sum(q, p0);
            out.lost |= !push(&out, s.lo);
            s = dd_two_sum(p1, s.hi);      /* |p1| >= |s|: a fast two-sum would do */
            q = s.hi;
            out.lost |= !push(&out, s.lo);
        }
        out.lost |= !push(&out, q) || !isfinite(q);
    }
    copy(h, &out);
}

void exp_mul(Expansion *h, const Expansion *e, const Expansion *f)
{
    Expansion acc, term;
    acc.n = 0;
    acc.lost = e->lost || f->lost;
    for (int k = 0; k < f->n; k++) {
        exp_scale(&term, e, f->e[k]);
        exp_add(&acc, &acc, &term);
    }
    copy(h, &acc);
}

int exp_sign(const Expansion *x)
{
    if (x->n == 0)
        return 0;
    return x->e[x->n - 1] > 0 ? 1 : -1;
}

bool exp_ok(const Expansion *x)
{
    return !x->lost;
}

dd exp_to_dd(const Expansion *x)
{
    dd s = dd_from(0);
    for (int k = 0; k < x->n; k++)
        s = dd_add(s, dd_from(x->e[k]));
    return s;
}

void expv_diff(ExpVec *v, const double a[3], const double b[3])
{
    for (int k = 0; k < 3; k++)
        exp_diff(&v->c[k], a[k], b[k]);
}

void expv_cross(ExpVec *h, const ExpVec *a, const ExpVec *b)
{
    static _Thread_local ExpVec out;
    static _Thread_local Expansion p, q;
    for (int k = 0; k < 3; k++) {
        int i = (k + 1) % 3, j = (k + 2) % 3;
        exp_mul(&p, &a->c[i], &b->c[j]);
        exp_mul(&q, &a->c[j], &b->c[i]);
        exp_sub(&out.c[k], &p, &q);
    }
    for (int k = 0; k < 3; k++)
        copy(&h->c[k], &out.c[k]);
}

void expv_dot(Expansion *h, const ExpVec *a, const ExpVec *b)
{
    static _Thread_local Expansion acc, p;
    acc.n = 0;
    acc.lost = false;
    for (int k = 0; k < 3; k++) {
        exp_mul(&p, &a->c[k], &b->c[k]);
        exp_add(&acc, &acc, &p);
    }
    copy(h, &acc);
}

void expv_dot_d(Expansion *h, const double a[3], const ExpVec *b)
{
    static _Thread_local Expansion acc, p;
    acc.n = 0;
    acc.lost = false;
    for (int k = 0; k < 3; k++) {
        exp_scale(&p, &b->c[k], a[k]);
        exp_add(&acc, &acc, &p);
    }
    copy(h, &acc);
}
