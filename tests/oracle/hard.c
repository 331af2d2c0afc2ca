/*
 * hard.c - the hard-case generators of hard.h.
 *
 * Each generator is a switch over its families; every case draws from its
 * own random stream, seeded by (seed, part, k).  Expected values come from
 * the oracle only.  Where a construction is exact (dyadic 3-4-5 and 2-3-6-7
 * style quadruples scaled by powers of two) the exact t is also what the
 * oracle returns; the unit tests check that.
 */
#include <stdio.h>
#include <string.h>
#include "hard.h"
#include "draw.h"

/* ---- Part 1 -------------------------------------------------------------- */

static const char *const fam1[HARD_PART1_FAMILIES] = {
    "fov 180 - 2^-k",
    "fov 179.999...9",
    "tiny fov 1e-10..1 deg",
    "ordinary fov 1..179",
    "fov near 90 (tan branch at 45)",
    "round fov (30, 60, 90, 120, ...)",
};

int hard_part1(uint64_t seed, HardCase1 *cases, int max)
{
    static const double nines[] = { 179.999, 179.9999, 179.99999, 179.999999, 179.9999999,
                                    179.99999999, 179.999999999, 179.9999999999 };
    static const double round_fov[] = { 1, 5, 10, 20, 30, 45, 60, 75, 90, 100, 120, 135,
                                         150, 160, 170, 175, 179 };
    for (int k = 0; k < max; k++) {
        uint64_t s = draw_stream(seed, 1, k);
        HardCase1 *c = &cases[k];
        int fam = k % HARD_PART1_FAMILIES;
        double fov = 60;
        switch (fam) {
        case 0: fov = 180 - ldexp(1, -draw_int(&s, 1, 45)); break;
        case 1: fov = nines[draw_int(&s, 0, (int)(sizeof nines / sizeof nines[0]) - 1)]; break;
        case 2: fov = draw_log(&s, 1e-10, 1); break;
        case 3: fov = draw_uni(&s, 1, 179); break;
        case 4: {
            int m = draw_int(&s, -16, 16);
            fov = 90;
            for (; m > 0; m--) fov = nextafter(fov, 180);
            for (; m < 0; m++) fov = nextafter(fov, 0);
            break;
        }
        default: fov = round_fov[draw_int(&s, 0, (int)(sizeof round_fov / sizeof round_fov[0]) - 1)]; break;
        }
        draw_family(c->family, fam1[fam]);
        c->fov_degrees = fov;
        /* Wide and tall in turn, so that a field of view taken along the
         * wrong side (pbrt's shorter axis) fails every family. */
        c->aspect = draw_log(&s, 1, 1e6);
        if ((k / HARD_PART1_FAMILIES) % 2)
            c->aspect = 1 / c->aspect;
        c->d = draw_log(&s, 1e-6, 1e6);
        oracle_image_plane(c->fov_degrees, c->aspect, c->d, &c->w, &c->h);
    }
    return max > 0 ? max : 0;
}

static bool rel_close(double got, double want, double rel)
{
    return fabs(got - want) <= rel * fabs(want);
}

bool hard_check1(const HardCase1 *c, double w, double h)
{
    return rel_close(w, c->w, HARD_PART1_REL_TOL) && rel_close(h, c->h, HARD_PART1_REL_TOL);
}

/* ---- Part 2 -------------------------------------------------------------- */

static const char *const fam2[HARD_PART2_FAMILIES] = {
    "huge image (5e5..1e6 a side)",
    "centre and edge pixels",
    "tiny image (1..16 a side)",
    "power-of-two size (rounding ties)",
};

/* The special indices of a row of n pixels: the first, the last and the
 * two middle ones (one when n is odd). */
static int edge_index(int kind, int n)
{
    switch (kind % 4) {
    case 0: return 0;
    case 1: return n - 1;
    case 2: return n / 2;
    default: return (n - 1) / 2;
    }
}

/* A double in [2^e, 2^(e+1)) with the last bit of its significand set. */
static double odd_significand(uint64_t *s, int e)
{
    uint64_t m = (hard_rng_next(s) >> 12) | 1;            /* 52 bits, odd */
    return ldexp((double)((1ULL << 52) | m), e - 52);
}

