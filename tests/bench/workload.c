/*
 * workload.c - the rays the benchmark measures with.
 *
 *   rayset_camera  camera rays of a scene, the ordinary workload: rays start
 *                  at the eye and most of them miss most spheres
 *   cases_scene    every (camera ray, sphere) pair of a scene
 *   cases_hard     the hard families, from a fixed seed:
 *     far      small spheres far away: D/R from 10 to 10^7 (far.scene is
 *              10^7), rays aimed within 1.5 R of the centre
 *     near     origins close to big spheres: height above (or depth below)
 *              the surface from R 10^-1 down to R 10^-12, any direction
 *     tangent  rays that pass the centre at R (1 +- delta), delta from
 *              10^-2 down to 10^-14: grazing hits and near misses
 * Camera rays come from the reference's parts 1, 2 and 3b (linked), so they
 * are exactly the rays the lab's renderer shoots.
 */
#include <math.h>
#include <stdlib.h>
#include "bench.h"

int rayset_alloc(RaySet *rs, int n)
{
    size_t m = n > 0 ? (size_t)n : 1;
    rs->n = n;
    rs->rays = malloc(m * sizeof *rs->rays);
    rs->raysf = malloc(m * sizeof *rs->raysf);
    rs->dx = malloc(3 * m * sizeof(double));
    rs->fdx = malloc(3 * m * sizeof(float));
    if (!rs->rays || !rs->raysf || !rs->dx || !rs->fdx) {
        rayset_free(rs);
        return -1;
    }
    rs->dy = rs->dx + m;
    rs->dz = rs->dx + 2 * m;
    rs->fdy = rs->fdx + m;
    rs->fdz = rs->fdx + 2 * m;
    return 0;
}

void rayset_free(RaySet *rs)
{
    free(rs->rays);
    free(rs->raysf);
    free(rs->dx);
    free(rs->fdx);
    RaySet empty = { 0 };
    *rs = empty;
}

void rayset_put(RaySet *rs, int i, Ray ray, unsigned layouts)
{
    if (layouts & LAYOUT_AOS_D)
        rs->rays[i] = ray;
    if (layouts & LAYOUT_AOS_F)
        rs->raysf[i] = rayf_from(&ray);
    if (layouts & LAYOUT_SOA_D) {
        rs->dx[i] = ray.direction.x;
        rs->dy[i] = ray.direction.y;
        rs->dz[i] = ray.direction.z;
    }
    if (layouts & LAYOUT_SOA_F) {
        rs->fdx[i] = (float)ray.direction.x;
        rs->fdy[i] = (float)ray.direction.y;
        rs->fdz[i] = (float)ray.direction.z;
    }
}

int rayset_camera(RaySet *rs, const Scene *scene, int nx, int ny, int step)
{
    double w, h;
    image_plane_size(scene->fov_degrees, (double)nx / ny, scene->d, &w, &h);
    int cols = (nx + step - 1) / step, rows = (ny + step - 1) / step;
    if (rayset_alloc(rs, cols * rows) != 0)
        return -1;
    int k = 0;
    for (int j = 0; j < ny; j += step)
        for (int i = 0; i < nx; i += step) {
            Vec3 pixel = pixel_coordinates(i, j, nx, ny, w, h, scene->d);
            rayset_put(rs, k++, camera_ray(scene->eye, pixel), ~0u);
        }
    return 0;
}

Case *cases_scene(const Scene *scene, int step, int *n)
{
    RaySet rs;
    *n = 0;
    if (rayset_camera(&rs, scene, scene->nx, scene->ny, step) != 0)
        return NULL;
    size_t per_ray = (size_t)(scene->nspheres > 0 ? scene->nspheres : 1);
    Case *cases = malloc((size_t)rs.n * per_ray * sizeof *cases);
    if (cases) {
        for (int i = 0; i < rs.n; i++)
            for (int k = 0; k < scene->nspheres; k++) {
                Case c = { scene->spheres[k], rs.rays[i] };
                cases[(*n)++] = c;
            }
    }
    rayset_free(&rs);
    return cases;
}

/* ---- the hard families ---------------------------------------------------- */

/* splitmix64: a small, fixed, portable generator. */
static uint64_t next_u64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static double uniform(uint64_t *state)          /* [0, 1) */
{
    return (double)(next_u64(state) >> 11) * 0x1p-53;
}

