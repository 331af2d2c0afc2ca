/*
 * accuracy.c - each method's errors against the exact answers.
 *
 * The exact answers come from tests/oracle (double-double arithmetic on the
 * same double inputs).  For every case:
 *   - the oracle says ambiguous (the line passes within rounding of the
 *     silhouette, or the origin lies within rounding of the surface): not
 *     counted at all, either answer is right;
 *   - hit/miss differs from the oracle's: a wrong answer;
 *   - both hit: the relative error |t - t_exact| / t_exact, and the same in
 *     units of u kappa (kappa: the oracle's condition number of t, u = 2^-53),
 *     which stays small for a backward-stable double method however hard the
 *     case.
 * A float method is given the inputs rounded to float, as a float renderer
 * would be; that rounding is part of its error.
 */
#include <math.h>
#include <stdlib.h>
#include "../oracle/oracle.h"
#include "bench.h"

Exact *exact_answers(const Case *cases, int n)
{
    Exact *ex = malloc((size_t)(n > 0 ? n : 1) * sizeof *ex);
    if (!ex)
        return NULL;
    for (int i = 0; i < n; i++) {
        OracleHit h = oracle_sphere(&cases[i].sphere, &cases[i].ray);
        ex[i].hit = h.hit;
        ex[i].ambiguous = h.ambiguous;
        ex[i].t = h.t;
        ex[i].kappa = h.kappa;
    }
    return ex;
}

void accuracy_run(const Method *m, const Case *cases, const Exact *exact, int n,
                  ErrorStats *st, double *errs, long *nerrs)
{
    double *own = errs ? errs : malloc((size_t)(n > 0 ? n : 1) * sizeof *own);
    long ne = 0;
    st->tests = n;
    st->ambiguous = st->wrong = st->hits = st->over_tol = 0;
    st->max_rel = st->median_rel = st->max_over_kappa = 0;
    for (int i = 0; i < n; i++) {
        if (exact[i].ambiguous) {
            st->ambiguous++;
            continue;
        }
        double t = NAN;
        bool hit = method_one(m, &cases[i].sphere, &cases[i].ray, &t);
        if (hit && !isfinite(t))
            hit = false;                  /* a hit with no usable t */
        if (hit != exact[i].hit) {
            st->wrong++;
            continue;
        }
        if (!hit)
            continue;
        double rel = fabs(t - exact[i].t) / exact[i].t;
        double ku = rel / (ORACLE_U * exact[i].kappa);
        st->hits++;
        if (rel > st->max_rel)
            st->max_rel = rel;
        if (ku > st->max_over_kappa)
            st->max_over_kappa = ku;
        if (ku > ORACLE_K_T)
            st->over_tol++;
        if (own)
            own[ne++] = rel;
    }
    if (own && ne > 0)
        st->median_rel = median(own, (int)ne);
    if (nerrs)
        *nerrs = ne;
    if (own != errs)
        free(own);
}
