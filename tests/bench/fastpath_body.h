/*
 * fastpath_body.h - the fast path's packet loops, written once and compiled
 * by fastpath.c for double and for float.  fastpath.c defines:
 *   REAL, UINT        the number type and the unsigned integer of its size
 *   SIGN_SHIFT        bits to shift a UINT to bring down the sign bit
 *   BIG               the largest finite REAL: "no hit yet"
 *   SQRT, COPYSIGN    the <math.h> functions for REAL
 *   FIELD(name)       the FastScene array of that precision (cx or fcx)
 *   NAME(x)           x with the precision's suffix
 */

static REAL NAME(from_bits)(UINT u)
{
    REAL x;
    memcpy(&x, &u, sizeof x);
    return x;
}

static UINT NAME(to_bits)(REAL x)
{
    UINT u;
    memcpy(&u, &x, sizeof u);
    return u;
}

/* The sign bit of x, as 0 or 1. */
static UINT NAME(sign_bit)(REAL x)
{
    return NAME(to_bits)(x) >> SIGN_SHIFT;
}

/* ---- the packet's rays and its answers ----------------------------------------- */

/* The packet's directions: the caller's arrays when the packet is full, else
 * a copy padded with (1, 0, 0) (its answers are dropped). */
static void NAME(packet_rays)(const REAL *dx, const REAL *dy, const REAL *dz, int p0, int np,
                              REAL pad[3][FAST_PACKET], const REAL **rx, const REAL **ry,
                              const REAL **rz)
{
    if (np == FAST_PACKET) {
        *rx = dx + p0;
        *ry = dy + p0;
        *rz = dz + p0;
        return;
    }
    for (int i = 0; i < FAST_PACKET; i++) {
        pad[0][i] = i < np ? dx[p0 + i] : 1;
        pad[1][i] = i < np ? dy[p0 + i] : 0;
        pad[2][i] = i < np ? dz[p0 + i] : 0;
    }
    *rx = pad[0];
    *ry = pad[1];
    *rz = pad[2];
}

/* The nearest hit so far: tbest (BIG: none yet) and kbest, its sphere. */
static void NAME(packet_start)(REAL *tbest, UINT *kbest)
{
    for (int i = 0; i < FAST_PACKET; i++) {
        tbest[i] = BIG;
        kbest[i] = ~(UINT)0;
    }
}

static void NAME(packet_finish)(const REAL *tbest, const UINT *kbest, int np, int *idx, double *t)
{
    for (int i = 0; i < np; i++) {
        bool hit = kbest[i] != ~(UINT)0;
        idx[i] = hit ? (int)kbest[i] : -1;
        t[i] = hit ? (double)tbest[i] : INFINITY;
    }
}

/* ---- 1. the filter ------------------------------------------------------------- */

/* Whether any ray of the packet may meet the sphere (c, bthr): b = c.r at
 * least bthr.  The answer for each ray is the sign bit of b - bthr (the
 * rounded difference has the sign of the exact one); and-ing them, the sign
 * survives only if every ray misses. */
static bool NAME(filter)(REAL cx, REAL cy, REAL cz, REAL bthr,
                         const REAL *rx, const REAL *ry, const REAL *rz)
{
    UINT all_miss = ~(UINT)0;
    for (int i = 0; i < FAST_PACKET; i++) {
        REAL b = cx * rx[i] + cy * ry[i] + cz * rz[i];
        all_miss &= NAME(to_bits)(b - bthr);
    }
    return !(all_miss >> SIGN_SHIFT);
}

/* The same for two spheres at once: each ray is loaded once for both. */
static unsigned NAME(filter2)(const FastScene *fs, int k, const REAL *rx, const REAL *ry,
                              const REAL *rz)
{
    REAL ax = fs->FIELD(cx)[k], ay = fs->FIELD(cy)[k], az = fs->FIELD(cz)[k];
    REAL bx = fs->FIELD(cx)[k + 1], by = fs->FIELD(cy)[k + 1], bz = fs->FIELD(cz)[k + 1];
    REAL athr = fs->FIELD(bthr)[k], bthr = fs->FIELD(bthr)[k + 1];
    UINT miss_a = ~(UINT)0, miss_b = ~(UINT)0;
    for (int i = 0; i < FAST_PACKET; i++) {
        REAL x = rx[i], y = ry[i], z = rz[i];
        miss_a &= NAME(to_bits)(ax * x + ay * y + az * z - athr);
        miss_b &= NAME(to_bits)(bx * x + by * y + bz * z - bthr);
    }
    return (unsigned)(!(miss_a >> SIGN_SHIFT)) | (unsigned)(!(miss_b >> SIGN_SHIFT)) << 1;
}

/* ---- 2. the solve ----------------------------------------------------------------- */

/* Sphere k, which the eye is outside of (C > 0), against the whole packet:
 * for each ray that passes the filter's test (recomputed here, the same
 * arithmetic, so each ray's answer depends on that ray alone) and whose
 * near root beats the best so far, keep it.  From outside, a hit has b > 0
 * and the near root is C / q, q = b + sqrt(R^2 - |c - b r|^2); a miss gives
 * q = NaN or q <= 0, both mapped to q = 0, which never wins.
 * Three short loops rather than one long one: the processor overlaps more
 * of the sqrt and division latency.  "Beats" is C < tbest q, so the
 * comparison does not wait for the division. */
