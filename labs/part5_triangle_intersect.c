/* Part 5 (optional): where a ray meets a triangle. */
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
    /* TODO Part 5: solve for t, beta and gamma; check them. */
    (void)tri;
    (void)ray;
    (void)t;
    return false;
}