int hard_part2(uint64_t seed, HardCase2 *cases, int max)
{
    for (int k = 0; k < max; k++) {
        uint64_t s = draw_stream(seed, 2, k);
        HardCase2 *c = &cases[k];
        int fam = k % HARD_PART2_FAMILIES;
        c->w = draw_log(&s, 1e-6, 1e6);
        c->h = draw_log(&s, 1e-6, 1e6);
        c->d = draw_log(&s, 1e-6, 1e6);
        switch (fam) {
        case 0:
            c->nx = draw_int(&s, 500000, 1000000);
            c->ny = draw_int(&s, 500000, 1000000);
            c->i = draw_int(&s, 0, c->nx - 1);
            c->j = draw_int(&s, 0, c->ny - 1);
            break;
        case 1: {
            /* The family's m-th case: every four in a row take each index
             * kind once for i and once for j, in different pairs, so that
             * no mistake that is right at one of them (rows counted from
             * the bottom, right at the middle row) passes four cases.  At
             * least 2 a side: a single row or column is the tiny images'. */
            int m = k / HARD_PART2_FAMILIES;
            c->nx = (int)draw_log(&s, 2, 1e6);
            c->ny = (int)draw_log(&s, 2, 1e6);
            c->i = edge_index(m, c->nx);
            c->j = edge_index(3 * m + m / 4, c->ny);
            break;
        }
        case 2:
            c->nx = draw_int(&s, 1, 16);
            c->ny = draw_int(&s, 1, 16);
            c->i = draw_int(&s, 0, c->nx - 1);
            c->j = draw_int(&s, 0, c->ny - 1);
            if ((k / HARD_PART2_FAMILIES) % 4 == 0) {
                /* Every fourth: the bottom-left pixel of an image that is
                 * neither square nor one row, where a flipped y, swapped i
                 * and j, or nx for ny are each wrong, as a random pixel of
                 * a tiny image is not always. */
                c->nx = draw_int(&s, 2, 15);
                c->ny = draw_int(&s, 2, 15);
                if (c->ny >= c->nx)
                    c->ny++;
                c->i = 0;
                c->j = c->ny - 1;
            }
            break;
        default:
            c->nx = 1 << draw_int(&s, 0, 19);
            c->ny = 1 << draw_int(&s, 0, 19);
            c->i = draw_int(&s, 0, c->nx - 1);
            c->j = draw_int(&s, 0, c->ny - 1);
            c->w = odd_significand(&s, draw_int(&s, -20, 19));
            c->h = odd_significand(&s, draw_int(&s, -20, 19));
            break;
        }
        draw_family(c->family, fam2[fam]);
        c->p = oracle_pixel(c->i, c->j, c->nx, c->ny, c->w, c->h, c->d);
    }
    return max > 0 ? max : 0;
}

bool hard_check2(const HardCase2 *c, Vec3 got)
{
    return fabs(got.x - c->p.x) <= HARD_PART2_TOL_U * ORACLE_U * fabs(c->p.x)
        && fabs(got.y - c->p.y) <= HARD_PART2_TOL_U * ORACLE_U * fabs(c->p.y)
        && got.z == c->p.z;
}

/* ---- Part 3a ------------------------------------------------------------- */

static const char *const fam3a[HARD_PART3A_FAMILIES] = {
    "ordinary scene",
    "far small sphere D/R=1e1",
    "far small sphere D/R=1e2",
    "far small sphere D/R=1e3",
    "far small sphere D/R=1e4",
    "far small sphere D/R=1e5",
    "far small sphere D/R=1e6",
    "far small sphere D/R=1e7",
    "origin above huge sphere h/R=1e-1",
    "origin above huge sphere h/R=1e-3",
    "origin above huge sphere h/R=1e-5",
    "origin above huge sphere h/R=1e-7",
    "origin above huge sphere h/R=1e-9",
    "origin just inside huge sphere h/R=1e-3",
    "origin just inside huge sphere h/R=1e-6",
    "origin just inside huge sphere h/R=1e-9",
    "tangent ray +-1 ulp",
    "grazing ray, gap 16u..1e4u",
    "tiny direction, length 1e-150..1e-50",
    "huge direction, length 1e50..1e150",
    "origin inside (exact dyadic)",
    "origin on the surface (exact dyadic)",
    "from outside (exact dyadic)",
    "exact tangent (dyadic), R +-1 ulp",
    "sphere behind the eye / mirrored",
    "tiny scene (lengths ~1e-6)",
    "huge scene (lengths ~1e9)",
    "origin on the surface, rounded",
};

