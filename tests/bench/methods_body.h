/*
 * methods_body.h - the ray/sphere formulations, and Moller-Trumbore's
 * ray/triangle test (Part 5, tri_methods.c), written once and compiled
 * twice by methods.c: with REAL = double and with REAL = float, so the two
 * cannot drift apart.
 *
 * methods.c defines, before each inclusion:
 *   REAL, VEC, SPHERE, RAY, TRI   the number and struct types
 *   SQRT, COPYSIGN           the <math.h> functions for REAL
 *   TINY                     the smallest normal number
 *   SAFE_LO, SAFE_HI         the range where A R^2 is formed safely
 *   NAME(x)                  x with the precision's suffix (_d or _f)
 * and this file undefines them at its end.
 *
 * Notation (the lecture's): ray x(t) = e + t r, sphere centre c, radius R,
 * f = e - c, A = r.r, B = f.r, C = f.f - R^2.  Every method returns the
 * smallest root t > 0 (from inside the sphere, the exit point) and false on
 * a miss; NaN input falls through every `!(x >= 0)` test to a miss.
 */

static VEC NAME(sub)(VEC a, VEC b)
{
    VEC v = { a.x - b.x, a.y - b.y, a.z - b.z };
    return v;
}

static REAL NAME(dot)(VEC a, VEC b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

static VEC NAME(cross)(VEC a, VEC b)
{
    VEC v = { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
    return v;
}

/* The lecture's quadratic: t = (-B -+ sqrt(B^2 - A C)) / A.  B^2 - A C loses
 * R^2 when the sphere is small and far; -B + sqrt(..) cancels when e is
 * close to a big sphere.  With unit set, A = 1, which holds for unit
 * directions (camera rays): t = -B -+ sqrt(B^2 - C), one product and two
 * divisions fewer (multiplying and dividing by a constant 1 are exact, and
 * the compiler drops them: isect_unit is compiled as if written alone). */
static inline bool NAME(quadratic)(const SPHERE *sphere, const RAY *ray, REAL *t, bool unit)
{
    VEC r = ray->direction;
    VEC f = NAME(sub)(ray->origin, sphere->center);
    REAL A = unit ? 1 : NAME(dot)(r, r);
    REAL B = NAME(dot)(f, r);
    REAL C = NAME(dot)(f, f) - sphere->radius * sphere->radius;
    REAL disc = B * B - A * C;
    if (!(disc >= 0))
        return false;
    REAL sq = SQRT(disc);
    REAL t1 = (-B - sq) / A;
    if (t1 > 0) {
        *t = t1;
        return true;
    }
    REAL t2 = (-B + sq) / A;
    if (t2 > 0) {
        *t = t2;
        return true;
    }
    return false;
}

bool NAME(isect_textbook)(const SPHERE *sphere, const RAY *ray, REAL *t)
{
    return NAME(quadratic)(sphere, ray, t, false);
}

bool NAME(isect_unit)(const SPHERE *sphere, const RAY *ray, REAL *t)
{
    return NAME(quadratic)(sphere, ray, t, true);
}

/* The geometric method (unit r): L = c - e, t_ca = L.r is where the ray
 * passes closest to c, d^2 = L.L - t_ca^2 the squared distance there (by
 * Pythagoras: the same cancellation as B^2 - C), t_hc = sqrt(R^2 - d^2),
 * t = t_ca -+ t_hc.  The early exit for a centre behind the ray holds only
 * from outside the sphere, so it tests that too. */
bool NAME(isect_geometric)(const SPHERE *sphere, const RAY *ray, REAL *t)
{
    VEC r = ray->direction;
    VEC L = NAME(sub)(sphere->center, ray->origin);
    REAL tca = NAME(dot)(L, r);
    REAL L2 = NAME(dot)(L, L);
    REAL R2 = sphere->radius * sphere->radius;
    if (tca < 0 && L2 > R2)
        return false;
    REAL d2 = L2 - tca * tca;
    if (!(d2 <= R2))
        return false;
    REAL thc = SQRT(R2 - d2);
    REAL t0 = tca - thc;
    if (t0 > 0) {
        *t = t0;
        return true;
    }
    REAL t1 = tca + thc;
    if (t1 > 0) {
        *t = t1;
        return true;
    }
    return false;
}

/* Ray Tracing Gems, ch. 7 (the general-direction listing): the discriminant
 * from l = f - (B/A) r, the offset from c to the line's closest point,
 * A (R^2 - l.l); then q = -(B + sign(B) sqrt(disc)) and the roots C/q and
 * q/A, neither of which cancels. */
bool NAME(isect_rtg)(const SPHERE *sphere, const RAY *ray, REAL *t)
{
    VEC r = ray->direction;
    VEC f = NAME(sub)(ray->origin, sphere->center);
    REAL A = NAME(dot)(r, r);
    REAL B = NAME(dot)(f, r);
    REAL R2 = sphere->radius * sphere->radius;
    REAL b = B / A;
    VEC l = { f.x - b * r.x, f.y - b * r.y, f.z - b * r.z };
    REAL disc = A * (R2 - NAME(dot)(l, l));
    if (!(disc >= 0))
        return false;
    REAL C = NAME(dot)(f, f) - R2;
    REAL q = -(B + COPYSIGN(SQRT(disc), B));
    REAL t1 = C / q, t2 = q / A;
    REAL tnear = t1 < t2 ? t1 : t2, tfar = t1 < t2 ? t2 : t1;
    REAL root = tnear > 0 ? tnear : tfar;
    if (!(root > 0))
        return false;
    *t = root;
    return true;
}

/* The reference's miss test on f = e - c and r, with AR2 = A R^2: adds the
 * terms of |f x r|^2 one at a time and stops at the first partial sum above
 * T.  Returns the stage that decides (REF_STAGE_NX, _NXY, _NN: a miss;
 * REF_STAGE_ROOTS or _CAREFUL: the reference goes on), with *nn the sum. */
static inline int NAME(stage)(VEC f, VEC r, REAL AR2, REAL *nn)
{
    VEC n = { f.y * r.z - f.z * r.y, f.z * r.x - f.x * r.z, f.x * r.y - f.y * r.x };
    REAL T = AR2 + 2 * TINY;
    *nn = n.x * n.x;
    if (*nn > T)
        return REF_STAGE_NX;
    *nn += n.y * n.y;
    if (*nn > T)
        return REF_STAGE_NXY;
    *nn += n.z * n.z;
    if (*nn > T)
        return REF_STAGE_NN;
    return AR2 > SAFE_LO && AR2 < SAFE_HI ? REF_STAGE_ROOTS : REF_STAGE_CAREFUL;
}

/* solutions/part3a_sphere_intersect.c, line by line in REAL.  Compiled as
 * double it must agree bit for bit with the linked sphere_intersect (the
 * benchmark checks, so this copy cannot silently go stale); the float
 * version is the benchmark's "reference, float".  SAFE_LO and SAFE_HI are
 * the reference's 2^-900 and 2^900: where A R^2 and |f x r|^2 are formed
 * without overflow or underflow (2^-100 and 2^100 in float).  The miss
 * test is NAME(stage) (see the reference). */
bool NAME(isect_reference)(const SPHERE *sphere, const RAY *ray, REAL *t)
{
    VEC r = ray->direction;
    VEC f = NAME(sub)(ray->origin, sphere->center);
    REAL R2 = sphere->radius * sphere->radius;
    REAL A = NAME(dot)(r, r);
    REAL AR2 = A * R2;
    REAL nn;
    int stage = NAME(stage)(f, r, AR2, &nn);
    if (stage <= REF_STAGE_NN)
        return false;

    REAL sq;
    if (stage == REF_STAGE_ROOTS) {
        sq = SQRT(AR2 - nn);
    } else {
        if (nn - AR2 > TINY)
            return false;
        if (!(A > 0))
            return false;
        REAL b = NAME(dot)(f, r) / A;
        VEC l = { f.x - r.x * b, f.y - r.y * b, f.z - r.z * b };
        REAL D = R2 - NAME(dot)(l, l);
        if (!(D >= 0))
            return false;
        sq = SQRT(A) * SQRT(D);
    }
    REAL B = NAME(dot)(f, r);
    REAL C = NAME(dot)(f, f) - R2;
    REAL q = B < 0 ? sq - B : -(B + sq);
    REAL root = C / q;
    if (!(root > 0))
        root = q / A;
    if (!(root > 0) || root >= (REAL)INFINITY)
        return false;
    *t = root;
    return true;
}

/* The closest-hit loop (suite.c's method_closest): for each of the nrays
 * rays, the index of the nearest of the n spheres that fn hits (-1: none)
 * and its t (infinity: none), in REAL and stored as double. */
void NAME(closest)(bool (*fn)(const SPHERE *, const RAY *, REAL *), const SPHERE *spheres, int n,
                   const RAY *rays, int nrays, int *idx, double *t)
{
    for (int i = 0; i < nrays; i++) {
        REAL tmin = INFINITY;
        int best = -1;
        for (int k = 0; k < n; k++) {
            REAL tk;
            if (fn(&spheres[k], &rays[i], &tk) && tk < tmin) {
                tmin = tk;
                best = k;
            }
        }
        idx[i] = best;
        t[i] = tmin;
    }
}

/* Moller-Trumbore (1997), the skeleton's formula: det = 0 a miss, one
 * division. */
bool NAME(tri_moller_trumbore)(const TRI *tri, const RAY *ray, REAL *t)
{
    VEC e1 = NAME(sub)(tri->b, tri->a), e2 = NAME(sub)(tri->c, tri->a);
    VEC s = NAME(sub)(ray->origin, tri->a), q = NAME(cross)(ray->direction, e2);
    REAL det = NAME(dot)(e1, q);
    if (det == 0)
        return false;
    REAL inv = 1 / det, beta = NAME(dot)(s, q) * inv;
    if (beta < 0 || beta > 1)
        return false;
    VEC sx = NAME(cross)(s, e1);
    REAL gamma = NAME(dot)(ray->direction, sx) * inv;
    if (gamma < 0 || beta + gamma > 1)
        return false;
    REAL tt = NAME(dot)(e2, sx) * inv;
    if (!(tt > 0 && tt < INFINITY))
        return false;
    *t = tt;
    return true;
}

#undef REAL
#undef VEC
#undef SPHERE
#undef RAY
#undef TRI
#undef SQRT
#undef COPYSIGN
#undef TINY
#undef SAFE_LO
#undef SAFE_HI
#undef NAME