static void NAME(solve_outside)(const FastScene *fs, int k, const REAL *rx, const REAL *ry,
                                const REAL *rz, REAL *restrict tbest, UINT *restrict kbest)
{
    REAL cx = fs->FIELD(cx)[k], cy = fs->FIELD(cy)[k], cz = fs->FIELD(cz)[k];
    REAL r2 = fs->FIELD(r2)[k], C = fs->FIELD(c)[k], bthr = fs->FIELD(bthr)[k];
    UINT kk = (UINT)k;
    REAL b[FAST_PACKET], disc[FAST_PACKET], q[FAST_PACKET];
    for (int i = 0; i < FAST_PACKET; i++) {
        REAL x = rx[i], y = ry[i], z = rz[i];
        REAL bi = cx * x + cy * y + cz * z;
        REAL lx = cx - bi * x, ly = cy - bi * y, lz = cz - bi * z;
        b[i] = bi;
        disc[i] = r2 - (lx * lx + ly * ly + lz * lz);
    }
    for (int i = 0; i < FAST_PACKET; i++) {
        REAL qi = b[i] + SQRT(disc[i]);
        q[i] = qi > 0 ? qi : 0;                    /* NaN too goes to 0 */
    }
    for (int i = 0; i < FAST_PACKET; i++) {
        REAL tb = tbest[i], t = C / q[i];          /* t in (0, +inf]     */
        UINT passes = NAME(sign_bit)(b[i] - bthr) - 1;        /* all ones or 0 */
        UINT better = ((UINT)0 - NAME(sign_bit)(C - tb * q[i])) & passes;
        tbest[i] = NAME(from_bits)((NAME(to_bits)(t) & better) | (NAME(to_bits)(tb) & ~better));
        kbest[i] = (kk & better) | (kbest[i] & ~better);
    }
}

/* Sphere k against the first n rays, one at a time: for a sphere the eye is
 * inside of (or on), which every ray meets.  The roots of t^2 - 2 b t + C = 0
 * without cancellation: q = b + sign(b) s, roots q and C / q. */
static void NAME(solve_rays)(const FastScene *fs, int k, const REAL *rx, const REAL *ry,
                             const REAL *rz, int n, REAL *tbest, UINT *kbest)
{
    REAL cx = fs->FIELD(cx)[k], cy = fs->FIELD(cy)[k], cz = fs->FIELD(cz)[k];
    REAL r2 = fs->FIELD(r2)[k], C = fs->FIELD(c)[k];
    for (int i = 0; i < n; i++) {
        REAL x = rx[i], y = ry[i], z = rz[i];
        REAL b = cx * x + cy * y + cz * z;
        REAL lx = cx - b * x, ly = cy - b * y, lz = cz - b * z;
        REAL disc = r2 - (lx * lx + ly * ly + lz * lz);
        if (!(disc >= 0))
            continue;
        REAL q = b + COPYSIGN(SQRT(disc), b);
        if (q == 0)
            continue;
        REAL t1 = q, t2 = C / q;
        REAL tnear = t1 < t2 ? t1 : t2, tfar = t1 < t2 ? t2 : t1;
        REAL root = tnear > 0 ? tnear : tfar;
        if (root > 0 && root < tbest[i]) {
            tbest[i] = root;
            kbest[i] = (UINT)k;
        }
    }
}

/* ---- the loop over packets -------------------------------------------------------- */

void NAME(fast_closest)(const FastScene *fs, const REAL *dx, const REAL *dy, const REAL *dz,
                        int count, int *idx, double *t)
{
    for (int p0 = 0; p0 < count; p0 += FAST_PACKET) {
        int np = count - p0 < FAST_PACKET ? count - p0 : FAST_PACKET;
        const REAL *rx, *ry, *rz;
        REAL pad[3][FAST_PACKET], tbest[FAST_PACKET];
        UINT kbest[FAST_PACKET];
        NAME(packet_rays)(dx, dy, dz, p0, np, pad, &rx, &ry, &rz);
        NAME(packet_start)(tbest, kbest);
        for (int k = 0; k < fs->n; k++) {
            if (!(fs->FIELD(c)[k] > 0)) {
                NAME(solve_rays)(fs, k, rx, ry, rz, np, tbest, kbest);
            } else if (k + 1 < fs->n && fs->FIELD(c)[k + 1] > 0) {
                unsigned pass = NAME(filter2)(fs, k, rx, ry, rz);
                if (pass & 1u)
                    NAME(solve_outside)(fs, k, rx, ry, rz, tbest, kbest);
                if (pass & 2u)
                    NAME(solve_outside)(fs, k + 1, rx, ry, rz, tbest, kbest);
                k++;
            } else if (NAME(filter)(fs->FIELD(cx)[k], fs->FIELD(cy)[k], fs->FIELD(cz)[k],
                                    fs->FIELD(bthr)[k], rx, ry, rz)) {
                NAME(solve_outside)(fs, k, rx, ry, rz, tbest, kbest);
            }
        }
        NAME(packet_finish)(tbest, kbest, np, idx + p0, t + p0);
    }
}
