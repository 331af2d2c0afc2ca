/*
 * public.c - the public tests, shipped to students as tests/public/partN.tests.
 * Every test mixes cases so that no fixed answer (the skeletons' zeros,
 * "always miss", "always the background") passes any of them.
 */
#include "testgen.h"
#include "oracle.h"

#include <stdio.h>

static void part1(TestList *l)
{
    Test *t = tg_test(l, PART1, KIND_PLANE, 1, "Part 1: the worked example (alpha = 90, aspect = 2, d = 1)",
                      "h = 2 d tan(alpha / 2) = 2 tan(45 deg) = 2, w = aspect h = 4");
    tg_plane(t, 90, 2, 1);
    t = tg_test(l, PART1, KIND_PLANE, 1, "Part 1: square images at 60 degrees",
                "alpha = 60: h = 2 d tan(30 deg); aspect 1 gives w = h");
    tg_plane(t, 60, 1, 1);
    tg_plane(t, 60, 1, 3);
    t = tg_test(l, PART1, KIND_PLANE, 2, "Part 1: fields of view from narrow to wide",
                "alpha is in degrees; tan takes radians");
    tg_plane(t, 10, 1.5, 1);
    tg_plane(t, 45, 4.0 / 3, 1);
    tg_plane(t, 120, 16.0 / 9, 2);
    tg_plane(t, 170, 1, 1);
    t = tg_test(l, PART1, KIND_PLANE, 1, "Part 1: the distance d scales the plane",
                "the plane at distance d is d times as large as at distance 1");
    tg_plane(t, 50, 1.25, 0.25);
    tg_plane(t, 50, 1.25, 8);
    tg_plane(t, 75, 2, 100);
    t = tg_test(l, PART1, KIND_PLANE, 1, "Part 1: wide and tall images",
                "aspect = nx / ny; w = aspect h");
    tg_plane(t, 60, 16.0 / 9, 1);
    tg_plane(t, 60, 0.5, 1);
    tg_plane(t, 40, 3.2, 1);
    tg_plane(t, 90, 0.75, 2);
}

static void part2(TestList *l)
{
    Test *t = tg_test(l, PART2, KIND_PIXEL, 1, "Part 2: the worked example (4 x 2 pixels, w = 4, h = 2, d = 1)",
                      "every pixel of a 4 x 2 image: pixel (0, 0) is (-1.5, 0.5, -1)");
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 4; i++)
            tg_pixel(t, i, j, 4, 2, 4, 2, 1);
    t = tg_test(l, PART2, KIND_PIXEL, 1, "Part 2: the four corner pixels of a 640 x 480 image",
                "pixel (0, 0) is at the top left: x < 0 and y > 0");
    double w = 4.0 / 3 * 1.1547005383792515, h = 1.1547005383792515;
    for (int k = 0; k < 4; k++)                 /* top left, top right, bottom left, bottom right */
        tg_pixel(t, k % 2 ? 639 : 0, k / 2 ? 479 : 0, 640, 480, w, h, 1);
    t = tg_test(l, PART2, KIND_PIXEL, 1, "Part 2: odd image sizes and the centre pixel",
                "with nx = 5 the centre column i = 2 has x = 0");
    tg_pixel(t, 2, 1, 5, 3, 5, 3, 1);
    tg_pixel(t, 0, 2, 5, 3, 5, 3, 1);
    tg_pixel(t, 4, 0, 5, 3, 5, 3, 2);
    tg_pixel(t, 0, 0, 1, 1, 2, 2, 1);
    tg_pixel(t, 6, 3, 7, 9, 1.75, 2.25, 0.5);
    t = tg_test(l, PART2, KIND_PIXEL, 1, "Part 2: pixels that are not square, and z = -d",
                "x uses w and nx, y uses h and ny; the plane is at z = -d");
    tg_pixel(t, 3, 5, 8, 8, 4, 1, 1);
    tg_pixel(t, 7, 0, 8, 8, 4, 1, 3);
    tg_pixel(t, 10, 2, 16, 4, 0.5, 2, 0.25);
    tg_pixel(t, 1, 6, 3, 7, 9, 0.3, 10);
}

