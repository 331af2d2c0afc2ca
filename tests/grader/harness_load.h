/*
 * harness_load.h - the harness's side of a part's program built as a
 * prebuilt runner and the student's file as a shared object (Linux; see
 * build.c).  After including raytracer.h, the harness calls the part's
 * functions through these pointers, loaded from the student's object.
 */
#ifndef HARNESS_LOAD_H
#define HARNESS_LOAD_H

#include "raytracer.h"

#include <stddef.h>

extern void (*load_image_plane_size)(double, double, double, double *, double *);
extern Vec3 (*load_pixel_coordinates)(int, int, int, int, double, double, double);
extern bool (*load_sphere_intersect)(const Sphere *, const Ray *, double *);
extern Ray (*load_camera_ray)(Vec3, Vec3);
extern Vec3 (*load_ray_color)(const Scene *, const Ray *);
extern bool (*load_plane_intersect)(const Plane *, const Ray *, double *);
extern bool (*load_triangle_intersect)(const Triangle *, const Ray *, double *);

/* Loads the shared object path for the harness of part (HARNESS_PART:
 * counted from 0, as contract.h counts) and checks what the linker of a whole program would: every
 * symbol it uses is defined (the runner's C library, libm and, with refs,
 * the reference for every other part), it defines its part's functions,
 * and it does not define main or, with refs, another part's function.
 * 0 when it loads; otherwise -1 with the linker's kind of message in why. */
int harness_load(int part, bool refs, const char *path, char *why, size_t whylen);

#define image_plane_size (*load_image_plane_size)
#define pixel_coordinates (*load_pixel_coordinates)
#define sphere_intersect (*load_sphere_intersect)
#define camera_ray (*load_camera_ray)
#define ray_color (*load_ray_color)
#define plane_intersect (*load_plane_intersect)
#define triangle_intersect (*load_triangle_intersect)

#endif
