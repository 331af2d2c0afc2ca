/*
 * vec3.h - small vector helpers, in the spirit of glMatrix's vec3.
 * Include raytracer.h, which includes this file after defining Vec3.
 *
 * Every helper takes and returns Vec3 by value: write
 *     Vec3 f = vec3_sub(ray->origin, sphere->center);
 *     double B = vec3_dot(f, ray->direction);
 */
#ifndef VEC3_H
#define VEC3_H

#include "raytracer.h"

/* (x, y, z) */
static inline Vec3 vec3(double x, double y, double z)
{
    Vec3 v = { x, y, z };
    return v;
}

/* a + b */
static inline Vec3 vec3_add(Vec3 a, Vec3 b)
{
    return vec3(a.x + b.x, a.y + b.y, a.z + b.z);
}

/* a - b */
static inline Vec3 vec3_sub(Vec3 a, Vec3 b)
{
    return vec3(a.x - b.x, a.y - b.y, a.z - b.z);
}

/* s a, for a number s */
static inline Vec3 vec3_scale(Vec3 a, double s)
{
    return vec3(s * a.x, s * a.y, s * a.z);
}

/* -a */
static inline Vec3 vec3_negate(Vec3 a)
{
    return vec3(-a.x, -a.y, -a.z);
}

/* a . b */
static inline double vec3_dot(Vec3 a, Vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* a x b (right-handed) */
static inline Vec3 vec3_cross(Vec3 a, Vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y,
                a.z * b.x - a.x * b.z,
                a.x * b.y - a.y * b.x);
}

/* |a| */
static inline double vec3_length(Vec3 a)
{
    return sqrt(vec3_dot(a, a));
}

/* a / |a|, the unit vector along a.  The zero vector stays zero (as in
 * glMatrix), so a caller never sees a NaN it did not bring. */
static inline Vec3 vec3_normalize(Vec3 a)
{
    double len = vec3_length(a);
    return len > 0 ? vec3_scale(a, 1 / len) : a;
}

#endif
