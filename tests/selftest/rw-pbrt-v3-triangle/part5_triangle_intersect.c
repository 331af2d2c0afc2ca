/* Part 5 after pbrt-v3's Triangle::Intersect (shapes/triangle.cpp), Float
 * taken as double: the vertices relative to the origin, permuted so that
 * kz is the largest |r| component (kx = kz + 1, ky = kx + 1, mod 3), and
 * sheared with Sx = -d.x / d.z, Sy = -d.y / d.z, Sz = 1 / d.z; edge
 * functions e0 = p1.x p2.y - p1.y p2.x, e1 = p2.x p0.y - p2.y p0.x,
 * e2 = p0.x p1.y - p0.y p1.x; a miss when they have mixed signs or
 * det = e0 + e1 + e2 = 0; tScaled = e0 p0.z + e1 p1.z + e2 p2.z (z scaled
 * by Sz), a miss when its sign is not det's (or it is 0); t = tScaled /
 * det, a miss when t <= deltaT, the book's conservative bound on t's
 * error, with gamma(n) = n eps / (1 - n eps), eps = DBL_EPSILON / 2. */
#include "raytracer.h"

static double gamma_n(int n)
{
    const double eps = DBL_EPSILON * 0.5;
    return (n * eps) / (1 - n * eps);
}

static double max3(double a, double b, double c)
{
    return fmax(a, fmax(b, c));
}

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 q0 = vec3_sub(tri->a, ray->origin);
    Vec3 q1 = vec3_sub(tri->b, ray->origin);
    Vec3 q2 = vec3_sub(tri->c, ray->origin);
    double dv[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    double ad[3] = { fabs(dv[0]), fabs(dv[1]), fabs(dv[2]) };
    int kz = ad[0] > ad[1] ? (ad[0] > ad[2] ? 0 : 2) : (ad[1] > ad[2] ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    double a0[3] = { q0.x, q0.y, q0.z }, a1[3] = { q1.x, q1.y, q1.z }, a2[3] = { q2.x, q2.y, q2.z };
    double p0x = a0[kx], p0y = a0[ky], p0z = a0[kz];
    double p1x = a1[kx], p1y = a1[ky], p1z = a1[kz];
    double p2x = a2[kx], p2y = a2[ky], p2z = a2[kz];
    double Sx = -dv[kx] / dv[kz], Sy = -dv[ky] / dv[kz], Sz = 1 / dv[kz];
    p0x += Sx * p0z;
    p0y += Sy * p0z;
    p1x += Sx * p1z;
    p1y += Sy * p1z;
    p2x += Sx * p2z;
    p2y += Sy * p2z;
    double e0 = p1x * p2y - p1y * p2x;
    double e1 = p2x * p0y - p2y * p0x;
    double e2 = p0x * p1y - p0y * p1x;
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0))
        return false;
    double det = e0 + e1 + e2;
    if (det == 0)
        return false;
    p0z *= Sz;
    p1z *= Sz;
    p2z *= Sz;
    double tScaled = e0 * p0z + e1 * p1z + e2 * p2z;
    if (det < 0 && tScaled >= 0)
        return false;
    if (det > 0 && tScaled <= 0)
        return false;
    double invDet = 1 / det;
    double root = tScaled * invDet;
    double maxZt = max3(fabs(p0z), fabs(p1z), fabs(p2z));
    double deltaZ = gamma_n(3) * maxZt;
    double maxXt = max3(fabs(p0x), fabs(p1x), fabs(p2x));
    double maxYt = max3(fabs(p0y), fabs(p1y), fabs(p2y));
    double deltaX = gamma_n(5) * (maxXt + maxZt);
    double deltaY = gamma_n(5) * (maxYt + maxZt);
    double deltaE = 2 * (gamma_n(2) * maxXt * maxYt + deltaY * maxXt + deltaX * maxYt);
    double maxE = max3(fabs(e0), fabs(e1), fabs(e2));
    double deltaT = 3 * (gamma_n(3) * maxE * maxZt + deltaE * maxZt + deltaZ * maxE) * fabs(invDet);
    if (root <= deltaT)
        return false;
    *t = root;
    return true;
}