/* Integer points on spheres: a^2 + b^2 + c^2 = d^2 (3-4-5 and 2-3-6-7 and
 * their kin).  Scaled by powers of two they give exact hits. */
static const int quads[][4] = {
    { 3, 4, 0, 5 }, { 1, 2, 2, 3 }, { 2, 3, 6, 7 }, { 1, 4, 8, 9 }, { 4, 4, 7, 9 },
    { 2, 6, 9, 11 }, { 6, 6, 7, 11 }, { 3, 4, 12, 13 }, { 2, 10, 11, 15 },
    { 1, 12, 12, 17 }, { 8, 9, 12, 17 },
};

/* A random permutation with random signs of quadruple q's (a, b, c). */
static Vec3 lattice_point(uint64_t *s, int q)
{
    static const int perm[6][3] = { {0,1,2}, {0,2,1}, {1,0,2}, {1,2,0}, {2,0,1}, {2,1,0} };
    const int *p = perm[draw_int(s, 0, 5)];
    double v[3];
    for (int k = 0; k < 3; k++)
        v[k] = quads[q][p[k]] * (draw_int(s, 0, 1) ? 1.0 : -1.0);
    return vec3(v[0], v[1], v[2]);
}

/* Two different lattice points P1, P2 on the sphere of radius d of one
 * quadruple (not opposite when need_cross), a dyadic centre and scale. */
typedef struct {
    Vec3 c, p1, p2;      /* centre; p1, p2 relative to it, already scaled */
    double R;            /* d 2^m */
    double scale;        /* 2^m */
} Lattice;

static Lattice lattice(uint64_t *s, bool need_cross)
{
    Lattice L;
    int q = draw_int(s, 0, (int)(sizeof quads / sizeof quads[0]) - 1);
    Vec3 a = lattice_point(s, q), b;
    for (;;) {
        b = lattice_point(s, q);
        Vec3 x = vec3_cross(a, b);
        bool same = a.x == b.x && a.y == b.y && a.z == b.z;
        if (!same && (!need_cross || vec3_dot(x, x) > 0))
            break;
    }
    int m = draw_int(s, -20, 20);
    L.scale = ldexp(1, m);
    L.R = quads[q][3] * L.scale;
    L.p1 = vec3_scale(a, L.scale);
    L.p2 = vec3_scale(b, L.scale);
    int cz = draw_int(s, -1000, 1000), cy = draw_int(s, -1000, 1000), cx = draw_int(s, -1000, 1000);
    L.c = vec3_scale(vec3(cx, cy, cz), ldexp(1, m - 2));
    return L;
}

/* Centre at distance D from e in a random direction. */
static Vec3 centre_at(uint64_t *s, Vec3 e, double D)
{
    return vec3_add(e, vec3_scale(draw_unit(s), D));
}

/* The lecture's kind of scene, at length scale S: an eye within S of the
 * origin, a sphere of radius about S at 1.2 to 5 radii (one time in four,
 * with inside true, around the eye). */
static void ordinary(uint64_t *s, double S, bool inside_ok, Vec3 *e, Vec3 *c, double *R)
{
    *e = draw_point(s, S);
    *R = S * draw_uni(s, 0.5, 2);
    bool inside = inside_ok && hard_rng_next(s) % 4 == 0;
    *c = centre_at(s, *e, *R * (inside ? draw_uni(s, 0, 0.9) : draw_uni(s, 1.2, 5)));
}

