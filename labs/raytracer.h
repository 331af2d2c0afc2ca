/*
 * raytracer.h - the lab's contract: the types and the functions you write
 * (five in Parts 1-3b; one more in each of the optional Parts 4 and 5).
 *
 * Conventions (the lecture's):
 *   - The eye e is at the origin, looking down -z; the image plane is at z = -d.
 *   - fov_degrees is the VERTICAL field of view in degrees, 0 < fov < 180;
 *     aspect = nx / ny.
 *   - Pixel (i, j): i is the column counted from the left, j the row counted
 *     from the top, both 0-based.
 *   - A ray is x(t) = e + t r: origin e, direction r (not always unit length).
 *   - Colours are Vec3 with components in [0, 1].
 *
 * The vector helpers you may use (vec3_add, vec3_sub, vec3_scale, vec3_dot,
 * vec3_length, vec3_normalize, ...) are in vec3.h, included below.
 */
#ifndef RAYTRACER_H
#define RAYTRACER_H

#include <float.h>
#include <math.h>
#include <stdbool.h>

/* M_PI is POSIX, not ISO C: -std=c11 hides it on some systems. */
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct { double x, y, z; } Vec3;
typedef struct { Vec3 origin, direction; } Ray;            /* x(t) = e + t r   */
typedef struct { Vec3 center; double radius; Vec3 color; } Sphere;
typedef struct { Vec3 point, normal; Vec3 color; } Plane;     /* (x - point).normal = 0 */
typedef struct { Vec3 a, b, c; Vec3 color; } Triangle;

typedef struct {
    int nx, ny;            /* image size in pixels (columns, rows)           */
    double fov_degrees;    /* vertical field of view, degrees, 0 < fov < 180 */
    double d;              /* distance from the eye to the image plane, > 0  */
    Vec3 eye;              /* always the origin in this lab                  */
    Vec3 background;       /* colour of rays that hit nothing                */
    Sphere *spheres;
    int nspheres;
    Plane *planes;         /* Part 4's planes and Part 5's triangles: a scene */
    int nplanes;           /* with none of them is drawn by Parts 1-3b alone  */
    Triangle *triangles;
    int ntriangles;
} Scene;

#include "vec3.h"

/* Part 1  (part1_image_plane.c) */
void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h);

/* Part 2  (part2_pixel_coordinates.c) */
Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d);

/* Part 3a (part3a_sphere_intersect.c) */
bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t);

/* Part 3b (part3b_ray_color.c) */
Ray  camera_ray(Vec3 eye, Vec3 pixel);
Vec3 ray_color(const Scene *scene, const Ray *ray);

/* Part 4  (part4_plane_intersect.c), optional */
bool plane_intersect(const Plane *plane, const Ray *ray, double *t);

/* Part 5  (part5_triangle_intersect.c), optional */
bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t);

#endif
