/* The bounding volume hierarchy of labs/kit (bvh.h) and the closest hit
 * through it (closest.h), held up against the plain loop that tests every
 * object for every ray.
 *
 * This program links its own sphere_intersect and triangle_intersect:
 * each passes the call on to the function the test has chosen, the
 * reference's (solutions/, compiled here under other names) or one of the
 * deliberately wrong ones below.  Parts 1, 2, 3b and 4 are the reference's.
 * The boxes' expected intervals are computed here in long double, with
 * divisions, apart from bvh_slab. */
#include "check.h"            /* first: it sets the POSIX feature level */
#include <float.h>
#include <stdatomic.h>
#include "../../labs/kit/bvh.h"
#include "../../labs/kit/closest.h"
#include "render_check.h"

bool reference_sphere_intersect(const Sphere *sphere, const Ray *ray, double *t);
bool reference_triangle_intersect(const Triangle *tri, const Ray *ray, double *t);

typedef bool SphereFn(const Sphere *sphere, const Ray *ray, double *t);
typedef bool TriangleFn(const Triangle *tri, const Ray *ray, double *t);
static SphereFn *sphere_fn = reference_sphere_intersect;
static TriangleFn *triangle_fn = reference_triangle_intersect;
static atomic_long triangle_calls;

bool sphere_intersect(const Sphere *sphere, const Ray *ray, double *t)
{
    return sphere_fn(sphere, ray, t);
}

bool triangle_intersect(const Triangle *tri, const Ray *ray, double *t)
{
    atomic_fetch_add_explicit(&triangle_calls, 1, memory_order_relaxed);
    return triangle_fn(tri, ray, t);
}

/* ---- where a line is in a box, in long double -------------------------- */

/* Sets [*a, *b] to the t at which the line o + t d is in the box lo .. hi
 * and returns true; false when it misses the box. */
static bool line_in_box(const long double lo[3], const long double hi[3], const Ray *ray,
                        long double *a, long double *b)
{
    const double o[3] = { ray->origin.x, ray->origin.y, ray->origin.z },
                 d[3] = { ray->direction.x, ray->direction.y, ray->direction.z };
    long double t0 = -INFINITY, t1 = INFINITY;
    for (int k = 0; k < 3; k++) {
        if (d[k] == 0) {
            if (o[k] < lo[k] || o[k] > hi[k])
                return false;
            continue;
        }
        long double p = (lo[k] - o[k]) / d[k], q = (hi[k] - o[k]) / d[k];
        if (p > q) {
            long double swap = p;
            p = q;
            q = swap;
        }
        t0 = p > t0 ? p : t0;
        t1 = q < t1 ? q : t1;
    }
    if (t0 > t1)
        return false;
    *a = t0;
    *b = t1;
    return true;
}

/* The box of the n points v, each grown by r on every side. */
static void points_box(const Vec3 *v, int n, double r, long double lo[3], long double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = hi[k] = (&v[0].x)[k];
        for (int i = 1; i < n; i++) {
            long double x = (&v[i].x)[k];
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
        }
        lo[k] -= r;
        hi[k] += r;
    }
}

/* ---- deliberately wrong functions -------------------------------------- */

/* A hash of the bits of n doubles. */
static uint64_t hash_doubles(const double *x, int n)
{
    uint64_t h = 0x9e3779b97f4a7c15u;
    for (int k = 0; k < n; k++) {
        uint64_t bits;
        memcpy(&bits, &x[k], sizeof bits);
        h = (h ^ bits) * 0xff51afd7ed558ccdu;
        h ^= h >> 29;
    }
    return h;
}

/* Honest but wrong (closest.h): a "hit" wherever the line meets the box
 * [lo, hi], at a t on a grid of 1/4 inside the box where there is one (so
 * that neighbours tie), else where the line enters it; and by the hash h,
 * a hit at NaN, at +infinity, a hit with t left unset, or a miss. */
static bool box_hit(const long double lo[3], const long double hi[3], const Ray *ray, uint64_t h,
                    double *t)
{
    long double a, b;
    if (!line_in_box(lo, hi, ray, &a, &b))
        return false;
    switch (h % 16) {
    case 0: *t = NAN; return true;
    case 1: *t = INFINITY; return true;
    case 2: return true;
    case 3: return false;
    default: break;
    }
    long double q = ceill(4 * a) / 4;
    *t = (double)(q <= b ? q : a);
    return true;
}

