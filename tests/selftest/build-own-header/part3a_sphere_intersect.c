/* Part 3a, with a helper from a header of the student's own. */
#include "raytracer.h"
#include "myvec.h"

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    Vec3 f = vec3_sub(ray->origin, sphere->center), r = ray->direction;
    double A = my_dot(r, r), B = my_dot(f, r);
    double C = my_dot(f, f) - sphere->radius * sphere->radius;
    double disc = B * B - A * C;
    if (!(A > 0) || !(disc >= 0))
        return false;
    double s = sqrt(disc), t1 = (-B - s) / A, t2 = (-B + s) / A;
    if (t1 > 0)
        *t = t1;
    else if (t2 > 0)
        *t = t2;
    else
        return false;
    return true;
}
