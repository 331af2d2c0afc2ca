/*
 * methods.c - the ray/sphere formulations, each in double and in float.
 * The bodies are in methods_body.h, written once for both precisions, so
 * the double and float versions cannot drift apart.
 *
 * Each is an ordinary external function, called through a pointer from the
 * closest-hit loop in suite.c: the same call the lab makes from ray_color
 * (part 3b) to sphere_intersect (part 3a), so no method is inlined into the
 * loop and the linked reference is timed on equal terms.
 */
#include <float.h>
#include <math.h>
#include "bench.h"

Vec3f vec3f_from(Vec3 v)
{
    Vec3f f = { (float)v.x, (float)v.y, (float)v.z };
    return f;
}

Spheref spheref_from(const Sphere *s)
{
    Spheref f = { vec3f_from(s->center), (float)s->radius };
    return f;
}

Rayf rayf_from(const Ray *r)
{
    Rayf f = { vec3f_from(r->origin), vec3f_from(r->direction) };
    return f;
}

#define REAL double
#define VEC Vec3
#define SPHERE Sphere
#define RAY Ray
#define TRI Triangle
#define SQRT sqrt
#define COPYSIGN copysign
#define TINY DBL_MIN
#define SAFE_LO 0x1p-900
#define SAFE_HI 0x1p+900
#define NAME(x) x##_d
#include "methods_body.h"

#define REAL float
#define VEC Vec3f
#define SPHERE Spheref
#define RAY Rayf
#define TRI Trianglef
#define SQRT sqrtf
#define COPYSIGN copysignf
#define TINY FLT_MIN
#define SAFE_LO 0x1p-100f
#define SAFE_HI 0x1p+100f
#define NAME(x) x##_f
#include "methods_body.h"

/* Which test of the reference decides a (sphere, ray) pair: stage_d, the
 * first lines of isect_reference_d (solutions/part3a_sphere_intersect.c).  REF_STAGE_NX, _NXY and _NN: the partial sum of |f x r|^2 after
 * one, two and three terms exceeded T (a miss); REF_STAGE_ROOTS: the line
 * meets the sphere and A R^2 is in range, so the reference goes on to the
 * roots; REF_STAGE_CAREFUL: A R^2 out of range (or NaN), the careful
 * branch.  The benchmark checks the first three against sphere_intersect. */
int reference_stage(const Sphere *sphere, const Ray *ray)
{
    Vec3 r = ray->direction;
    Vec3 f = sub_d(ray->origin, sphere->center);
    double nn;
    return stage_d(f, r, dot_d(r, r) * (sphere->radius * sphere->radius), &nn);
}
