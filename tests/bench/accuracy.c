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

void errors_add(ErrorStats *e, bool ambiguous, bool exact_hit, double exact_t, double kappa,
                bool hit, double t, double *rel)
{
    if (ambiguous) {
        e->ambiguous++;
        return;
    }
    if (hit != exact_hit) {
        e->wrong++;
        return;
    }
    if (!hit)
        return;
    double r = fabs(t - exact_t) / exact_t, ku = r / (ORACLE_U * kappa);
    rel[e->hits++] = r;
    if (r > e->max_rel)
        e->max_rel = r;
    if (ku > e->max_over_kappa)
        e->max_over_kappa = ku;
    if (ku > ORACLE_K_T)
        e->over_tol++;
    if (kappa <= 100 && r / ORACLE_U > e->max_u_well)
        e->max_u_well = r / ORACLE_U;
}

void accuracy_run(const Method *m, const Case *cases, const OracleHit *exact, int n,
                  ErrorStats *st, double *errs, long *nerrs)
{
    *st = (ErrorStats){ .tests = n };
    for (int i = 0; i < n; i++) {
        const OracleHit *o = &exact[i];
        double t = NAN;
        bool hit = !o->ambiguous && method_one(m, &cases[i].sphere, &cases[i].ray, &t);
        if (hit && !isfinite(t))
            hit = false;                  /* a hit with no usable t */
        errors_add(st, o->ambiguous, o->hit, o->t, o->kappa, hit, t, errs);
    }
    if (st->hits > 0)
        st->median_rel = median(errs, (int)st->hits);
    *nerrs = st->hits;
}
