/*
 * closest.c - see closest.h.
 */
#include "closest.h"

#include <limits.h>

/* Why the attributes.  The renderer is built with link-time optimisation,
 * and its speed on spheres comes from inlining the student's stage
 * functions into render.c's loop, which compilers do freely only for a
 * function called from one place.  These functions are the other place.
 * flatten inlines their calls into them, so that no call of a stage
 * function is left here and render.c's are the only ones; noinline keeps
 * them, grown by that, out of render.c's loop.  Without them clang renders
 * the sphere scenes a sixth slower (gcc and clang; elsewhere nothing). */
#if defined(__GNUC__)
#define CLOSEST_APART __attribute__((flatten, noinline))
#else
#define CLOSEST_APART
#endif

Vec3 closest_color(const Scene *scene, const Ray *ray) CLOSEST_APART;
Vec3 closest_color_bvh(const Scene *scene, const Bvh *bvh, const Ray *ray, bool *stray) CLOSEST_APART;
bool closest_probe(const Scene *scene, const Bvh *bvh) CLOSEST_APART;
bool closest_rows(const Scene *scene, const Bvh *bvh, Image *img, double w, double h,
                  const double nudge[2], int j0, int j1) CLOSEST_APART;

/* The closest hit so far: its t, its place in the plain loop's order
 * (spheres, planes, triangles) and its colour. */
typedef struct {
    double t;
    int order;
    Vec3 color;
} ClosestHit;

/* Makes (t, order, color) the closest hit when the plain loop would: t
 * smaller, or equal (and finite) and earlier in its order.  The plain loop
 * offers hits in order, so for it this is "t strictly smaller". */
static void closest_offer(ClosestHit *best, double t, int order, Vec3 color)
{
    if (t < best->t || (t == best->t && t < INFINITY && order < best->order)) {
        best->t = t;
        best->order = order;
        best->color = color;
    }
}

/* Tests object k (numbered as in bvh.h) with the student's function; on a
 * hit sets *t, which starts as NaN (a hit that leaves it unset never wins). */
static bool closest_hit(const Scene *scene, int nspheres, int32_t k, const Ray *ray, double *t)
{
    *t = NAN;
    if (k < nspheres)
        return sphere_intersect(&scene->spheres[k], ray, t);
    return triangle_intersect(&scene->triangles[k - nspheres], ray, t);
}

/* Object k's colour and place in the plain loop's order. */
static Vec3 closest_object_color(const Scene *scene, int nspheres, int32_t k)
{
    return k < nspheres ? scene->spheres[k].color : scene->triangles[k - nspheres].color;
}

static int closest_order(const Scene *scene, int nspheres, int32_t k)
{
    return k < nspheres ? k : k + scene->nplanes;
}

/* The planes, which no box holds, for every ray, in order. */
static void closest_planes(const Scene *scene, const Ray *ray, ClosestHit *best)
{
    double t;
    for (int k = 0; k < scene->nplanes; k++) {
        t = NAN;
        if (plane_intersect(&scene->planes[k], ray, &t))
            closest_offer(best, t, scene->nspheres + k, scene->planes[k].color);
    }
}

Vec3 closest_color(const Scene *scene, const Ray *ray)
{
    ClosestHit best = { INFINITY, INT_MAX, scene->background };
    const int ns = scene->nspheres, nt = scene->ntriangles;
    double t;
    for (int k = 0; k < ns; k++)
        if (closest_hit(scene, ns, k, ray, &t))
            closest_offer(&best, t, k, scene->spheres[k].color);
    closest_planes(scene, ray, &best);
    for (int k = 0; k < nt; k++)
        if (closest_hit(scene, ns, ns + k, ray, &t))
            closest_offer(&best, t, ns + scene->nplanes + k, scene->triangles[k].color);
    return best.color;
}

/* True when a hit of object k at t is a stray hit: t < +inf and outside
 * the interval bvh_slab gives for the object's own box. */
