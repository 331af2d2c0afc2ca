/*
 * dd.c - the double-double constants and elementary functions of dd.h.
 *
 * Only what the oracle needs: sin and cos on |x| <= pi / 4 by their Taylor
 * series, and tan of an angle given in degrees with an exact reduction.
 */
#include "dd.h"

/* Each constant is hi + lo, the nearest double to the value and the
 * nearest double to the remainder; the error is below 1e-33 relative. */
const dd dd_pi     = { 0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53 };
const dd dd_pi_180 = { 0x1.1df46a2529d39p-6, 0x1.5c1d8becdd291p-62 };

/*
 * Taylor series, summed from the largest term down: with |x| <= pi / 4 the
 * terms fall by a factor of at least 10 per step after the first, and
 * sin x >= 0.9 x, cos x >= 0.7, so there is no cancellation; 15 terms reach
 * 1e-34.  The error is a few units of 2^-106 from the leading terms.
 */
void dd_sin_cos(dd x, dd *s, dd *c)
{
    dd mx2 = dd_neg(dd_sqr(x));
    dd sterm = x, ssum = x;
    dd cterm = dd_from(1), csum = dd_from(1);
    for (int k = 1; k <= 30; k++) {
        sterm = dd_div_d(dd_mul(sterm, mx2), (double)(2 * k) * (2 * k + 1));
        cterm = dd_div_d(dd_mul(cterm, mx2), (double)(2 * k - 1) * (2 * k));
        ssum = dd_add(ssum, sterm);
        csum = dd_add(csum, cterm);
        if (fabs(sterm.hi) <= 0x1p-115 * fabs(ssum.hi) && fabs(cterm.hi) <= 0x1p-115)
            break;
    }
    *s = ssum;
    *c = csum;
}

/*
 * tan(deg degrees).  For deg <= 45 the argument deg * pi / 180 is at most
 * pi / 4.  Above, tan(deg) = cos(y) / sin(y) with y = 90 - deg, which is
 * exact in double (Sterbenz: 45 <= deg <= 90); only then is y turned into
 * radians, so near 90 degrees the tiny y keeps its full relative accuracy.
 * Relative error: the argument's (about 2^-105 and 1e-33 from the
 * constant) times tan's condition number 2x / sin 2x <= pi / 2, plus the
 * series and the division: about 1e-30 in all.
 */
dd dd_tan_degrees(double deg)
{
    double a = fabs(deg);
    if (!(a <= 90)) {
        dd nan = { NAN, 0 };
        return nan;
    }
    dd s, c, t;
    if (a <= 45) {
        dd_sin_cos(dd_mul_d(dd_pi_180, a), &s, &c);
        t = dd_div(s, c);
    } else {
        double y = 90 - a;                  /* exact */
        if (y == 0) {
            dd inf = { INFINITY, 0 };
            t = inf;
        } else {
            dd_sin_cos(dd_mul_d(dd_pi_180, y), &s, &c);
            t = dd_div(c, s);
        }
    }
    return deg < 0 ? dd_neg(t) : t;
}
