/*
 * contract.h - the contract's functions (labs/raytracer.h), each with the
 * part that grades it, and the parts' stage files: the one table that the
 * grader's build, its link messages and the runners' loader read.
 */
#ifndef GRADER_CONTRACT_H
#define GRADER_CONTRACT_H

/* The stage files' names without ".c", in the parts' order (grader.h's
 * PART1, PART2, PART3A, PART3B, PART4, PART5). */
#define CONTRACT_STAGE_NAMES                                                              \
    "part1_image_plane", "part2_pixel_coordinates", "part3a_sphere_intersect",            \
    "part3b_ray_color", "part4_plane_intersect", "part5_triangle_intersect"

/* X(function, part) for each function, part counted from 0 as above: the
 * function is defined in CONTRACT_STAGE_NAMES[part]'s file. */
#define CONTRACT_FUNCTIONS(X)                                                             \
    X(image_plane_size, 0)                                                                \
    X(pixel_coordinates, 1)                                                               \
    X(sphere_intersect, 2)                                                                \
    X(camera_ray, 3)                                                                      \
    X(ray_color, 3)                                                                       \
    X(plane_intersect, 4)                                                                 \
    X(triangle_intersect, 5)

#endif