/* Part 3a's families 8 to 15: an origin just above (8 to 12) or just
 * inside (13 to 15) a huge sphere, h/R from 1e-1 to 1e-9 off its surface. */
static void near_huge(uint64_t *s, int fam, bool want_hit, Vec3 *eye, Vec3 *centre, Vec3 *dir, double *radius)
{
    Vec3 e, c, r;
    double R;
    static const double hr[16] = { [8] = 1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-3, 1e-6, 1e-9 };
    bool above = fam <= 12;
    R = draw_log(s, 1e2, 1e6);
    c = draw_point(s, 10 * R);
    Vec3 n = draw_unit(s);
    double h = R * hr[fam] * draw_uni(s, 1, 2);
    e = vec3_add(c, vec3_scale(n, above ? R + h : R - h));
    Vec3 w = draw_perp(s, n);
    if (!above) {                   /* inside: always a hit, out or in */
        double sgn = want_hit ? 1 : -1;
        r = vec3_add(vec3_scale(n, sgn), vec3_scale(w, draw_uni(s, 0, 3)));
    } else if (want_hit) {          /* downwards, up to 63 degrees off */
        r = vec3_add(vec3_scale(n, -1), vec3_scale(w, draw_uni(s, 0, 2)));
    } else if (hard_rng_next(s) % 2) {  /* upwards */
        r = vec3_add(n, vec3_scale(w, draw_uni(s, 0, 3)));
    } else {                        /* horizontal or just above */
        r = vec3_add(w, vec3_scale(n, draw_uni(s, 0, 0.5)));
    }
    r = vec3_scale(r, draw_len(s));
    *eye = e, *centre = c, *dir = r, *radius = R;
}

/* Part 3a's family 16: a ray tangent to the sphere, then one of r's
 * components, R or the centre's x moved 1 or 2 ulps up (want_hit) or
 * down; the oracle says which answer that makes. */
static void tangent_ulp(uint64_t *s, bool want_hit, Vec3 *eye, Vec3 *centre, Vec3 *dir, double *radius)
{
    Vec3 e, c, r;
    double R;
    e = draw_point(s, 1);
    double len = draw_len(s);
    r = vec3_scale(draw_unit(s), len);
    R = draw_log(s, 0.01, 100);
    double t0 = R * draw_uni(s, 1, 1000) / vec3_length(r);
    c = vec3_add(vec3_add(e, vec3_scale(r, t0)), vec3_scale(draw_perp(s, r), R));
    double *target[5] = { &r.x, &r.y, &r.z, &R, &c.x };
    double *x = target[draw_int(s, 0, 4)];
    int steps = draw_int(s, 1, 2);
    for (int k = 0; k < steps; k++)
        *x = nextafter(*x, want_hit ? INFINITY : -INFINITY);
    *eye = e, *centre = c, *dir = r, *radius = R;
}

/* Part 3a's families 20 to 23: exact dyadic lattice spheres, the origin
 * inside (20), on the surface (21), outside (22), or a tangent ray (23). */
static void dyadic(uint64_t *s, int fam, bool want_hit, Vec3 *eye, Vec3 *centre, Vec3 *dir, double *radius)
{
    Vec3 e, c, r;
    double R;
    Lattice L = lattice(s, fam == 23);
    c = L.c;
    R = L.R;
    Vec3 chord = vec3_sub(L.p2, L.p1);                  /* exact */
    double rs = ldexp(1, draw_int(s, -10, 10));
    if (fam == 20) {                /* inside: exit at p2 (or p1) */
        double lambda = draw_int(s, 1, 15) / 16.0;
        e = vec3_add(c, vec3_add(L.p1, vec3_scale(chord, lambda)));
        r = vec3_scale(chord, want_hit ? rs : -rs);
    } else if (fam == 21) {         /* on the surface: in (hit) or out */
        e = vec3_add(c, L.p1);
        r = vec3_scale(chord, want_hit ? rs : -rs);
    } else if (fam == 22) {         /* outside: towards it or away */
        double mu = draw_int(s, 1, 40) / 8.0;
        e = vec3_add(c, vec3_sub(L.p1, vec3_scale(chord, mu)));
        r = vec3_scale(chord, want_hit ? rs : -rs);
    } else {                        /* tangent at p1: along p1 x p2 */
        Vec3 w = vec3_scale(vec3_cross(L.p1, L.p2), 1 / L.scale);   /* exact */
        double mu = draw_int(s, 1, 40) / 8.0;
        e = vec3_add(c, vec3_sub(L.p1, vec3_scale(w, mu)));
        r = vec3_scale(w, rs);
        if (hard_rng_next(s) % 2)
            R = nextafter(R, want_hit ? INFINITY : 0);
    }
    *eye = e, *centre = c, *dir = r, *radius = R;
}

