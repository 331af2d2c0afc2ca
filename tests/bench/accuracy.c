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
#include "bench.h"

double per_million(long count, long of)
{
    return of > 0 ? 1e6 * (double)count / (double)of : 0;
}

double wrong_per_million(const ErrorStats *s)
{
    return per_million(s->wrong, s->tests - s->ambiguous);
}

OracleHit *exact_answers(const Case *cases, int n)
{
    OracleHit *ex = malloc((size_t)(n > 0 ? n : 1) * sizeof *ex);
    for (int i = 0; ex && i < n; i++)
        ex[i] = oracle_sphere(&cases[i].sphere, &cases[i].ray);
    return ex;
}

void accuracy_run(const Method *m, const Case *cases, const OracleHit *exact, int n,
                  ErrorStats *st, double *errs, long *nerrs)
{
    long ne = 0;
    *st = (ErrorStats){ .tests = n };
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
        errs[ne++] = rel;
    }
    if (ne > 0)
        st->median_rel = median(errs, (int)ne);
    *nerrs = ne;
}
