/*
 * expansion.h - exact sums and products of doubles, as expansions: a
 * number is the exact, unevaluated sum of several doubles (Shewchuk,
 * "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
 * Predicates", 1997).  Used by the oracle for Parts 4 and 5, whose answers
 * hinge on the exact sign of triple products: there double-double is not
 * enough (a triple product of differences of doubles needs up to about
 * 3 x 53 + 3 bits), and an expansion holds it exactly.
 *
 * The components are kept nonoverlapping, in increasing order of size,
 * without zeros: the sign of the number is the sign of its last component,
 * and the number is 0 exactly when it has none.  Results are exact as long
 * as nothing overflows and no product falls below EXP_TINY (about 2^-960),
 * where the error of a product could itself round away; a result for which
 * either may have happened says so with exp_ok() false.
 *
 * Portable ISO C with fma(); needs round-to-nearest-even IEEE doubles and
 * -ffp-contract=off, like dd.h.
 */
#ifndef EXPANSION_H
#define EXPANSION_H

#include <stdbool.h>
#include "dd.h"

#define EXP_MAX 512                 /* components: enough for a 3x3 determinant */

typedef struct {
    int n;                          /* the number of components              */
    bool lost;                      /* an overflow, an underflow or too many */
    double e[EXP_MAX];              /* e[0] smallest .. e[n-1] largest      */
} Expansion;

void exp_from(Expansion *x, double a);                          /* x = a          */
void exp_diff(Expansion *x, double a, double b);                /* x = a - b      */
void exp_add(Expansion *h, const Expansion *e, const Expansion *f);   /* h = e + f */
void exp_sub(Expansion *h, const Expansion *e, const Expansion *f);   /* h = e - f */
void exp_scale(Expansion *h, const Expansion *e, double b);     /* h = e b        */
void exp_mul(Expansion *h, const Expansion *e, const Expansion *f);   /* h = e f   */

int exp_sign(const Expansion *x);           /* -1, 0 or 1 */
bool exp_ok(const Expansion *x);            /* every operation was exact */
dd exp_to_dd(const Expansion *x);           /* within about 2^-100 relative */

/* A 3-vector of expansions, and the products the oracle needs. */
typedef struct {
    Expansion c[3];
} ExpVec;

void expv_diff(ExpVec *v, const double a[3], const double b[3]);     /* a - b     */
void expv_cross(ExpVec *h, const ExpVec *a, const ExpVec *b);         /* a x b     */
void expv_dot(Expansion *h, const ExpVec *a, const ExpVec *b);        /* a . b     */
void expv_dot_d(Expansion *h, const double a[3], const ExpVec *b);    /* a . b     */

#endif