static bool box_hit_triangle(const Triangle *tri, const Ray *ray, double *t)
{
    long double lo[3], hi[3];
    const Vec3 v[3] = { tri->a, tri->b, tri->c };
    points_box(v, 3, 0, lo, hi);
    const double key[5] = { tri->a.x, tri->b.y, tri->c.z, ray->direction.x, ray->direction.y };
    return box_hit(lo, hi, ray, hash_doubles(key, 5), t);
}

static bool box_hit_sphere(const Sphere *sphere, const Ray *ray, double *t)
{
    long double lo[3], hi[3];
    points_box(&sphere->center, 1, sphere->radius, lo, hi);
    const double key[4] = { sphere->center.x, sphere->radius, ray->direction.x, ray->direction.y };
    return box_hit(lo, hi, ray, hash_doubles(key, 4), t);
}

/* Not honest: the reference's hits, at -t (behind the eye, where the box is not). */
static bool negated_triangle(const Triangle *tri, const Ray *ray, double *t)
{
    if (!reference_triangle_intersect(tri, ray, t))
        return false;
    *t = -*t;
    return true;
}

/* Not honest: hits in the triangle grown three times about its centroid,
 * most of which lie outside its box (as a test without the check
 * beta + gamma <= 1 hits outside the triangle). */
static bool grown_triangle(const Triangle *tri, const Ray *ray, double *t)
{
    Vec3 g = vec3_scale(vec3_add(vec3_add(tri->a, tri->b), tri->c), 1.0 / 3);
    Triangle big = { vec3_add(g, vec3_scale(vec3_sub(tri->a, g), 3)),
                     vec3_add(g, vec3_scale(vec3_sub(tri->b, g), 3)),
                     vec3_add(g, vec3_scale(vec3_sub(tri->c, g), 3)), tri->color };
    return reference_triangle_intersect(&big, ray, t);
}

/* ---- scenes and renders ------------------------------------------------ */

/* A colour for object k, different for each of the first 4096. */
static Vec3 color_of(int k)
{
    return vec3((k % 16) / 15.0, (k / 16 % 16) / 15.0, (k / 256 % 16) / 15.0);
}

/* A uniform number in [lo, hi). */
static double uniform(uint32_t *state, double lo, double hi)
{
    return lo + (hi - lo) * (check_xorshift32(state) / 4294967296.0);
}

/* An empty scene of nx x ny pixels, fov 70, eye at the origin. */
static Scene empty_scene(int nx, int ny)
{
    Scene s = { .nx = nx, .ny = ny, .fov_degrees = 70, .d = 1, .background = { 0.5, 0.5, 0.5 } };
    return s;
}

/* A random scene: n triangles of random sizes all around the eye (in
 * front, around and behind it, so that some boxes hold the eye), some of
 * them repeated later with another colour (exact ties), nspheres spheres
 * and one plane far behind.  Free it with free_random. */
static Scene random_scene(uint32_t seed, int n, int nspheres)
{
    Scene s = empty_scene(64, 48);
    uint32_t st = seed;
    s.triangles = malloc((size_t)n * sizeof *s.triangles);
    s.spheres = malloc(((size_t)nspheres + 1) * sizeof *s.spheres);
    s.planes = malloc(sizeof *s.planes);
    for (int k = 0; k < n; k++) {
        if (k > n / 2 && k % 7 == 0) {                /* a repeat of an earlier one */
            s.triangles[k] = s.triangles[check_xorshift32(&st) % (uint32_t)(n / 2)];
            s.triangles[k].color = color_of(k);
            continue;
        }
        Vec3 c = vec3(uniform(&st, -4, 4), uniform(&st, -3, 3), uniform(&st, -9, 2));
        double size = uniform(&st, 0.05, 1.5);
        Vec3 v[3];
        for (int i = 0; i < 3; i++)
            v[i] = vec3_add(c, vec3(uniform(&st, -size, size), uniform(&st, -size, size),
                                    uniform(&st, -size, size)));
        Triangle tri = { v[0], v[1], v[2], color_of(k) };
        s.triangles[k] = tri;
    }
    s.ntriangles = n;
    for (int k = 0; k < nspheres; k++) {
        Sphere sp = { vec3(uniform(&st, -4, 4), uniform(&st, -3, 3), uniform(&st, -9, 2)),
                      uniform(&st, 0.1, 1), color_of(k + 2000) };
        s.spheres[k] = sp;
    }
    s.nspheres = nspheres;
    s.spheres[nspheres] = scene_guard_sphere();
    Plane back = { vec3(0, 0, -20), vec3(0.1, 0.2, 1), vec3(0.9, 0.9, 0.1) };
    s.planes[0] = back;
    s.nplanes = 1;
    return s;
}