static void part3a(TestList *l)
{
    Test *t = tg_test(l, PART3A, KIND_SPHERE, 1, "Part 3a: the worked example (c = (0, 0, -5), R = 1, r = (0, 0, -2))",
                      "roots t = 2 and t = 3: the first hit is t = 2");
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0, -2));
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0, -1));
    t = tg_test(l, PART3A, KIND_SPHERE, 2, "Part 3a: hits and misses with unit directions",
                "B^2 - A C < 0 is a miss; otherwise the smaller root t > 0");
    tg_sphere(t, V(0, 0, -10), 2, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(3, 0, -10), 2, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(1, 1, -6), 1.5, V(0, 0, 0), V(0.6, 0, -0.8));
    tg_sphere(t, V(0, 4, -3), 1, V(0, 0, 0), V(0, 0.8, -0.6));
    tg_sphere(t, V(-2, 0, -4), 0.5, V(0, 0, 0), V(0.6, 0, -0.8));
    t = tg_test(l, PART3A, KIND_SPHERE, 2, "Part 3a: directions that are not unit length",
                "A = r.r is not 1 when |r| is not 1; t scales with 1 / |r|");
    tg_sphere(t, V(0, 0, -10), 2, V(0, 0, 0), V(0, 0, -4));
    tg_sphere(t, V(0, 0, -10), 2, V(0, 0, 0), V(0, 0, -0.25));
    tg_sphere(t, V(1, 2, -7), 1, V(0, 0, 0), V(3, 6, -21));
    tg_sphere(t, V(5, 0, -5), 1, V(0, 0, 0), V(0, 0, -3));
    t = tg_test(l, PART3A, KIND_SPHERE, 2, "Part 3a: spheres behind the eye are misses",
                "both roots negative: the sphere is behind the ray's origin");
    tg_sphere(t, V(0, 0, 5), 1, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0, 1));
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(2, 2, 8), 3, V(0, 0, 0), V(0.48, 0.6, 0.64));
    tg_sphere(t, V(2, 2, -8), 3, V(0, 0, 0), V(0.48, 0.6, -0.64));
    t = tg_test(l, PART3A, KIND_SPHERE, 2, "Part 3a: from inside the sphere the hit is the exit point",
                "inside, C < 0: one root is negative, the other is where the ray leaves");
    tg_sphere(t, V(0, 0, 0), 10, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(0, 0, -1), 5, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(0, 0, -1), 5, V(0, 0, 0), V(0, 0, 1));
    tg_sphere(t, V(1, 2, 3), 50, V(0, 0, 0), V(0.36, 0.48, -0.8));
    /* tmin = 0 is the lecture's rule: a hit however close to e counts.
     * The origins are exact binary fractions just outside the sphere, so
     * the near root is exactly e.z + 1 in the axis-aligned cases. */
    t = tg_test(l, PART3A, KIND_SPHERE, 2, "Part 3a: hits just ahead of the ray's origin (t = 5e-4, 1e-7)",
                "tmin = 0: a hit at any t > 0 counts, however small (tutorials' tmin = 0.001 is for "
                "shadow rays, next week)");
    tg_sphere(t, V(0, 0, -2), 1, V(0, 0, -1 + 0x1.0cp-11), V(0, 0, -1));
    tg_sphere(t, V(0, 0, -2), 1, V(0, 0, -1 + 0x1.ap-24), V(0, 0, -1));
    tg_sphere(t, V(3, -1, -7), 2.5, V(3, -1, -4.5 + 0x1p-12), V(0, 0.6, -0.8));
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0, -1));
    t = tg_test(l, PART3A, KIND_SPHERE, 1, "Part 3a: a tangent ray touches the sphere",
                "B^2 - A C = 0 exactly: one root, a hit");
    tg_sphere(t, V(2, 0, -10), 2, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(0, -3, -6), 3, V(0, 0, 0), V(0, 0, -2));
    tg_sphere(t, V(0, 0, -6), 1, V(0, 0, 0), V(0, 0, -1));
    t = tg_test(l, PART3A, KIND_SPHERE, 1, "Part 3a: a zero direction is a miss",
                "r = 0 gives A = 0: no ray, no hit (and no division by zero)");
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0, 0));
    tg_sphere(t, V(0, 0, -1), 5, V(0, 0, 0), V(0, 0, 0));          /* from inside */
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0.6, -0.8));
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 0), V(0, 0.1, -0.9));
    t = tg_test(l, PART3A, KIND_SPHERE, 1, "Part 3a: a ray that starts on the sphere",
                "C = 0 exactly: one root is t = 0, the ray's own origin, which is not ahead of it (t > 0)");
    tg_sphere(t, V(0, 0, -1), 1, V(0, 0, 0), V(0, 0, -1));
    tg_sphere(t, V(0, 0, -1), 1, V(0, 0, 0), V(0, 0, 1));
    tg_sphere(t, V(0, 0, -2), 2, V(0, 0, 0), V(0, 0, -2));
    t = tg_test(l, PART3A, KIND_SPHERE, 1, "Part 3a: rays that do not start at the origin",
                "f = e - c uses the ray's own origin e");
    tg_sphere(t, V(0, 0, -5), 1, V(0, 0, 3), V(0, 0, -1));
    tg_sphere(t, V(4, 1, -2), 1.5, V(1, 1, 1), V(1, 0, -1));
    tg_sphere(t, V(4, 1, -2), 1.5, V(10, 1, -2), V(1, 0, 0));
    tg_sphere(t, V(-3, 2, 0), 1, V(-3, 2, 10), V(0, 0, -0.5));
}

