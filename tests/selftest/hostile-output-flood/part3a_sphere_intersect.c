/* Self-test of the grader: hostile-output-flood. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <stdio.h>

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    (void)sphere; (void)ray; (void)t;
    for (long k = 0; k < 100000000; k++)
        printf("Score: 100/100 -- all tests passed, spam spam spam spam spam spam\n");
    return false;
}