static bool closest_stray(const Scene *scene, int nspheres, int32_t k, const BvhRay *br, double t)
{
    if (!(t < INFINITY))
        return false;                   /* NaN, +inf: never the closest */
    double lo[3], hi[3], t0, t1;
    bvh_object_box(scene, nspheres, k, lo, hi);
    return !bvh_slab(br, lo, hi, &t0, &t1) || t < t0 || t > t1;
}

/* Where the ray enters node's box (bvh_slab's t0); false when it misses. */
static bool closest_enter(const BvhRay *br, const BvhNode *node, double *t0)
{
    const double lo[3] = { node->lo[0], node->lo[1], node->lo[2] },
                 hi[3] = { node->hi[0], node->hi[1], node->hi[2] };
    double t1;
    return bvh_slab(br, lo, hi, t0, &t1);
}

/* The walk.  A node is skipped when the ray misses its box, or enters it
 * only beyond the closest hit so far (t0 > best.t: strictly, so that an
 * object at the same t, which may come first in the plain loop's order,
 * is still tested).  An honest hit in a skipped node would be at a t in
 * its box's interval, so it would be no closer.  Of two children the
 * nearer entered is walked first and the other kept on a stack with its
 * t0, to be skipped when it is popped if a hit has come nearer since. */
Vec3 closest_color_bvh(const Scene *scene, const Bvh *bvh, const Ray *ray, bool *stray)
{
    BvhRay br;
    if (!bvh_ray(&br, ray))
        return closest_color(scene, ray);
    ClosestHit best = { INFINITY, INT_MAX, scene->background };
    closest_planes(scene, ray, &best);
    const int ns = bvh->nspheres;
    struct {
        int32_t node;
        double t0;
    } stack[BVH_MAX_DEPTH];
    int top = 0;
    if (closest_enter(&br, &bvh->nodes[0], &stack[0].t0)) {
        stack[0].node = 0;
        top = 1;
    }
    while (top > 0) {
        top--;
        if (stack[top].t0 > best.t)
            continue;
        const BvhNode *node = &bvh->nodes[stack[top].node];
        while (node && node->count == 0) {
            int32_t near = node->first, far = node->first + 1;
            double tn = 0, tf = 0;
            bool in_near = closest_enter(&br, &bvh->nodes[near], &tn) && !(tn > best.t);
            bool in_far = closest_enter(&br, &bvh->nodes[far], &tf) && !(tf > best.t);
            if (in_near && in_far && tf < tn) {
                int32_t swap = near;
                near = far;
                far = swap;
                tf = tn;
            }
            if (in_near && in_far) {
                stack[top].node = far;
                stack[top++].t0 = tf;
            }
            node = in_near || in_far ? &bvh->nodes[in_near ? near : far] : NULL;
        }
        for (int i = 0; node && i < node->count; i++) {
            int32_t k = bvh->items[node->first + i];
            double t;
            if (!closest_hit(scene, ns, k, ray, &t))
                continue;
            if (closest_stray(scene, ns, k, &br, t)) {
                *stray = true;
                return best.color;
            }
            closest_offer(&best, t, closest_order(scene, ns, k), closest_object_color(scene, ns, k));
        }
    }
    return best.color;
}

/* Where closest_probe aims, as weights of a triangle's vertices a, b, c:
 * its centroid, then points in its plane outside it, near and far: just
 * outside each edge and just beyond each vertex, each vertex mirrored
 * through the opposite edge and through the other vertices, and points far
 * beyond each edge and vertex.  A sphere's points are its centre and six
 * points 2 R from it along the axes. */