static double between(uint64_t *state, double lo, double hi)
{
    return lo + (hi - lo) * uniform(state);
}

static Vec3 random_unit(uint64_t *state)
{
    for (;;) {
        Vec3 v = vec3(between(state, -1, 1), between(state, -1, 1), between(state, -1, 1));
        double len2 = vec3_dot(v, v);
        if (len2 > 0.01 && len2 <= 1)
            return vec3_normalize(v);
    }
}

/* A unit vector perpendicular to the unit vector u. */
static Vec3 perpendicular(uint64_t *state, Vec3 u)
{
    for (;;) {
        Vec3 v = random_unit(state);
        Vec3 p = vec3_sub(v, vec3_scale(u, vec3_dot(u, v)));
        if (vec3_length(p) > 0.1)
            return vec3_normalize(p);
    }
}

/* An origin: the eye (half the time) or a point in the cube [-1, 1]^3. */
static Vec3 random_origin(uint64_t *state)
{
    if (uniform(state) < 0.5)
        return vec3(0, 0, 0);
    return vec3(between(state, -1, 1), between(state, -1, 1), between(state, -1, 1));
}

static Case make_far(uint64_t *state)
{
    Vec3 e = random_origin(state);
    double D = pow(10, between(state, 0, 3));
    double R = D / pow(10, between(state, 1, 7));
    Vec3 u = random_unit(state);
    Vec3 c = vec3_add(e, vec3_scale(u, D));
    /* aim at a point of the disc of radius 1.5 R around c, facing e */
    double rho = 1.5 * R * sqrt(uniform(state));
    Vec3 aim = vec3_add(c, vec3_scale(perpendicular(state, u), rho));
    Case k = { { c, R, vec3(1, 1, 1) }, { e, vec3_normalize(vec3_sub(aim, e)) } };
    return k;
}

static Case make_near(uint64_t *state)
{
    double R = pow(10, between(state, 0, 4));
    Vec3 c = vec3_scale(random_unit(state), R * between(state, 0, 2));
    Vec3 n = random_unit(state);
    double h = R * pow(10, -between(state, 1, 12));
    if (uniform(state) < 0.5)
        h = -h;                                   /* just inside */
    Vec3 e = vec3_add(c, vec3_scale(n, R + h));
    Case k = { { c, R, vec3(1, 1, 1) }, { e, random_unit(state) } };
    return k;
}

static Case make_tangent(uint64_t *state)
{
    Vec3 e = random_origin(state);
    double R = pow(10, between(state, -1, 2));
    double D = R * pow(10, between(state, 0.2, 3));
    Vec3 u = random_unit(state);
    Vec3 c = vec3_add(e, vec3_scale(u, D));
    double delta = pow(10, -between(state, 2, 14));
    if (uniform(state) < 0.5)
        delta = -delta;
    double sin_a = R * (1 + delta) / D;           /* distance of the line from c */
    double cos_a = sqrt(1 - sin_a * sin_a);
    Vec3 w = perpendicular(state, u);
    Vec3 r = vec3_add(vec3_scale(u, cos_a), vec3_scale(w, sin_a));
    Case k = { { c, R, vec3(1, 1, 1) }, { e, vec3_normalize(r) } };
    return k;
}

Case *cases_hard(Family f, int n, uint64_t seed)
{
    Case *cases = malloc((size_t)(n > 0 ? n : 1) * sizeof *cases);
    if (!cases)
        return NULL;
    uint64_t state = seed ^ (0x5eed0000ull + (uint64_t)f);
    for (int i = 0; i < n; i++)
        cases[i] = f == FAMILY_FAR ? make_far(&state)
                 : f == FAMILY_NEAR ? make_near(&state)
                 : make_tangent(&state);
    return cases;
}

const char *const family_names[FAMILY_COUNT] = { "scene", "far", "near", "tangent" };
const char *const family_titles[FAMILY_COUNT] = {
    "ordinary scene (default.scene, every camera ray against every sphere)",
    "far small spheres (D/R from 10 to 10^7)",
    "origins near big spheres (height R 10^-12 to R 10^-1, either side)",
    "near-tangent rays (line passes the centre at R (1 +- 10^-14 .. 10^-2))",
};