static void free_random(Scene *s)
{
    free(s->triangles);
    free(s->spheres);
    free(s->planes);
}

/* Renders scene with and without the hierarchy and checks the two images
 * are the same, byte for byte, and that the hierarchy was built where
 * closest.h draws the scene (not for spheres alone, which Part 3b draws);
 * *stray gets whether it was set aside for a stray hit.  what names the
 * case in a failure. */
static void check_same(const Scene *scene, const char *what, bool *stray)
{
    const bool closest = scene->nplanes > 0 || scene->ntriangles > 0;
    Image with, without;
    RenderStats sw, so;
    *stray = false;
    if (render_as(scene, RENDER_HIERARCHY_ON, 2, &with, &sw) < 0)
        return;
    if (render_as(scene, RENDER_HIERARCHY_OFF, 2, &without, &so) == 0) {
        size_t n = (size_t)scene->nx * scene->ny, differ = 0, first = n;
        for (size_t p = 0; p < n; p++)
            if (memcmp(with.rgb + 3 * p, without.rgb + 3 * p, 3) != 0 && differ++ == 0)
                first = p;
        CHECK_MSG(differ == 0, "%s: %zu pixels differ with and without the hierarchy, the first "
                  "(%zu, %zu)", what, differ, first % (size_t)scene->nx, first / (size_t)scene->nx);
        CHECK_MSG(closest ? sw.objects == scene->nspheres + scene->ntriangles && sw.nodes >= 1
                          : sw.objects == 0,
                  "%s: the hierarchy holds %d objects in %d nodes", what, sw.objects, sw.nodes);
        CHECK_MSG(so.objects == 0, "%s: a hierarchy was built with --hierarchy off", what);
        *stray = sw.stray;
        image_free(&without);
    }
    image_free(&with);
}

/* ---- the box test ------------------------------------------------------ */

/* Checks bvh_slab on one box and ray against line_in_box: where the exact
 * line meets the box, bvh_slab's interval holds it, widened by no more
 * than a relative 2^-19; where the line misses it by more than that, it
 * says so. */
static void check_slab(const double lo[3], const double hi[3], const Ray *ray, const char *what)
{
    BvhRay br;
    if (!bvh_ray(&br, ray)) {
        CHECK_MSG(0, "%s: bvh_ray refuses the ray", what);
        return;
    }
    const long double llo[3] = { lo[0], lo[1], lo[2] }, lhi[3] = { hi[0], hi[1], hi[2] };
    long double a, b;
    double t0 = 0, t1 = 0;
    bool in = bvh_slab(&br, lo, hi, &t0, &t1);
    if (line_in_box(llo, lhi, ray, &a, &b)) {
        CHECK_MSG(in && t0 <= a && b <= t1, "%s: the line is in the box for t in [%.17Lg, %.17Lg], "
                  "bvh_slab says %s [%.17g, %.17g]", what, a, b, in ? "" : "it misses,", t0, t1);
        CHECK_MSG(!in || (t0 >= a - fabsl(a) * 0x1p-19L - DBL_MIN && t1 <= b + fabsl(b) * 0x1p-19L + DBL_MIN),
                  "%s: [%.17g, %.17g] is much wider than [%.17Lg, %.17Lg]", what, t0, t1, a, b);
    } else {
        /* widened by 2^-18 on every side, it still misses: bvh_slab must too */
        long double wlo[3], whi[3];
        for (int k = 0; k < 3; k++) {
            long double m = fabsl(llo[k]) > fabsl(lhi[k]) ? fabsl(llo[k]) : fabsl(lhi[k]);
            long double e = (m + fabsl((&ray->origin.x)[k])) * 0x1p-18L;
            wlo[k] = llo[k] - e;
            whi[k] = lhi[k] + e;
        }
        if (!line_in_box(wlo, whi, ray, &a, &b))
            CHECK_MSG(!in, "%s: the line misses the box, bvh_slab says [%.17g, %.17g]", what, t0, t1);
    }
}

