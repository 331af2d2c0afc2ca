/*
 * hard.h - deterministic generators of hard cases for every part, each with
 * its expected answer from the oracle and the rule that judges an answer
 * (hard_check1, 2 and 3b; the oracle's own for Parts 3a, 4 and 5).
 *
 *     HardCase3a cases[HARD_PART3A_FAMILIES * 20];
 *     int n = hard_part3a(seed, cases, HARD_PART3A_FAMILIES * 20);
 *     for (int k = 0; k < n; k++) {
 *         double t = 0;
 *         bool hit = sphere_intersect(&cases[k].sphere, &cases[k].ray, &t);
 *         if (!oracle_sphere_accepts(&cases[k].sphere, &cases[k].ray, hit, t))
 *             ...  "Part 3a: " + cases[k].family
 *     }
 *
 * Case k belongs to family k % HARD_PARTx_FAMILIES and depends only on
 * (seed, k): any max >= the number of families covers every family, and a
 * longer list starts with the shorter one.  Within a family, even and odd
 * cases aim at a hit and at a miss where the family allows both (the
 * oracle decides what they are).  Only + - * / sqrt ldexp nextafter are
 * used to make the inputs, so the same seed gives the same cases on every
 * IEEE-754 machine (build with -ffp-contract=off).
 *
 * Tolerances (those rules apply them):
 *   Part 1   w and h each within HARD_PART1_REL_TOL = 8 u relative.  The
 *            reference's error is a few u: the rounding of pi / 180 and of
 *            the argument (times tan's condition, at most pi / 2 once the
 *            angle is reduced to 45 degrees or less), tan's own ulp, the
 *            products by 2 d and by aspect.
 *   Part 2   x within HARD_PART2_TOL_U u |x| of the exact centre, y within
 *            HARD_PART2_TOL_U u |y|, z exactly -d: relative to the
 *            coordinate itself, so the centre column is x = 0 exactly and
 *            mirrored pixels opposite.  (2 i + 1 - nx) (w / (2 nx)) is an
 *            exact integer times one rounding, rounded once more: within
 *            about 2 u |x|.  The lecture's formula -w/2 + w (i + 0.5) / nx
 *            cancels near the centre (off by up to about 2 u |w| whatever
 *            x), and fails.
 *   Part 3a  oracle_sphere_accepts (oracle.h): hit/miss must match unless
 *            ambiguous; t within ORACLE_K_T u kappa t; a hit's t finite, > 0.
 *   Part 3b  camera_ray: origin exact, each direction component within
 *            HARD_PART3B_DIR_TOL_U u of the correctly rounded unit vector
 *            (the reference is off by at most about 2.5 u).  ray_color: the
 *            colour of the oracle's closest sphere (or the background), or
 *            when ambiguous that of the alternative.
 *   Parts 4, 5 oracle_flat_accepts(&c->expect, hit, t) (oracle.h).
 */
#ifndef HARD_H
#define HARD_H

#include <stdint.h>
#include "oracle.h"

#define HARD_FAMILY_LEN 48

/* splitmix64: *state advances by one step per call. */
uint64_t hard_rng_next(uint64_t *state);
/* Uniform in [0, 1), 53 random bits. */
double hard_rng_uniform(uint64_t *state);

/* ---- Part 1: image_plane_size ------------------------------------------ */

#define HARD_PART1_FAMILIES 6
#define HARD_PART1_REL_TOL (8 * ORACLE_U)

typedef struct {
    char family[HARD_FAMILY_LEN];      /* e.g. "fov 180 - 2^-k"            */
    double fov_degrees, aspect, d;     /* inputs                           */
    double w, h;                       /* expected (oracle_image_plane)    */
} HardCase1;

int  hard_part1(uint64_t seed, HardCase1 *cases, int max);
bool hard_check1(const HardCase1 *c, double w, double h);

/* ---- Part 2: pixel_coordinates ----------------------------------------- */

#define HARD_PART2_FAMILIES 4
#define HARD_PART2_TOL_U 4.0

typedef struct {
    char family[HARD_FAMILY_LEN];
    int i, j, nx, ny;                  /* inputs                           */
    double w, h, d;
    Vec3 p;                            /* expected (oracle_pixel)          */
} HardCase2;

int  hard_part2(uint64_t seed, HardCase2 *cases, int max);
bool hard_check2(const HardCase2 *c, Vec3 got);

