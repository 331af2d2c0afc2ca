/*
 * draw.h - random draws shared by the hard-case generators (draw.c).
 * Each case draws from its own stream, draw_stream(seed, part, k), so a
 * case depends only on (seed, part, k).
 */
#ifndef DRAW_H
#define DRAW_H

#include <stdint.h>
#include "hard.h"

uint64_t draw_stream(uint64_t seed, uint64_t part, int k);
double draw_uni(uint64_t *s, double a, double b);       /* uniform in [a, b)               */
int draw_int(uint64_t *s, int a, int b);                /* uniform integer in [a, b]       */
double draw_log(uint64_t *s, double a, double b);       /* about log-uniform, 0 < a < b    */
Vec3 draw_unit(uint64_t *s);                            /* a random unit vector            */
Vec3 draw_perp(uint64_t *s, Vec3 a);                    /* a unit vector perpendicular to a */
Vec3 draw_point(uint64_t *s, double size);              /* coordinates in [-size, size]    */
/* A direction from e that passes the centre c at rho R, of length len. */
Vec3 draw_aim(uint64_t *s, Vec3 e, Vec3 c, double R, double rho, double len);
double draw_len(uint64_t *s);                           /* 1/16 .. 16, not a power of two  */
void draw_family(char *dst, const char *name);          /* copies a family's name          */

#endif