/* Lines in a face, along an edge, through a corner alone, of exact boxes;
 * zero direction components of either sign; and the line missing by the
 * least amount. */
static void test_slab_exact_cases(void)
{
    const double lo[3] = { 0, 0, 0 }, hi[3] = { 1, 1, 1 };
    const Ray cases[] = {
        { { 1, 0.5, 5 }, { 0, 0, -1 } },          /* in the face x = 1: t in [4, 5] */
        { { 1, 1, 5 }, { 0, 0, -1 } },            /* along the edge x = y = 1 */
        { { 0, 0, -3 }, { -0.0, 0.0, 2 } },       /* along the edge x = y = 0, from below */
        { { 0, 2, 2 }, { 1, -1, -1 } },           /* through the corner (1, 1, 1) alone, t = 1 */
        { { 0, 2, 1 }, { 1, -1, 0 } },            /* the same corner, in the face z = 1 */
        { { 0.5, 0.5, 0.5 }, { 0.3, -0.7, 0.1 } },/* from inside: t0 < 0 < t1 */
        { { 0.5, 0.5, 9 }, { 0, 0, 1 } },         /* wholly behind: t in [-9, -8] */
        { { 0.5, 0.5, 0.5 }, { 0, 0, 0 } },       /* no direction, from inside: every t */
        { { 0.5, 1, 0.5 }, { 0, -0.0, 0 } },      /* no direction, on a face */
        { { 0.5, 1.5, 0.5 }, { 0, 0, 0 } },       /* no direction, outside: no t */
        { { 2, 0.5, 0.5 }, { -1e-300, 1, 0 } },   /* not 0, below 2^-500: bvh_ray refuses it */
    };
    const size_t last = sizeof cases / sizeof cases[0] - 1;
    for (size_t k = 0; k < last; k++) {
        char what[64];
        snprintf(what, sizeof what, "exact case %zu", k);
        check_slab(lo, hi, &cases[k], what);
    }
    BvhRay br;
    CHECK_MSG(!bvh_ray(&br, &cases[last]), "bvh_ray takes a direction component of 1e-300");
    const Ray nan_ray = { { 0, 0, 0 }, { NAN, 0, 1 } }, big_origin = { { 0x1p501, 0, 0 }, { 0, 0, 1 } };
    CHECK(!bvh_ray(&br, &nan_ray));
    CHECK(!bvh_ray(&br, &big_origin));
    /* the line x = 1 + 2^-52 misses the face x = 1 by one step */
    const Ray past = { { 1 + 0x1p-52, 0.5, 5 }, { 0, 0, -1 } };
    double t0, t1;
    CHECK(bvh_ray(&br, &past));
    CHECK_MSG(!bvh_slab(&br, lo, hi, &t0, &t1), "a line parallel to a face, outside it, enters the box");
}

/* Random boxes and lines through points exactly on their faces, edges and
 * corners, where rounding decides: bvh_slab never loses one. */
static void test_slab_grazing(void)
{
    uint32_t st = 12345;
    for (int n = 0; n < 200000; n++) {
        double lo[3], hi[3], p[3];
        for (int k = 0; k < 3; k++) {
            double scale = ldexp(1, (int)(check_xorshift32(&st) % 40) - 20);
            lo[k] = uniform(&st, -1, 1) * scale;
            hi[k] = lo[k] + uniform(&st, 0, 1) * scale * (check_xorshift32(&st) % 8 == 0 ? 0 : 1);
            /* on the box: each coordinate a side's, or anywhere between */
            uint32_t pick = check_xorshift32(&st) % 3;
            p[k] = pick == 0 ? lo[k] : pick == 1 ? hi[k] : uniform(&st, lo[k], hi[k]);
        }
        Vec3 d = vec3(uniform(&st, -1, 1), uniform(&st, -1, 1), uniform(&st, -1, 1));
        if (check_xorshift32(&st) % 4 == 0)
            (&d.x)[check_xorshift32(&st) % 3] = 0;
        double s = uniform(&st, -10, 10);
        Ray ray = { vec3(p[0] - s * d.x, p[1] - s * d.y, p[2] - s * d.z), d };
        if (d.x == 0 && d.y == 0 && d.z == 0)
            continue;
        char what[64];
        snprintf(what, sizeof what, "grazing case %d", n);
        check_slab(lo, hi, &ray, what);
    }
}

