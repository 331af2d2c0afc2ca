/* Self-test of the grader: p5-edge-behind. The watertight test, with strict
 * signs on the side met from behind (U < 0 && V < 0 && W < 0). */
#include "raytracer.h"

/*
 * triangle_intersect - the point, ahead of the ray's origin, where the ray
 *                      x(t) = e + t r meets the triangle with vertices
 *                      a, b, c.
 *
 * Parameters:
 *   tri          the vertices a, b, c, in either winding order
 *   ray          origin e and direction r; r need NOT have unit length
 *   t            out: on a hit, the t > 0 at which e + t r is in the
 *                triangle
 * Returns:       true on a hit (and stores *t), false on a miss (*t unused).
 *                Both sides count. Edges and vertices belong to the
 *                triangle. A ray parallel to the triangle's plane or lying
 *                in it, a triangle behind e, a zero-area triangle, a zero
 *                direction and NaN input are misses.
 *                The hard-case challenge: be watertight, so that a ray
 *                through an edge or vertex that triangles share hits at
 *                least one of them.
 * Example:       a = (-1, -1, -4), b = (1, -1, -4), c = (0, 1, -4),
 *                e = (0, 0, 0), r = (0, 0, -2): the ray meets the plane
 *                z = -4 at t = 2, the point (0, 0, -4) = a + 0.25 (b - a)
 *                + 0.5 (c - a), inside the triangle: *t = 2.
 * Formula:       e + t r = a + beta (b - a) + gamma (c - a), three equations
 *                in t, beta, gamma.  With e1 = b - a, e2 = c - a, s = e - a,
 *                q = r x e2 and det = e1.q (Cramer's rule, as Moller and
 *                Trumbore write it):
 *                beta = s.q / det,  gamma = r.(s x e1) / det,
 *                t = e2.(s x e1) / det;  no hit when det = 0;  a hit when
 *                beta >= 0, gamma >= 0, beta + gamma <= 1 and t > 0.
 */
bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    /* The watertight test of Woop, Benthin and Wald (JCGT 2013), as pbrt-v4
     * writes it, with exact signs.
     *
     * 1. Look along the ray.  Relabel the axes so that z is the one along
     *    which r is longest (kz), then shear the vertices, taken relative to
     *    e, so that the ray becomes the +z axis: a vertex P goes to
     *    (P.x - Sx P.z, P.y - Sy P.z), Sx = r.x / r.z, Sy = r.y / r.z.  The
     *    ray meets the triangle when the sheared triangle covers (0, 0).
     * 2. That is three 2-d edge tests, one per edge PQ: the sign of
     *    Q.x P.y - Q.y P.x says on which side of the edge (0, 0) lies.  Two
     *    triangles that share an edge shear its two vertices to the same
     *    points, since a vertex's image depends on the vertex and the ray
     *    alone; as the edge values below get every sign exactly right, the
     *    sheared mesh is a true planar picture and (0, 0), on an edge or a
     *    vertex, is inside at least one of the triangles that share it.
     *    Moller-Trumbore rounds each triangle's barycentric coordinates on
     *    its own, so (0, 0) can fall between two neighbours: a crack.
     * 3. The edge values U, V, W are the barycentric coordinates times
     *    det = U + V + W, and t is their weighted mean of the vertices'
     *    depths along the ray. */
    const Vec3 o = ray->origin, r = ray->direction;
    const double d[3] = { r.x, r.y, r.z };
    int kz = fabs(d[0]) > fabs(d[1]) ? 0 : 1;
    if (fabs(d[2]) > fabs(d[kz]))
        kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) {                    /* keep the winding: swap x and y */
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    const double Sx = d[kx] / d[kz], Sy = d[ky] / d[kz];  /* NaN for r = 0 */

    /* The vertices relative to e, relabelled, then sheared. */
    Vec3 A3 = vec3_sub(tri->a, o), B3 = vec3_sub(tri->b, o), C3 = vec3_sub(tri->c, o);
    const double A[3] = { A3.x, A3.y, A3.z }, B[3] = { B3.x, B3.y, B3.z },
                 C[3] = { C3.x, C3.y, C3.z };
    const double Ax = A[kx] - Sx * A[kz], Ay = A[ky] - Sy * A[kz];
    const double Bx = B[kx] - Sx * B[kz], By = B[ky] - Sy * B[kz];
    const double Cx = C[kx] - Sx * C[kz], Cy = C[ky] - Sy * C[kz];

    /* The edge values, U for the edge BC, V for CA, W for AB: for the edge
     * PQ, Q.x P.y - Q.y P.x.  When that difference is larger than 4 u times
     * the sum of its two products it has the sign of the exact value; when
     * it is not (rarely: the ray passes within rounding of the edge),
     * Kahan's difference of products recomputes it with fma, whose
     * relative error is at most 2 u, so the sign is exact there too (and 0
     * exactly when the exact value is 0).  This holds while the products
     * stay in double's normal range. */
    double U = Cx * By - Cy * Bx;
    if (!(fabs(U) > 0x1p-51 * (fabs(Cx * By) + fabs(Cy * Bx))))
        U = fma(Cx, By, -(Cy * Bx)) + fma(-Cy, Bx, Cy * Bx);
    double V = Ax * Cy - Ay * Cx;
    if (!(fabs(V) > 0x1p-51 * (fabs(Ax * Cy) + fabs(Ay * Cx))))
        V = fma(Ax, Cy, -(Ay * Cx)) + fma(-Ay, Cx, Ay * Cx);
    if ((U < 0 && V > 0) || (U > 0 && V < 0))   /* most misses end here */
        return false;
    double W = Bx * Ay - By * Ax;
    if (!(fabs(W) > 0x1p-51 * (fabs(Bx * Ay) + fabs(By * Ax))))
        W = fma(Bx, Ay, -(By * Ax)) + fma(-By, Ax, By * Ax);
    /* Inside (edges and vertices included) when the three signs agree,
     * from either side; NaN fails both tests. */
    if (!((U >= 0 && V >= 0 && W >= 0) || (U < 0 && V < 0 && W < 0)))
        return false;
    const double det = U + V + W;
    if (det == 0)                       /* parallel, in the plane, zero area */
        return false;

    /* t = (U A.z + V B.z + W C.z) / (det r.z), the depths along the
     * ray's own axis, weighted by the barycentric coordinates. */
    const double T = U * A[kz] + V * B[kz] + W * C[kz];
    const double root = T / (det * d[kz]);
    if (!(root > 0 && root < INFINITY)) /* behind e, or NaN */
        return false;
    *t = root;
    return true;
}
