/*
 * draw.c - the random draws of the hard-case generators (hard.c, hard_flat.c):
 * splitmix64 streams and the shapes drawn from them.  Only + - * / sqrt
 * ldexp frexp are used, and each draw is a statement of its own (C leaves
 * the order of a call's arguments open: gcc evaluates them last first,
 * clang first first), so the same seed gives the same numbers on every
 * IEEE-754 machine and compiler (built with -ffp-contract=off).  The
 * callers keep that rule too (hard.c, hard_flat.c, hidden.c), drawing in
 * the order gcc did when the public tests were written.  What each draw
 * gives is said in draw.h.
 */
#include <stdio.h>
#include "draw.h"

/* ---- random numbers (splitmix64) ----------------------------------------- */

uint64_t hard_rng_next(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

double hard_rng_uniform(uint64_t *state)
{
    return (double)(hard_rng_next(state) >> 11) * 0x1p-53;
}

uint64_t draw_stream(uint64_t seed, uint64_t part, int k)
{
    uint64_t s = seed ^ (part * 0xD1B54A32D192ED03u);
    uint64_t mixed = hard_rng_next(&s) ^ ((uint64_t)k * 0x632BE59BD9B4E019u);
    hard_rng_next(&mixed);
    return mixed;
}

double draw_uni(uint64_t *s, double a, double b)
{
    return a + (b - a) * hard_rng_uniform(s);
}

int draw_int(uint64_t *s, int a, int b)
{
    return a + (int)(hard_rng_next(s) % (uint64_t)(b - a + 1));
}

/* Roughly log-uniform in [a, b], 0 < a < b: a random binade, a random
 * significand, redrawn until inside.  No libm: the same on every machine. */
double draw_log(uint64_t *s, double a, double b)
{
    int ea, eb;
    frexp(a, &ea);
    frexp(b, &eb);
    for (;;) {
        int binade = draw_int(s, ea - 1, eb - 1);
        double x = ldexp(1 + hard_rng_uniform(s), binade);
        if (x >= a && x <= b)
            return x;
    }
}

/* A random direction: uniform in the unit ball (rejection), normalized. */
Vec3 draw_unit(uint64_t *s)
{
    for (;;) {
        double z = draw_uni(s, -1, 1), y = draw_uni(s, -1, 1), x = draw_uni(s, -1, 1);
        Vec3 v = vec3(x, y, z);
        double n2 = vec3_dot(v, v);
        if (n2 > 0.01 && n2 <= 1)
            return vec3_scale(v, 1 / sqrt(n2));
    }
}

Vec3 draw_perp(uint64_t *s, Vec3 a)
{
    for (;;) {
        Vec3 p = vec3_cross(a, draw_unit(s));
        double n = vec3_length(p);
        if (n > 0.1 * vec3_length(a))
            return vec3_scale(p, 1 / n);
    }
}

Vec3 draw_point(uint64_t *s, double size)
{
    double z = draw_uni(s, -size, size), y = draw_uni(s, -size, size), x = draw_uni(s, -size, size);
    return vec3(x, y, z);
}

Vec3 draw_aim(uint64_t *s, Vec3 e, Vec3 c, double R, double rho, double len)
{
    Vec3 n = draw_perp(s, vec3_sub(c, e));
    Vec3 r = vec3_sub(vec3_add(c, vec3_scale(n, rho * R)), e);
    return vec3_scale(r, len / vec3_length(r));
}

double draw_len(uint64_t *s)
{
    int binade = draw_int(s, -4, 3);
    return ldexp(1 + hard_rng_uniform(s), binade);
}

void draw_family(char *dst, const char *name)
{
    snprintf(dst, HARD_FAMILY_LEN, "%s", name);
}