/* ---- the build --------------------------------------------------------- */

/* Checks the hierarchy of scene: every object once, every box holding its
 * children's and its objects' exact boxes, leaves of 1 to 8 objects, no
 * path longer than BVH_MAX_DEPTH, the nodes a binary tree. */
static void check_structure(const Scene *scene, const char *what)
{
    Bvh bvh;
    char err[128];
    if (bvh_build(&bvh, scene, err, sizeof err) < 0) {
        CHECK_MSG(0, "%s: %s", what, err);
        return;
    }
    int n = scene->nspheres + scene->ntriangles;
    CHECK_EQ_INT(bvh.nitems, n);
    char *seen = calloc((size_t)n, 1);
    int leaves = 0, bad = 0, deepest = 0;
    struct { int node, depth; } stack[256];
    int top = 0;
    stack[top].node = 0;
    stack[top++].depth = 1;
    while (top > 0 && !bad) {
        top--;
        const BvhNode *nd = &bvh.nodes[stack[top].node];
        int depth = stack[top].depth;
        deepest = depth > deepest ? depth : deepest;
        if (nd->count > 0) {
            leaves++;
            bad |= nd->count > 8;
            for (int i = 0; i < nd->count && !bad; i++) {
                int32_t k = bvh.items[nd->first + i];
                bad |= k < 0 || k >= n || seen[k];
                if (bad)
                    break;
                seen[k] = 1;
                double lo[3], hi[3];
                bvh_object_box(scene, scene->nspheres, k, lo, hi);
                for (int a = 0; a < 3; a++)
                    bad |= !(nd->lo[a] <= lo[a] && hi[a] <= nd->hi[a]);
            }
            continue;
        }
        for (int c = 0; c < 2 && !bad; c++) {
            const BvhNode *child = &bvh.nodes[nd->first + c];
            bad |= nd->first < 1 || nd->first + 1 >= bvh.nnodes || top >= 255;
            for (int a = 0; a < 3 && !bad; a++)
                bad |= !(nd->lo[a] <= child->lo[a] && child->hi[a] <= nd->hi[a]);
            stack[top].node = nd->first + c;
            stack[top++].depth = depth + 1;
        }
    }
    int missing = 0;
    for (int k = 0; k < n; k++)
        missing += !seen[k];
    CHECK_MSG(!bad && missing == 0, "%s: a box, a leaf or an object is wrong (%d objects missing)",
              what, missing);
    CHECK_MSG(bvh.nnodes == 2 * leaves - 1, "%s: %d nodes for %d leaves", what, bvh.nnodes, leaves);
    CHECK_MSG(deepest <= BVH_MAX_DEPTH, "%s: a path of %d nodes", what, deepest);
    free(seen);
    bvh_free(&bvh);
}

static void test_structure(void)
{
    Scene s = random_scene(7, 3000, 40);
    check_structure(&s, "a random scene");
    /* every triangle the same: no split by the heuristic is possible */
    for (int k = 0; k < s.ntriangles; k++)
        s.triangles[k] = s.triangles[0];
    check_structure(&s, "one triangle 3000 times");
    /* beyond float's range, and tiny */
    s.ntriangles = 500;
    for (int k = 0; k < s.ntriangles; k++) {
        double x = k % 2 ? 1e300 : 1e-300;
        Triangle tri = { vec3(x, k, 0), vec3(-x, k + 1, 1), vec3(x * k, 0, -x), color_of(k) };
        s.triangles[k] = tri;
    }
    check_structure(&s, "huge and tiny triangles");
    s.ntriangles = 1;
    s.nspheres = 0;
    check_structure(&s, "one triangle");
    free_random(&s);
}