static void part3b(TestList *l)
{
    Test *t = tg_test(l, PART3B, KIND_CAMERA, 1, "Part 3b: camera_ray, the worked example (pixel (3, 0, -4))",
                      "origin = e, direction = (s - e) / |s - e| = (0.6, 0, -0.8)");
    tg_camera(t, V(0, 0, 0), V(3, 0, -4));
    tg_camera(t, V(0, 0, 0), V(0, 0, -1));
    t = tg_test(l, PART3B, KIND_CAMERA, 1, "Part 3b: camera_ray gives unit directions",
                "the direction has length 1 whatever the pixel's distance");
    tg_camera(t, V(0, 0, 0), V(-0.5, 0.375, -1));
    tg_camera(t, V(0, 0, 0), V(12, -9, -20));
    tg_camera(t, V(0, 0, 0), V(0.001, 0.002, -0.003));
    tg_camera(t, V(1, 2, 3), V(4, -2, 3));

    t = tg_test(l, PART3B, KIND_COLOR, 1, "Part 3b: ray_color, one sphere: hit and miss",
                "a hit gives the sphere's colour, a miss the background");
    t->background[0] = 0.2, t->background[1] = 0.4, t->background[2] = 0.6;
    test_add_sphere(t, V(0, 0, -5), 1, V(1, 0, 0));
    tg_color(t, V(0, 0, 0), V(0, 0, -1));
    tg_color(t, V(0, 0, 0), V(0, 0.6, -0.8));
    tg_color(t, V(0, 0, 0), V(0.1, 0.1, -0.9899494936611665));
    t = tg_test(l, PART3B, KIND_COLOR, 2, "Part 3b: ray_color, the closest of several spheres",
                "spheres listed far to near: the smallest t wins, not the first sphere hit");
    t->background[0] = 0.1, t->background[1] = 0.1, t->background[2] = 0.1;
    test_add_sphere(t, V(0, 0, -20), 5, V(0, 0, 1));
    test_add_sphere(t, V(0, 0, -10), 2, V(0, 1, 0));
    test_add_sphere(t, V(0.5, 0, -5), 1, V(1, 0, 0));
    test_add_sphere(t, V(0, 0, -30), 1, V(1, 1, 0));
    tg_color(t, V(0, 0, 0), V(0, 0, -1));
    tg_color(t, V(0, 0, 0), V(0, 0.15, -0.9886859966642595));
    tg_color(t, V(0, 0, 0), V(0, 0.3, -0.9539392014169456));
    tg_color(t, V(0, 0, 0), V(0.6, 0, -0.8));
    tg_color(t, V(0, 0, -25), V(0, 0, -1));
    t = tg_test(l, PART3B, KIND_COLOR, 1, "Part 3b: ray_color ignores spheres behind the ray",
                "a sphere behind the eye is not hit, whatever its place in the list");
    t->background[0] = 0, t->background[1] = 0, t->background[2] = 0.3;
    test_add_sphere(t, V(0, 0, 5), 2, V(1, 0, 1));
    test_add_sphere(t, V(0, 0, -8), 2, V(0, 1, 0));
    tg_color(t, V(0, 0, 0), V(0, 0, -1));
    tg_color(t, V(0, 0, 0), V(0, 0, 1));
    tg_color(t, V(0, 0, 0), V(0, 0.5, -0.8660254037844386));
    t = tg_test(l, PART3B, KIND_COLOR, 1, "Part 3b: ray_color counts a hit just ahead of the eye",
                "the red sphere is hit at t = 5e-4 and 6.3e-4: every hit of sphere_intersect counts, however "
                "near (no bound such as t > 0.001): red, not the green behind it");
    t->background[0] = 0.2, t->background[1] = 0.2, t->background[2] = 0.2;
    test_add_sphere(t, V(0, 0, -10), 3, V(0, 1, 0));
    test_add_sphere(t, V(0, 0, -1.0005), 1, V(1, 0, 0));
    tg_color(t, V(0, 0, 0), V(0, 0, -1));
    tg_color(t, V(0, 0, 0), V(0, 0.6, -0.8));
    tg_color(t, V(0, 0, 0), V(0, 0, 1));

    tg_image(l, "Part 3b: render the default scene at 40 x 30", "labs/scenes/default.scene", 40, 30)->weight = 2;
    tg_image(l, "Part 3b: render the flip scene at 24 x 24", "labs/scenes/flip.scene", 24, 24);
    tg_image(l, "Part 3b: render the inside scene at 32 x 24", "labs/scenes/inside.scene", 32, 24);
    for (int k = l->n - 3; k < l->n; k++)
        snprintf(l->tests[k].note, sizeof l->tests[k].note, "%s",
                 "each pixel centre goes through your camera_ray and ray_color");
}

void testgen_public(TestList *list)
{
    part1(list);
    part2(list);
    part3a(list);
    part3b(list);
    tg_hard(list, PUBLIC_HARD_SEED, 2, false);
    testgen_public_flat(list);          /* Parts 4 and 5: public_flat.c */
}
