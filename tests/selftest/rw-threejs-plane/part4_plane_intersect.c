/* Part 4 after three.js Ray.distanceToPlane, with the plane as three.js
 * keeps it (Plane.setFromNormalAndCoplanarPoint): a normal n and a
 * constant = -(p . n).  denominator = n . r; when it is 0 the ray is
 * parallel: t = 0 when the origin lies in the plane (n . e + constant ==
 * 0), else no hit; otherwise t = -(e . n + constant) / denominator, a hit
 * when t >= 0.  JavaScript numbers are doubles. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    Vec3 n = plane->normal;
    double constant = -vec3_dot(plane->point, n);
    double denominator = vec3_dot(n, ray->direction);
    if (denominator == 0) {
        if (vec3_dot(n, ray->origin) + constant == 0) {
            *t = 0;
            return true;
        }
        return false;
    }
    double root = -(vec3_dot(ray->origin, n) + constant) / denominator;
    if (!(root >= 0))
        return false;
    *t = root;
    return true;
}