/* ---- the renders ------------------------------------------------------- */

/* The reference draws every shipped scene the same with and without the
 * hierarchy, and finds no stray hit.  cracks.scene at its own size, where
 * its rays run along the edges (in the sanitized build, whose sums are the
 * same, smaller); the others smaller.  (Part 3b draws the
 * scenes of spheres alone, with no hierarchy: check_same checks that too.) */
static void test_shipped_scenes_reference(void)
{
    static const char *const names[] = { "default", "flip", "wide", "behind", "inside", "far",
                                         "ground", "triangles", "cracks", "knot" };
    for (int k = 0; k < CHECK_COUNT(names); k++) {
        char path[128];
        snprintf(path, sizeof path, "labs/scenes/%s.scene", names[k]);
        Scene scene;
        if (load_scene(&scene, path, 0, 0) < 0)
            continue;
        if (strcmp(names[k], "cracks") != 0 || CHECK_SANITIZED) {
            bool big = strcmp(names[k], "knot") == 0 || CHECK_SANITIZED;  /* 10,000 triangles a ray */
            scene.nx = big ? 64 : 160;
            scene.ny = big ? 48 : 120;
        }
        bool stray;
        check_same(&scene, path, &stray);
        CHECK_MSG(!stray, "%s: the reference made a stray hit", path);
        scene_free(&scene);
    }
}

/* With the hierarchy, the reference still lets no ray through
 * cracks.scene: the box's front face spans the pixel centres from (64, 48)
 * to (256, 192) (tests/tools/cracks-mesh.sh), and every pixel inside that
 * rim, whose rays cross the box, many through shared edges, is the box's
 * colour.  (The rays of the rim itself graze the side walls, whose planes
 * hold the eye: rounding decides those.) */
static void test_cracks_watertight(void)
{
    Scene scene;
    if (load_scene(&scene, "labs/scenes/cracks.scene", 0, 0) < 0)
        return;
    Image img;
    RenderStats stats;
    if (render_as(&scene, RENDER_HIERARCHY_ON, 2, &img, &stats) == 0) {
        const Vec3 c = scene.triangles[0].color;
        const unsigned char want[3] = { image_channel(c.x), image_channel(c.y), image_channel(c.z) };
        int through = 0;
        for (int j = 49; j < 192; j++)
            for (int i = 65; i < 256; i++)
                through += memcmp(img.rgb + 3 * ((size_t)j * scene.nx + i), want, 3) != 0;
        CHECK_MSG(through == 0, "%d rays went through the box", through);
        CHECK(stats.objects == 516 && !stats.stray);
        image_free(&img);
    }
    scene_free(&scene);
}

/* Random scenes of triangles, spheres and a plane: the same pictures with
 * and without the hierarchy, for the reference and for functions that are
 * wrong but honest: hits anywhere in the box, at t on a grid (ties by the
 * hundred), at NaN, at +inf, with t unset, and behind the eye.  Functions
 * that hit outside the box are found out, and the picture is the plain
 * loop's. */
static void test_random_scenes(void)
{
    const struct { SphereFn *sphere; TriangleFn *triangle; const char *name; bool stray; } fns[] = {
        { reference_sphere_intersect, reference_triangle_intersect, "the reference", false },
        { box_hit_sphere, box_hit_triangle, "hits anywhere in the boxes", false },
        { reference_sphere_intersect, box_hit_triangle, "triangles hit anywhere in their boxes", false },
        { reference_sphere_intersect, negated_triangle, "hits at -t", true },
        { reference_sphere_intersect, grown_triangle, "hits in the triangle grown three times", true },
    };
    for (int f = 0; f < CHECK_COUNT(fns); f++)
        for (uint32_t seed = 1; seed <= (fns[f].stray ? 3u : CHECK_SANITIZED ? 2u : 4u); seed++) {
            sphere_fn = fns[f].sphere;
            triangle_fn = fns[f].triangle;
            Scene s = fns[f].stray ? random_scene(seed * 104729, 300 * (int)seed, 3)
                                   : random_scene(seed * 7919, 400 * (int)seed, (int)seed * 5);
            char what[128];
            snprintf(what, sizeof what, "%s, random scene %u", fns[f].name, seed);
            bool stray;
            check_same(&s, what, &stray);
            CHECK_MSG(stray == fns[f].stray, "%s: %s", what,
                      stray ? "a stray hit, from a function that makes none" : "no stray hit found");
            free_random(&s);
        }
    sphere_fn = reference_sphere_intersect;
    triangle_fn = reference_triangle_intersect;
}

