/* Self-test of the grader: hostile-segfault. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    (void)sphere; (void)ray;
    volatile double *p = 0;
    *t = *p;
    return true;
}
