/*
 * bvh.c - building the bounding volume hierarchy (see bvh.h).
 *
 * Top down: a node takes a range of the objects, finds the split of that
 * range that the surface-area heuristic prefers, reorders the range so
 * that the left part comes first, and hands each part to a child.
 *
 * The heuristic: a ray that passes through a box passes through a box
 * inside it with a probability of about the ratio of their surface areas.
 * A node of n objects made a leaf costs n object tests; split into L and
 * R, it costs the two box tests of its children and, weighted by those
 * ratios, the tests of L's and R's objects.  The candidate splits are the
 * 15 planes between 16 equal bins of the objects' centres (n - 1 between n
 * bins for a node of n < 16 objects), along each axis.
 *
 * Depth: below BVH_SAH_DEPTH a node's range is halved, so no path is
 * longer than 40 + log2(n), and a scene holds fewer than 2^21 objects
 * (scene.h): under BVH_MAX_DEPTH, the walk's stack.
 */
#include "bvh.h"
#include "textfile.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BVH_BINS      16
#define BVH_LEAF_MAX  8        /* a leaf holds at most this many objects */
#define BVH_SAH_DEPTH 40       /* deeper, halve the range */
#define BVH_COST_BOX  2.0      /* an inner node's two box tests, in object tests */

/* An object while the hierarchy is built: its box, rounded outward to
 * float, and its number. */
typedef struct {
    float lo[3], hi[3];
    int32_t item;
} BvhObject;

/* The largest float <= x (x < -FLT_MAX: -infinity), and the smallest >= x. */
static float bvh_float_down(double x)
{
    if (x < -FLT_MAX)
        return -INFINITY;
    if (x > FLT_MAX)
        return FLT_MAX;
    float f = (float)x;
    return f > x ? nextafterf(f, -INFINITY) : f;
}

static float bvh_float_up(double x)
{
    return -bvh_float_down(-x);
}

void bvh_object_box(const Scene *scene, int nspheres, int32_t k, double lo[3], double hi[3])
{
    if (k < nspheres) {
        const Sphere *s = &scene->spheres[k];
        const double c[3] = { s->center.x, s->center.y, s->center.z };
        for (int a = 0; a < 3; a++) {
            lo[a] = nextafter(c[a] - s->radius, -INFINITY);
            hi[a] = nextafter(c[a] + s->radius, INFINITY);
        }
        return;
    }
    const Triangle *t = &scene->triangles[k - nspheres];
    const double v[3][3] = { { t->a.x, t->a.y, t->a.z }, { t->b.x, t->b.y, t->b.z },
                             { t->c.x, t->c.y, t->c.z } };
    for (int a = 0; a < 3; a++) {
        lo[a] = hi[a] = v[0][a];
        for (int i = 1; i < 3; i++) {
            lo[a] = v[i][a] < lo[a] ? v[i][a] : lo[a];
            hi[a] = v[i][a] > hi[a] ? v[i][a] : hi[a];
        }
    }
}

/* A box being grown: empty until something is added. */
typedef struct {
    float lo[3], hi[3];
} BvhBox;

static void box_empty(BvhBox *b)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = INFINITY;
        b->hi[a] = -INFINITY;
    }
}

static inline void box_add(BvhBox *b, const float lo[3], const float hi[3])
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = lo[a] < b->lo[a] ? lo[a] : b->lo[a];
        b->hi[a] = hi[a] > b->hi[a] ? hi[a] : b->hi[a];
    }
}