/* A triangle out of view whose grown copy reaches into it: no ray of the
 * render comes near the triangle's box, so only closest_probe can find the
 * stray hits that the plain loop draws. */
static void test_probe_finds_what_rays_do_not(void)
{
    Scene s = empty_scene(64, 48);
    Triangle tris[20];
    for (int k = 0; k < 20; k++) {
        /* left of the view (fov 70: |x| < 0.93 z at this aspect), 1 wide */
        Triangle tri = { vec3(-6.5, -0.5 + 0.05 * k, -5), vec3(-5.5, -0.5, -5),
                         vec3(-6, 0.5, -5 - 0.01 * k), color_of(k) };
        tris[k] = tri;
    }
    s.triangles = tris;
    s.ntriangles = 20;
    Sphere guard[1] = { scene_guard_sphere() };
    s.spheres = guard;
    Bvh bvh;
    char err[128];
    CHECK(bvh_build(&bvh, &s, err, sizeof err) == 0);
    triangle_fn = grown_triangle;
    CHECK_MSG(closest_probe(&s, &bvh), "the probe finds no stray hit of the grown triangles");
    bool stray;
    check_same(&s, "grown triangles out of view", &stray);
    CHECK(stray);
    triangle_fn = reference_triangle_intersect;
    CHECK_MSG(!closest_probe(&s, &bvh), "the probe finds a stray hit of the reference");
    bvh_free(&bvh);
}

/* The hierarchy is used, not walked whole: on knot.scene (10,000
 * triangles) a camera ray tests a hundredth of them or fewer. */
static void test_prunes(void)
{
    Scene scene;
    char err[128];
    if (load_scene(&scene, "labs/scenes/knot.scene", 0, 0) < 0)
        return;
    Bvh bvh;
    CHECK(bvh_build(&bvh, &scene, err, sizeof err) == 0);
    const int nx = 64, ny = 48;
    double w, h;
    image_plane_size(scene.fov_degrees, (double)nx / ny, scene.d, &w, &h);
    atomic_store(&triangle_calls, 0);
    bool stray = false;
    int hits = 0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            Ray ray = camera_ray(scene.eye, pixel_coordinates(i, j, nx, ny, w, h, scene.d));
            Vec3 c = closest_color_bvh(&scene, &bvh, &ray, &stray);
            hits += memcmp(&c, &scene.background, sizeof c) != 0;
        }
    long per_ray = atomic_load(&triangle_calls) / (nx * ny);
    CHECK_MSG(per_ray <= 100, "%ld triangle tests a ray", per_ray);
    CHECK_MSG(hits > nx * ny / 10 && !stray, "%d rays of %d hit the knot", hits, nx * ny);
    bvh_free(&bvh);
    scene_free(&scene);
}

/* Below RENDER_HIERARCHY_MIN objects none is built, unless asked for. */
static void test_small_scenes_build_none(void)
{
    Scene s = random_scene(3, RENDER_HIERARCHY_MIN - 1, 1);
    for (int enough = 0; enough < 2; enough++) {
        s.ntriangles = RENDER_HIERARCHY_MIN - 2 + enough;     /* and one sphere */
        Image img;
        RenderStats stats;
        if (render_as(&s, RENDER_HIERARCHY_AUTO, 1, &img, &stats) == 0) {
            CHECK_EQ_INT(stats.objects, enough ? RENDER_HIERARCHY_MIN : 0);
            image_free(&img);
        }
    }
    free_random(&s);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_slab_exact_cases),
    CHECK_TEST(test_slab_grazing),
    CHECK_TEST(test_structure),
    CHECK_TEST(test_shipped_scenes_reference),
    CHECK_TEST(test_cracks_watertight),
    CHECK_TEST(test_random_scenes),
    CHECK_TEST(test_probe_finds_what_rays_do_not),
    CHECK_TEST(test_prunes),
    CHECK_TEST(test_small_scenes_build_none),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
