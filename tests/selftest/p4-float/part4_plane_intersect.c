/* Self-test of the grader: p4-float. Computes in float. */
#include "raytracer.h"

bool plane_intersect(const Plane *plane, const Ray *ray, double *t)
{
    float nx = (float)plane->normal.x, ny = (float)plane->normal.y, nz = (float)plane->normal.z;
    float rn = (float)ray->direction.x * nx + (float)ray->direction.y * ny + (float)ray->direction.z * nz;
    float num = ((float)plane->point.x - (float)ray->origin.x) * nx
              + ((float)plane->point.y - (float)ray->origin.y) * ny
              + ((float)plane->point.z - (float)ray->origin.z) * nz;
    if (rn == 0)
        return false;
    float t0 = num / rn;
    if (!(t0 > 0))
        return false;
    *t = t0;
    return true;
}