static void gen3a(uint64_t *s, int fam, bool want_hit, Sphere *sp, Ray *ray)
{
    Vec3 e = vec3(0, 0, 0), c = vec3(0, 0, 0), r = vec3(0, 0, -1);
    double R = 1;
    double rho = want_hit ? draw_uni(s, 0, 0.98) : draw_uni(s, 1.02, 2);
    if (fam == 0) {                                         /* ordinary */
        ordinary(s, 1, true, &e, &c, &R);
        r = draw_aim(s, e, c, R, rho, draw_len(s));
    } else if (fam <= 7) {                                  /* far small sphere */
        static const double ratio[8] = { 0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7 };
        R = draw_log(s, 0.01, 100);
        e = draw_point(s, R);
        c = centre_at(s, e, R * ratio[fam] * draw_uni(s, 1, 2));
        r = draw_aim(s, e, c, R, rho, draw_len(s));
    } else if (fam <= 15) {                                 /* near a huge sphere */
        near_huge(s, fam, want_hit, &e, &c, &r, &R);
    } else if (fam == 16) {                                 /* tangent +- 1 ulp */
        tangent_ulp(s, want_hit, &e, &c, &r, &R);
    } else if (fam == 17) {                                 /* grazing, clear gap */
        double len = draw_len(s);
        r = vec3_scale(draw_unit(s), len);
        R = draw_log(s, 0.01, 100);
        double along = R * draw_uni(s, 2, 1000);
        double gap = (want_hit ? -1 : 1) * draw_log(s, 16, 1e4) * ORACLE_U * (along + 2 * R);
        c = vec3_add(vec3_scale(r, along / vec3_length(r)), vec3_scale(draw_perp(s, r), R + gap));
    } else if (fam <= 19) {                                 /* extreme |r| */
        ordinary(s, 1, true, &e, &c, &R);
        int k = fam == 18 ? draw_int(s, -498, -167) : draw_int(s, 166, 497);
        r = draw_aim(s, e, c, R, rho, ldexp(1 + hard_rng_uniform(s), k));
    } else if (fam <= 23) {                                 /* exact dyadic */
        dyadic(s, fam, want_hit, &e, &c, &r, &R);
    } else if (fam == 24) {                                 /* behind the eye */
        ordinary(s, 1, false, &e, &c, &R);
        double len = draw_len(s);
        r = draw_aim(s, e, c, R, draw_uni(s, 0, 0.95), len);
        if (!want_hit)
            r = vec3_negate(r);
    } else if (fam == 27) {                                 /* on the surface, rounded */
        R = draw_log(s, 0.01, 100);
        c = draw_point(s, 10 * R);
        Vec3 n = draw_unit(s);
        e = vec3_add(c, vec3_scale(n, R));
        double across = draw_uni(s, 0, 3);
        r = vec3_add(vec3_scale(n, want_hit ? -1 : 1), vec3_scale(draw_perp(s, n), across));
        r = vec3_scale(r, draw_len(s));
    } else {                                                /* tiny or huge scene */
        ordinary(s, fam == 25 ? 1e-6 : 1e9, true, &e, &c, &R);
        r = draw_aim(s, e, c, R, rho, fam == 25 ? 1 : draw_len(s));
    }
    sp->center = c;
    sp->radius = R;
    sp->color = vec3(1, 1, 1);
    ray->origin = e;
    ray->direction = r;
}