/* Half the surface area of b (the heuristic needs only ratios); 0 when empty. */
static inline double box_area(const BvhBox *b)
{
    double d[3];
    for (int a = 0; a < 3; a++)
        d[a] = b->hi[a] >= b->lo[a] ? (double)b->hi[a] - b->lo[a] : 0;
    return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

/* The centre of o's box along axis a, within float's finite range (a box
 * that reaches past it has an infinite side). */
static inline float centre(const BvhObject *o, int a)
{
    float c = 0.5f * o->lo[a] + 0.5f * o->hi[a];
    if (!(c == c))
        return 0;                       /* -infinity to infinity */
    return c > FLT_MAX ? FLT_MAX : c < -FLT_MAX ? -FLT_MAX : c;
}

/* How a node's objects are binned: nbins equal slices of the span of
 * their centres along each axis, the first at lo; scale is nbins over the
 * span (0 where the centres all lie at one place). */
typedef struct {
    float lo[3];
    double scale[3];
    int nbins;
} BvhBins;

/* The bins of n objects whose centres lie in cb: BVH_BINS, or n when
 * fewer (more bins than objects would only cost). */
static BvhBins bins_for(const BvhBox *cb, int n)
{
    BvhBins g;
    g.nbins = n < BVH_BINS ? n : BVH_BINS;
    for (int a = 0; a < 3; a++) {
        g.lo[a] = cb->lo[a];
        g.scale[a] = cb->hi[a] > cb->lo[a] ? g.nbins / ((double)cb->hi[a] - cb->lo[a]) : 0;
    }
    return g;
}

/* The bin, 0 .. g->nbins - 1, of o's centre along axis a. */
static inline int bin_of(const BvhObject *o, int a, const BvhBins *g)
{
    int k = (int)(((double)centre(o, a) - g->lo[a]) * g->scale[a]);
    return k < g->nbins ? k : g->nbins - 1;
}

/* What the build shares: the objects and the nodes made so far. */
typedef struct {
    BvhObject *objs;
    BvhNode *nodes;
    int nnodes;
} BvhBuild;

/* The best split of objs[0 .. n-1], binned by g: sets *axis and *bin
 * (left: the objects in bins 0 .. *bin along *axis) and returns its cost,
 * in object tests per ray through the node's box, of area area; INFINITY
 * when no split between bins leaves objects on both sides. */
static double bvh_best_split(const BvhObject *objs, int n, const BvhBins *g, double area,
                             int *axis, int *bin)
{
    const int nb = g->nbins;
    BvhBox box[3][BVH_BINS];
    int count[3][BVH_BINS] = { { 0 } };
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < nb; k++)
            box_empty(&box[a][k]);
    for (int i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) {
            int k = bin_of(&objs[i], a, g);
            count[a][k]++;
            box_add(&box[a][k], objs[i].lo, objs[i].hi);
        }
    double best = INFINITY;
    for (int a = 0; a < 3; a++) {
        if (g->scale[a] == 0)
            continue;
        /* right[k]: the cost of the bins above k, swept from the top */
        double right[BVH_BINS];
        BvhBox grow;
        box_empty(&grow);
        int m = 0;
        for (int k = nb - 1; k > 0; k--) {
            box_add(&grow, box[a][k].lo, box[a][k].hi);
            m += count[a][k];
            right[k - 1] = m * box_area(&grow);
        }
        box_empty(&grow);
        m = 0;
        for (int k = 0; k < nb - 1; k++) {
            box_add(&grow, box[a][k].lo, box[a][k].hi);
            m += count[a][k];
            if (m == 0 || m == n)
                continue;
            double cost = BVH_COST_BOX + (m * box_area(&grow) + right[k]) / area;
            if (cost < best) {
                best = cost;
                *axis = a;
                *bin = k;
            }
        }
    }
    return best;
}

/* Reorders objs[0 .. n-1] so that those in bins 0 .. bin along axis come
 * first.  Returns how many they are. */
static int bvh_partition(BvhObject *objs, int n, const BvhBins *g, int axis, int bin)
{
    int i = 0, j = n - 1;
    for (;;) {
        while (i <= j && bin_of(&objs[i], axis, g) <= bin)
            i++;
        while (i <= j && bin_of(&objs[j], axis, g) > bin)
            j--;
        if (i >= j)
            return i;
        BvhObject swap = objs[i];
        objs[i] = objs[j];
        objs[j] = swap;
    }
}