/* ---- Part 3a: sphere_intersect ----------------------------------------- */

#define HARD_PART3A_FAMILIES 28

typedef struct {
    char family[HARD_FAMILY_LEN];      /* e.g. "far small sphere D/R=1e7"  */
    Sphere sphere;                     /* inputs                           */
    Ray ray;
    OracleHit expect;                  /* oracle_sphere(&sphere, &ray)     */
} HardCase3a;

int  hard_part3a(uint64_t seed, HardCase3a *cases, int max);

/* ---- Part 3b: camera_ray and ray_color --------------------------------- */

#define HARD_PART3B_FAMILIES 6
#define HARD_PART3B_MAX_SPHERES 4
#define HARD_PART3B_DIR_TOL_U 4.0

typedef struct {
    char family[HARD_FAMILY_LEN];
    Sphere spheres[HARD_PART3B_MAX_SPHERES];   /* distinct colours         */
    int nspheres;
    Vec3 background;
    Vec3 eye;                          /* the origin                       */
    Vec3 pixel;                        /* camera_ray(eye, pixel)           */
    Ray ray;                           /* expected: eye, oracle_unit(pixel - eye);
                                          also the ray ray_color is given */
    int closest;                       /* expected: oracle_closest(scene, ray) */
    bool ambiguous;
    int alternative;
} HardCase3b;

int  hard_part3b(uint64_t seed, HardCase3b *cases, int max);
/* A Scene that points into c (valid while c is). */
Scene hard_scene3b(HardCase3b *c);
bool hard_check3b_ray(const HardCase3b *c, Ray got);
bool hard_check3b_color(const HardCase3b *c, Vec3 got);

/* ---- Part 4: plane_intersect (hard_flat.c) --------------------------------- */

#define HARD_PART4_FAMILIES 8

typedef struct {
    char family[HARD_FAMILY_LEN];
    Plane plane;                       /* inputs                           */
    Ray ray;
    OracleFlat expect;                 /* oracle_plane(&plane, &ray)       */
} HardCase4;

int  hard_part4(uint64_t seed, HardCase4 *cases, int max);

/* ---- Part 5: triangle_intersect (hard_flat.c) ------------------------------ */

#define HARD_PART5_FAMILIES 7

typedef struct {
    char family[HARD_FAMILY_LEN];
    Triangle tri;                      /* inputs                           */
    Ray ray;
    OracleFlat expect;                 /* oracle_triangle(&tri, &ray)      */
} HardCase5;

int  hard_part5(uint64_t seed, HardCase5 *cases, int max);

/* Closed meshes (convex polyhedra: a cube split into 12 triangles, an
 * octahedron, an icosahedron), each with rays from outside aimed at its
 * shared edges or vertices and on into its interior, so that every ray
 * crosses the surface there: a watertight test hits one of the triangles
 * that share the edge or vertex, and the first hit is that crossing.
 * expect[k] is oracle_mesh(tris, ntris, &rays[k]). */
#define HARD_MESH_FAMILIES 3
#define HARD_MESH_MAX_TRIANGLES 20
#define HARD_MESH_RAYS 48

typedef struct {
    char family[HARD_FAMILY_LEN];
    Triangle tris[HARD_MESH_MAX_TRIANGLES];
    int ntris;
    Vec3 centre;                       /* inside the mesh                  */
    Ray rays[HARD_MESH_RAYS];
    OracleFlat expect[HARD_MESH_RAYS];
} HardMesh;

/* Mesh k is of family k % HARD_MESH_FAMILIES and depends only on (seed, k);
 * the shapes take turns, starting from one the seed picks. */
int  hard_meshes(uint64_t seed, HardMesh *meshes, int max);

/* The building blocks, for the benchmark and the unit tests: a mesh of one
 * of HARD_MESH_SHAPES shapes about size across, centred near offset and
 * turned at random (without rays); a ray aimed from outside at one of its
 * shared vertices (vertex true) or at a point of one of its shared edges,
 * with the ray parameter at which it enters the mesh (to about 1e-15
 * relative): a method that lets the ray through there hits nothing at that
 * t (it may still hit the far side). */
#define HARD_MESH_SHAPES 3
void hard_mesh_make(uint64_t *state, int shape, double size, Vec3 offset, HardMesh *m);
Ray  hard_mesh_ray_at(uint64_t *state, const HardMesh *m, bool vertex, double *t_entry);

#endif
