/*
 * textbook.h - the lecture's formulas, as most students write them: what
 * the oracle's unit tests set next to the reference and the oracle.  Never
 * used by the oracle itself.
 */
#ifndef TEXTBOOK_H
#define TEXTBOOK_H

#include <math.h>
#include <stdbool.h>
#include "../../labs/raytracer.h"

/* Part 1: h = 2 d tan(fov / 2), in radians. */
static inline void textbook_image_plane(double fov, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov / 2 * M_PI / 180);
    *w = aspect * *h;
}

/* Part 2: -w/2 + w (i + 0.5) / nx, which cancels near the centre. */
static inline Vec3 textbook_pixel(int i, int j, int nx, int ny, double w, double h, double d)
{
    return vec3(-w / 2 + w * (i + 0.5) / nx, -h / 2 + h * (ny - 0.5 - j) / ny, -d);
}

/* Part 3a: B^2 - A C with the quadratic formula, the near root first; a
 * hit is a root t > tmin. */
static inline bool textbook_sphere_above(const Sphere *sp, const Ray *ray, double tmin, double *t)
{
    Vec3 r = ray->direction, f = vec3_sub(ray->origin, sp->center);
    double A = vec3_dot(r, r), B = vec3_dot(f, r);
    double C = vec3_dot(f, f) - sp->radius * sp->radius;
    double disc = B * B - A * C;
    if (!(A > 0) || !(disc >= 0))
        return false;
    *t = (-B - sqrt(disc)) / A;
    if (*t > tmin)
        return true;
    *t = (-B + sqrt(disc)) / A;
    return *t > tmin;
}

#endif
