/* Part 5 after GLM's intersectRayTriangle (gtx/intersect.inl, 0.9.9), in
 * double: edge1 = v1 - v0, edge2 = v2 - v0, p = dir x edge2, det =
 * edge1 . p.  det > epsilon: dist = orig - v0, u = dist . p, no hit when
 * u < 0 or u > det; q = dist x edge1, v = dir . q, no hit when v < 0 or
 * u + v > det.  det < -epsilon: the same with every comparison turned
 * round.  Otherwise parallel: no hit.  distance = edge2 . q / det, and the
 * function returns true (it does not look at the distance's sign).
 * epsilon is std::numeric_limits<double>::epsilon(). */
#include "raytracer.h"

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 edge1 = vec3_sub(tri->b, tri->a);
    Vec3 edge2 = vec3_sub(tri->c, tri->a);
    Vec3 p = vec3_cross(ray->direction, edge2);
    double det = vec3_dot(edge1, p);
    Vec3 q;
    if (det > DBL_EPSILON) {
        Vec3 dist = vec3_sub(ray->origin, tri->a);
        double u = vec3_dot(dist, p);
        if (u < 0 || u > det)
            return false;
        q = vec3_cross(dist, edge1);
        double v = vec3_dot(ray->direction, q);
        if (v < 0 || u + v > det)
            return false;
    } else if (det < -DBL_EPSILON) {
        Vec3 dist = vec3_sub(ray->origin, tri->a);
        double u = vec3_dot(dist, p);
        if (u > 0 || u < det)
            return false;
        q = vec3_cross(dist, edge1);
        double v = vec3_dot(ray->direction, q);
        if (v > 0 || u + v < det)
            return false;
    } else {
        return false;
    }
    double inv_det = 1 / det;
    *t = vec3_dot(edge2, q) * inv_det;
    return true;
}