static const double closest_probe_weights[][3] = {
    { 1.0 / 3, 1.0 / 3, 1.0 / 3 },
    { -0.1, 0.55, 0.55 }, { 0.55, -0.1, 0.55 }, { 0.55, 0.55, -0.1 },
    { -0.5, 0.75, 0.75 }, { 0.75, -0.5, 0.75 }, { 0.75, 0.75, -0.5 },
    { 1.2, -0.1, -0.1 }, { -0.1, 1.2, -0.1 }, { -0.1, -0.1, 1.2 },
    { 1.6, -0.3, -0.3 }, { -0.3, 1.6, -0.3 }, { -0.3, -0.3, 1.6 },
    { -1, 1, 1 }, { 1, -1, 1 }, { 1, 1, -1 },
    { 2, 0, -1 }, { 2, -1, 0 }, { 0, 2, -1 }, { -1, 2, 0 }, { 0, -1, 2 }, { -1, 0, 2 },
    { -8, 0.5, 8.5 }, { -8, 8.5, 0.5 }, { 0.5, -8, 8.5 }, { 8.5, -8, 0.5 },
    { 0.5, 8.5, -8 }, { 8.5, 0.5, -8 }, { 9, -4, -4 }, { -4, 9, -4 }, { -4, -4, 9 },
};

/* Point p of object k for closest_probe, or false past its last one. */
static bool closest_probe_point(const Scene *scene, int nspheres, int32_t k, int p, Vec3 *point)
{
    if (k < nspheres) {
        static const Vec3 axes[7] = { { 0, 0, 0 }, { 2, 0, 0 }, { -2, 0, 0 }, { 0, 2, 0 },
                                      { 0, -2, 0 }, { 0, 0, 2 }, { 0, 0, -2 } };
        const Sphere *s = &scene->spheres[k];
        if (p >= 7)
            return false;
        *point = vec3_add(s->center, vec3_scale(axes[p], s->radius));
        return true;
    }
    const Triangle *tri = &scene->triangles[k - nspheres];
    if (p >= (int)(sizeof closest_probe_weights / sizeof closest_probe_weights[0]))
        return false;
    const double *w = closest_probe_weights[p];
    *point = vec3_add(vec3_add(vec3_scale(tri->a, w[0]), vec3_scale(tri->b, w[1])),
                      vec3_scale(tri->c, w[2]));
    return true;
}

bool closest_probe(const Scene *scene, const Bvh *bvh)
{
    const int n = bvh->nitems, ns = bvh->nspheres;
    const int step = (n + CLOSEST_PROBE_OBJECTS - 1) / CLOSEST_PROBE_OBJECTS;
    for (int32_t k = 0; k < n; k += step) {
        Vec3 point;
        for (int p = 0; closest_probe_point(scene, ns, k, p, &point); p++) {
            Vec3 r = vec3_normalize(vec3_sub(point, scene->eye));
            for (int way = 0; way < 2; way++) {   /* towards the point, then away */
                Ray ray = { scene->eye, way == 0 ? r : vec3_negate(r) };
                BvhRay br;
                double t;
                if (bvh_ray(&br, &ray) && closest_hit(scene, ns, k, &ray, &t)
                    && closest_stray(scene, ns, k, &br, t))
                    return true;
            }
        }
    }
    return false;
}

bool closest_rows(const Scene *scene, const Bvh *bvh, Image *img, double w, double h,
                  const double nudge[2], int j0, int j1)
{
    const int nx = scene->nx, ny = scene->ny;
    const bool nudged = nudge[0] != 0 || nudge[1] != 0;
    bool stray = false;
    for (int j = j0; j < j1; j++) {
        unsigned char *px = img->rgb + (size_t)3 * nx * (size_t)j;
        for (int i = 0; i < nx; i++) {
            Vec3 s = pixel_coordinates(i, j, nx, ny, w, h, scene->d);
            if (nudged)
                s = vec3(s.x + nudge[0], s.y + nudge[1], s.z);
            Ray ray = camera_ray(scene->eye, s);
            Vec3 color = bvh ? closest_color_bvh(scene, bvh, &ray, &stray) : closest_color(scene, &ray);
            if (stray)
                return false;
            px[0] = image_channel(color.x);
            px[1] = image_channel(color.y);
            px[2] = image_channel(color.z);
            px += 3;
        }
    }
    return true;
}
