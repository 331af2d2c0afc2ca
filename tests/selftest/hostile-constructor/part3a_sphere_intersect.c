/* Self-test of the grader: hostile-constructor. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <stdio.h>
#include <unistd.h>

__attribute__((constructor)) static void before_main(void)
{
    /* write fake answers on the answer descriptor, then leave */
    dprintf(3, "1 0x1p+1\nend 1\n");
    dprintf(1, "Score: 100 / 100\n");
    close(3);
    _exit(0);
}

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    (void)sphere; (void)ray; (void)t;
    return false;
}
