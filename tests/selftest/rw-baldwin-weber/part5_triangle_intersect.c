/* Self-test of the grader: rw-baldwin-weber (NOTE.md).  Baldwin and
 * Weber's ray/triangle test: a matrix per triangle takes a point to its
 * barycentric coordinates and its height off the plane; no epsilon
 * anywhere.  Here in double, the matrix made for each call. */
#include "raytracer.h"

/* The paper's 12 numbers: rows 1 and 2 give the barycentric coordinates
 * b1, b2 of a point of the plane, row 3 (with the 1 in the column of the
 * normal's largest component) its height off the plane. */
static bool bw_matrix(const Triangle *tri, double T[12])
{
    Vec3 p0 = tri->a, p1 = tri->b, p2 = tri->c;
    Vec3 e1 = vec3_sub(p1, p0), e2 = vec3_sub(p2, p0), n = vec3_cross(e1, e2);
    double num = vec3_dot(p0, n), x1, x2;
    if (fabs(n.x) > fabs(n.y) && fabs(n.x) > fabs(n.z)) {
        x1 = p1.y * p0.z - p1.z * p0.y;
        x2 = p2.y * p0.z - p2.z * p0.y;
        T[0] = 0, T[1] = e2.z / n.x, T[2] = -e2.y / n.x, T[3] = x2 / n.x;
        T[4] = 0, T[5] = -e1.z / n.x, T[6] = e1.y / n.x, T[7] = -x1 / n.x;
        T[8] = 1, T[9] = n.y / n.x, T[10] = n.z / n.x, T[11] = -num / n.x;
    } else if (fabs(n.y) > fabs(n.z)) {
        x1 = p1.z * p0.x - p1.x * p0.z;
        x2 = p2.z * p0.x - p2.x * p0.z;
        T[0] = -e2.z / n.y, T[1] = 0, T[2] = e2.x / n.y, T[3] = x2 / n.y;
        T[4] = e1.z / n.y, T[5] = 0, T[6] = -e1.x / n.y, T[7] = -x1 / n.y;
        T[8] = n.x / n.y, T[9] = 1, T[10] = n.z / n.y, T[11] = -num / n.y;
    } else if (fabs(n.z) > 0) {
        x1 = p1.x * p0.y - p1.y * p0.x;
        x2 = p2.x * p0.y - p2.y * p0.x;
        T[0] = e2.y / n.z, T[1] = -e2.x / n.z, T[2] = 0, T[3] = x2 / n.z;
        T[4] = -e1.y / n.z, T[5] = e1.x / n.z, T[6] = 0, T[7] = -x1 / n.z;
        T[8] = n.x / n.z, T[9] = n.y / n.z, T[10] = 1, T[11] = -num / n.z;
    } else {
        return false;                   /* no area */
    }
    return true;
}

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    double T[12];
    if (!bw_matrix(tri, T))
        return false;
    Vec3 o = ray->origin, d = ray->direction;
    double transS = T[8] * o.x + T[9] * o.y + T[10] * o.z + T[11];
    double transD = T[8] * d.x + T[9] * d.y + T[10] * d.z;
    double ta = -transS / transD;
    if (ta <= 0 || ta >= INFINITY)
        return false;
    Vec3 wr = vec3_add(o, vec3_scale(d, ta));
    double xg = T[0] * wr.x + T[1] * wr.y + T[2] * wr.z + T[3];
    double yg = T[4] * wr.x + T[5] * wr.y + T[6] * wr.z + T[7];
    if (xg >= 0 && yg >= 0 && xg + yg <= 1) {
        *t = ta;
        return true;
    }
    return false;
}
