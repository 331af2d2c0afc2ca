/*
 * bvh.h - a bounding volume hierarchy over a scene's spheres and
 * triangles, so that a ray tests the few objects near it instead of all of
 * them.
 *
 * Each node holds a box around some of the objects: the root around all
 * of them, its two children around two halves, and so on down to leaves of
 * a few objects each.  A ray that misses a node's box misses every object
 * in it, and a box that the ray enters only beyond the closest hit found
 * so far can hold nothing closer: either way the whole subtree is skipped,
 * so a ray visits about log2(n) nodes, not n objects (closest.c walks it).
 *
 * The build is the usual one (pbrt, Embree): each node's objects are
 * sorted into 16 bins along each axis by their boxes' centres, and split
 * where the surface-area heuristic says a ray's expected work is least.
 * The nodes are one flat array: a node's children are next to each other.
 *
 * The boxes are conservative.  A node's box holds the exact boxes of its
 * objects (their vertices' extremes, a sphere's centre +/- radius),
 * rounded outward to float; and bvh_slab, which says where a ray's line is
 * in a box, widens what it computes by a relative 2^-20, far more than its
 * own rounding, as Ize's robust slab test widens by its rounding bound.  So
 * a hit at a point in an object's box, or within a relative 2^-20 of its t
 * there, is never skipped by a box test: a ray through an edge or a vertex
 * the boxes share is never lost to rounding.
 */
#ifndef KIT_BVH_H
#define KIT_BVH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "../raytracer.h"

#define BVH_MAX_DEPTH 64        /* no path from the root is longer (bvh.c) */
#define BVH_SLACK     0x1p-20   /* the relative widening of bvh_slab's interval */

/* A node: a box, and either two children or a leaf's objects. */
typedef struct {
    float lo[3], hi[3];         /* the box, x y z */
    int32_t first;              /* inner node: its children are nodes first and
                                   first + 1; leaf: its objects are
                                   items[first .. first + count - 1] */
    int32_t count;              /* the leaf's objects; 0 for an inner node */
} BvhNode;

/* The hierarchy of a scene.  An object is a number: k < nspheres is
 * scene->spheres[k], any other k is scene->triangles[k - nspheres]. */
typedef struct {
    BvhNode *nodes;             /* nodes[0] is the root */
    int nnodes;
    int32_t *items;             /* every object once, grouped by leaf */
    int nitems;
    int nspheres;
} Bvh;

/* Builds the hierarchy of scene's spheres and triangles (its planes, which
 * no box holds, stay outside).  Returns 0, or -1 with a reason in err when
 * memory runs out or the scene has no sphere or triangle. */
int bvh_build(Bvh *bvh, const Scene *scene, char *err, size_t errlen);

/* The exact box of object k of scene (numbered as above, nspheres
 * spheres first), in double: a triangle's is its vertices' extremes; a
 * sphere's is c -/+ R, each end moved a step outward (c - R and c + R
 * round by at most half a step). */
void bvh_object_box(const Scene *scene, int nspheres, int32_t k, double lo[3], double hi[3]);

/* Frees the hierarchy; safe on one already freed. */
void bvh_free(Bvh *bvh);

/* A ray made ready for box tests: its origin and 1 / its direction. */
typedef struct {
    double o[3], inv[3];
} BvhRay;

/* Makes ray ready for bvh_slab.  Returns false for a ray bvh_slab cannot
 * bound: a component of its origin not finite or beyond 2^500, or of its
 * direction not finite, or neither 0 nor between 2^-500 and 2^500 (for
 * these, 1 / r and the products below keep their relative rounding error
 * under 3 units of the last place).  Camera rays always pass. */
bool bvh_ray(BvhRay *br, const Ray *ray);

/* Where the line x(t) = e + t r may be in the box lo .. hi: sets [*t0, *t1]
 * to an interval holding every t, negative ones too, at which the exact
 * line is in the box, widened by a relative BVH_SLACK (as defined above
 * for each end).  Returns false, and sets nothing, when even that interval
 * is empty: the line misses the box. */
static inline bool bvh_slab(const BvhRay *br, const double lo[3], const double hi[3],
                            double *t0, double *t1)
{
    /* 2^-20 for the slack, and enough again for every rounding here */
    const double widen = BVH_SLACK + 0x1p-40;
    double near = -INFINITY, far = INFINITY;
    for (int k = 0; k < 3; k++) {
        if (br->inv[k] == INFINITY || br->inv[k] == -INFINITY) {
            /* r has no component k: the line keeps e's coordinate k */
            if (lo[k] > br->o[k] || hi[k] < br->o[k])
                return false;
            continue;
        }
        double a = (lo[k] - br->o[k]) * br->inv[k], b = (hi[k] - br->o[k]) * br->inv[k];
        if (br->inv[k] < 0) {
            double swap = a;
            a = b;
            b = swap;
        }
        near = a > near ? a : near;
        far = b < far ? b : far;
    }
    near = near < DBL_MAX ? near : DBL_MAX;       /* beyond the largest double: at it */
    far = far > -DBL_MAX ? far : -DBL_MAX;
    near -= fabs(near) * widen + DBL_MIN;         /* DBL_MIN: a product that underflowed */
    far += fabs(far) * widen + DBL_MIN;
    if (!(near <= far))
        return false;
    *t0 = near;
    *t1 = far;
    return true;
}

#endif
