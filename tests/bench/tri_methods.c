/*
 * tri_methods.c - Part 5's formulations of ray/triangle intersection, for
 * the benchmark (triangles.c), written here apart from solutions/:
 *
 *   moller-trumbore   the skeleton's formula (Moller and Trumbore 1997),
 *                     in double and in float (methods_body.h, written
 *                     once for both): det = 0 a miss, one division;
 *   wbw-plain         Woop, Benthin and Wald's shear-and-project test
 *                     (JCGT 2013) in plain double, without the reference's
 *                     exact edge signs: two triangles that share an edge
 *                     compute its edge function from the same two points,
 *                     so edges hold; at a shared vertex three or more
 *                     rounded edge functions meet, and nothing makes
 *                     their signs agree;
 *   geometric         the plane first, then the hit point against each
 *                     edge (Scratchapixel's "geometric solution"): t's
 *                     error moves the point, so thin slivers defeat it.
 *
 * Each is an ordinary external function, called through a pointer as the
 * linked reference is, so none is inlined into the loop that times it.
 */
#include <math.h>
#include "bench.h"

bool tri_wbw_plain_d(const Triangle *tri, const Ray *ray, double *t)
{
    const double d[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    int kz = fabs(d[0]) > fabs(d[1]) ? 0 : 1;
    if (fabs(d[2]) > fabs(d[kz]))
        kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    const double sx = d[kx] / d[kz], sy = d[ky] / d[kz];
    Vec3 a = vec3_sub(tri->a, ray->origin), b = vec3_sub(tri->b, ray->origin),
         c = vec3_sub(tri->c, ray->origin);
    const double A[3] = { a.x, a.y, a.z }, B[3] = { b.x, b.y, b.z }, C[3] = { c.x, c.y, c.z };
    const double ax = A[kx] - sx * A[kz], ay = A[ky] - sy * A[kz];
    const double bx = B[kx] - sx * B[kz], by = B[ky] - sy * B[kz];
    const double cx = C[kx] - sx * C[kz], cy = C[ky] - sy * C[kz];
    const double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    if (!((u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0)))
        return false;
    const double det = u + v + w;
    if (det == 0)
        return false;
    const double tt = (u * A[kz] + v * B[kz] + w * C[kz]) / (det * d[kz]);
    if (!(tt > 0 && tt < INFINITY))
        return false;
    *t = tt;
    return true;
}

bool tri_geometric_d(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 n = vec3_cross(vec3_sub(tri->b, tri->a), vec3_sub(tri->c, tri->a));
    double dn = vec3_dot(n, ray->direction);
    if (dn == 0)
        return false;
    double tt = vec3_dot(vec3_sub(tri->a, ray->origin), n) / dn;
    if (!(tt > 0 && tt < INFINITY))
        return false;
    Vec3 p = vec3_add(ray->origin, vec3_scale(ray->direction, tt));
    const Vec3 v[3] = { tri->a, tri->b, tri->c };
    for (int k = 0; k < 3; k++)
        if (vec3_dot(n, vec3_cross(vec3_sub(v[(k + 1) % 3], v[k]), vec3_sub(p, v[k]))) < 0)
            return false;
    *t = tt;
    return true;
}