/* Makes node the root of objs[first .. first + n - 1], at depth depth. */
static void bvh_node(BvhBuild *b, int node, int first, int n, int depth)
{
    BvhObject *objs = b->objs + first;
    BvhBox box, cb;
    box_empty(&box);
    box_empty(&cb);
    for (int i = 0; i < n; i++) {
        box_add(&box, objs[i].lo, objs[i].hi);
        float c[3] = { centre(&objs[i], 0), centre(&objs[i], 1), centre(&objs[i], 2) };
        box_add(&cb, c, c);
    }
    BvhNode *nd = &b->nodes[node];
    memcpy(nd->lo, box.lo, sizeof nd->lo);
    memcpy(nd->hi, box.hi, sizeof nd->hi);
    nd->first = first;
    nd->count = n;
    if (n == 1)
        return;

    int left = n / 2;                   /* past BVH_SAH_DEPTH: halves */
    if (depth < BVH_SAH_DEPTH) {
        if (n <= BVH_COST_BOX)
            return;                     /* a split costs no less: a leaf */
        int axis = 0, bin = 0;
        BvhBins g = bins_for(&cb, n);
        double cost = bvh_best_split(objs, n, &g, box_area(&box), &axis, &bin);
        if (n <= BVH_LEAF_MAX && !(cost < n))
            return;                     /* a leaf is cheaper */
        if (cost < INFINITY)
            left = bvh_partition(objs, n, &g, axis, bin);
        else if (n <= BVH_LEAF_MAX)
            return;                     /* every centre in one bin: a leaf */
    }
    int child = b->nnodes;
    b->nnodes += 2;
    nd->first = child;
    nd->count = 0;
    bvh_node(b, child, first, left, depth + 1);
    bvh_node(b, child + 1, first + left, n - left, depth + 1);
}

int bvh_build(Bvh *bvh, const Scene *scene, char *err, size_t errlen)
{
    memset(bvh, 0, sizeof *bvh);
    int n = scene->nspheres + scene->ntriangles;
    if (n < 1)
        return kit_fail(err, errlen, "bvh: the scene has no sphere or triangle");
    BvhBuild b;
    b.objs = malloc((size_t)n * sizeof *b.objs);
    /* a binary tree of n leaves has 2 n - 1 nodes: the pages past the
     * nodes made are never touched, and are given back below */
    b.nodes = malloc((2 * (size_t)n - 1) * sizeof *b.nodes);
    bvh->items = malloc((size_t)n * sizeof *bvh->items);
    if (!b.objs || !b.nodes || !bvh->items) {
        free(b.objs);
        free(b.nodes);
        free(bvh->items);
        bvh->items = NULL;
        return kit_fail(err, errlen, "bvh: out of memory for %d objects", n);
    }
    for (int k = 0; k < n; k++) {
        double lo[3], hi[3];
        bvh_object_box(scene, scene->nspheres, k, lo, hi);
        for (int a = 0; a < 3; a++) {
            b.objs[k].lo[a] = bvh_float_down(lo[a]);
            b.objs[k].hi[a] = bvh_float_up(hi[a]);
        }
        b.objs[k].item = k;
    }
    b.nnodes = 1;
    bvh_node(&b, 0, 0, n, 0);
    for (int k = 0; k < n; k++)
        bvh->items[k] = b.objs[k].item;
    free(b.objs);
    BvhNode *fit = realloc(b.nodes, (size_t)b.nnodes * sizeof *fit);
    bvh->nodes = fit ? fit : b.nodes;
    bvh->nnodes = b.nnodes;
    bvh->nitems = n;
    bvh->nspheres = scene->nspheres;
    return 0;
}

bool bvh_ray(BvhRay *br, const Ray *ray)
{
    const double o[3] = { ray->origin.x, ray->origin.y, ray->origin.z },
                 r[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    for (int k = 0; k < 3; k++) {
        double m = fabs(r[k]);
        if (!(fabs(o[k]) <= 0x1p500) || !(m == 0 || (m >= 0x1p-500 && m <= 0x1p500)))
            return false;
        br->o[k] = o[k];
        br->inv[k] = 1 / r[k];          /* infinite for r[k] = 0 (bvh_slab looks) */
    }
    return true;
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->items);
    memset(bvh, 0, sizeof *bvh);
}