int hard_part3a(uint64_t seed, HardCase3a *cases, int max)
{
    for (int k = 0; k < max; k++) {
        uint64_t s = draw_stream(seed, 3, k);
        HardCase3a *c = &cases[k];
        int fam = k % HARD_PART3A_FAMILIES;
        bool want_hit = (k / HARD_PART3A_FAMILIES) % 2 == 0;
        gen3a(&s, fam, want_hit, &c->sphere, &c->ray);
        draw_family(c->family, fam3a[fam]);
        c->expect = oracle_sphere(&c->sphere, &c->ray);
    }
    return max > 0 ? max : 0;
}

/* ---- Part 3b ------------------------------------------------------------- */

static const char *const fam3b[HARD_PART3B_FAMILIES] = {
    "spheres touching where the ray enters",
    "nested spheres, eye outside",
    "eye inside a big sphere",
    "far small sphere before a huge one",
    "sphere behind the eye, one ahead",
    "nearly coincident spheres",
};

static Sphere make_sphere(Vec3 c, double R, int k)
{
    Sphere sp = { c, R, vec3(0.2 * (k + 1), 1 - 0.2 * (k + 1), 0.5) };
    return sp;
}

int hard_part3b(uint64_t seed, HardCase3b *cases, int max)
{
    for (int k = 0; k < max; k++) {
        uint64_t s = draw_stream(seed, 4, k);
        HardCase3b *c = &cases[k];
        int fam = k % HARD_PART3B_FAMILIES;
        bool even = (k / HARD_PART3B_FAMILIES) % 2 == 0;
        memset(c, 0, sizeof *c);
        draw_family(c->family, fam3b[fam]);

        /* A pixel of a large image, from the oracle's Parts 1 and 2. */
        int nx = draw_int(&s, 1, 1000000), ny = draw_int(&s, 1, 1000000);
        double w, h, d = draw_uni(&s, 0.5, 2);
        oracle_image_plane(draw_uni(&s, 20, 120), (double)nx / ny, d, &w, &h);
        c->eye = vec3(0, 0, 0);
        int j = draw_int(&s, 0, ny - 1), i = draw_int(&s, 0, nx - 1);
        c->pixel = oracle_pixel(i, j, nx, ny, w, h, d);
        c->background = vec3(0, 0, 0);
        c->ray.origin = c->eye;
        c->ray.direction = oracle_unit(vec3_sub(c->pixel, c->eye));
        Vec3 r = c->ray.direction;

        double t0 = draw_uni(&s, 2, 20), R1 = draw_uni(&s, 0.5, 2);
        Vec3 p = vec3_scale(r, t0);                         /* a point ahead */
        c->nspheres = fam == 0 ? 3 : 2;
        switch (fam) {
        case 0: {       /* both entered at p; odd: the second one 1e-6 sooner (even rounds) or
                           later (odd rounds); a third one on the ray beyond both */
            double R2 = R1 * draw_uni(&s, 1.2, 3);
            int round = k / (2 * HARD_PART3B_FAMILIES);
            double shift = even ? 0 : R2 * 1e-6 * (round % 2 ? 1 : -1);
            c->spheres[0] = make_sphere(vec3_add(p, vec3_scale(r, R1)), R1, 0);
            c->spheres[1] = make_sphere(vec3_add(p, vec3_scale(r, R2 + shift)), R2, 1);
            Vec3 beyond = vec3_add(p, vec3_scale(r, 2 * R2 + draw_uni(&s, 2, 4) * R1));
            double across = draw_uni(&s, 0, 0.9) * R1;
            c->spheres[2] = make_sphere(vec3_add(beyond, vec3_scale(draw_perp(&s, r), across)), R1, 2);
            break;
        }
        case 1: {       /* a small sphere inside a big one, on the ray: listed first (even) or last */
            double R2 = R1 * draw_uni(&s, 2, 4);
            Vec3 cb = vec3_add(p, vec3_scale(r, R2));
            /* at most (R2 - R1) / 2 along the ray and 0.8 R1 across it from
             * cb: inside the big one (R1 <= R2 - R1), and hit */
            double across = draw_uni(&s, 0, 0.8) * R1;
            Vec3 side = vec3_scale(draw_perp(&s, r), across);
            Vec3 cs = vec3_add(vec3_add(cb, vec3_scale(r, draw_uni(&s, -0.5, 0.5) * (R2 - R1))), side);
            c->spheres[even ? 0 : 1] = make_sphere(cs, R1, even ? 0 : 1);
            c->spheres[even ? 1 : 0] = make_sphere(cb, R2, even ? 1 : 0);
            break;
        }
        case 2: {       /* inside a room of radius 50: a sphere before or beyond its wall */
            c->spheres[0] = make_sphere(draw_point(&s, 5), 50, 0);
            double along = even ? draw_uni(&s, 5, 30) : draw_uni(&s, 70, 90);
            double across = draw_uni(&s, 0, 0.9) * R1;
            c->spheres[1] = make_sphere(vec3_add(vec3_scale(r, along), vec3_scale(draw_perp(&s, r), across)), R1, 1);
            break;
        }
        case 3: {       /* D/R = 1e6 before a huge sphere */
            double D = R1 * 1e6;
            double across = (even ? draw_uni(&s, 0, 0.95) : draw_uni(&s, 1.05, 2)) * R1;
            Vec3 cs = vec3_add(vec3_scale(r, D), vec3_scale(draw_perp(&s, r), across));
            c->spheres[0] = make_sphere(vec3_scale(r, 3 * D), D, 0);
            c->spheres[1] = make_sphere(cs, R1, 1);
            break;
        }
        case 4: {       /* a big sphere behind, a small one ahead (hit or missed) */
            double big = draw_uni(&s, 1, 2.5);
            c->spheres[0] = make_sphere(vec3_scale(r, -draw_uni(&s, 3, 10)), big, 0);
            double across = (even ? draw_uni(&s, 0, 0.9) : draw_uni(&s, 1.1, 2)) * R1;
            Vec3 off = vec3_scale(draw_perp(&s, r), across);
            c->spheres[1] = make_sphere(vec3_add(p, off), R1, 1);
            break;
        }
        default: {      /* one centre and radius, and its neighbour by an ulp */
            double across = draw_uni(&s, 0, 0.9) * R1;
            Vec3 c0 = vec3_add(p, vec3_scale(draw_perp(&s, r), across));
            Vec3 c1 = c0;
            c1.x = nextafter(c1.x, INFINITY);
            c->spheres[0] = make_sphere(c0, R1, 0);
            c->spheres[1] = make_sphere(c1, even ? R1 : nextafter(R1, 0), 1);
            break;
        }
        }
        Scene scene = hard_scene3b(c);
        c->closest = oracle_closest(&scene, &c->ray, &c->ambiguous, &c->alternative);
    }
    return max > 0 ? max : 0;
}

Scene hard_scene3b(HardCase3b *c)
{
    Scene scene = { .nx = 1, .ny = 1, .fov_degrees = 60, .d = 1, .eye = c->eye, .background = c->background,
                    .spheres = c->spheres, .nspheres = c->nspheres };
    return scene;
}

bool hard_check3b_ray(const HardCase3b *c, Ray got)
{
    double tol = HARD_PART3B_DIR_TOL_U * ORACLE_U;
    return got.origin.x == c->eye.x && got.origin.y == c->eye.y && got.origin.z == c->eye.z
        && fabs(got.direction.x - c->ray.direction.x) <= tol
        && fabs(got.direction.y - c->ray.direction.y) <= tol
        && fabs(got.direction.z - c->ray.direction.z) <= tol;
}

static bool same_color(Vec3 a, Vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

static Vec3 color_of(const HardCase3b *c, int index)
{
    return index < 0 ? c->background : c->spheres[index].color;
}

bool hard_check3b_color(const HardCase3b *c, Vec3 got)
{
    return same_color(got, color_of(c, c->closest))
        || (c->ambiguous && same_color(got, color_of(c, c->alternative)));
}
