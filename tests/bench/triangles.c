/*
 * triangles.c - Part 5 in `make bench`: each ray/triangle formulation's
 * speed, its error of t against the exact answers of tests/oracle, and the
 * rays it lets through closed meshes.
 *
 *   throughput   every method's closest-hit loop over the camera rays of
 *                cracks.scene (a closed box of 516 triangles) at its own
 *                size, interleaved rounds, medians
 *   errors       every method on the hard families of Part 5
 *                (tests/oracle/hard.h): relative error of t on the hits
 *                the oracle is sure of, wrong hit/miss per million, error in
 *                units of u kappa, and the grader's rule for those cases
 *   cracks       rays from outside aimed at shared edges and vertices of
 *                closed meshes (hard_mesh_ray_at), near the origin and at
 *                offsets 10^3 to 10^6: a crack is a ray no triangle stops
 *                where it enters the mesh
 * Writes results_triangles.csv and plot_triangles.svg; report.c puts the
 * table in report.md.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "kit/scene.h"
#include "../oracle/draw.h"
#include "../oracle/hard.h"
#include "bench.h"
#include "svg.h"

#define U 0x1p-53

/* The formulations compared; the reference is the linked solution. */
const TriMethod tri_methods[] = {
    { "reference", PREC_DOUBLE, triangle_intersect, NULL },
    { "moller-trumbore", PREC_DOUBLE, tri_moller_trumbore_d, NULL },
    { "moller-trumbore", PREC_FLOAT, NULL, tri_moller_trumbore_f },
    { "wbw-plain", PREC_DOUBLE, tri_wbw_plain_d, NULL },
    { "geometric", PREC_DOUBLE, tri_geometric_d, NULL },
};
const int tri_nmethods = (int)(sizeof tri_methods / sizeof tri_methods[0]);

static Trianglef trianglef_from(const Triangle *t)
{
    Trianglef f = { vec3f_from(t->a), vec3f_from(t->b), vec3f_from(t->c) };
    return f;
}

/* One test at the method's precision: float methods get the inputs rounded
 * to float, as a float renderer would. */
static bool tri_one(const TriMethod *m, const Triangle *tri, const Ray *ray, double *t)
{
    if (m->fn_d)
        return m->fn_d(tri, ray, t);
    Trianglef tf = trianglef_from(tri);
    Rayf rf = rayf_from(ray);
    float ft;
    bool hit = m->fn_f(&tf, &rf, &ft);
    *t = ft;
    return hit;
}

/* The first hit over n triangles (and their float copies), INFINITY for none. */
static double tri_closest(const TriMethod *m, const Triangle *tris, const Trianglef *trisf, int n,
                          const Ray *ray, const Rayf *rayf)
{
    double best = INFINITY;
    if (m->fn_d) {
        for (int k = 0; k < n; k++) {
            double t;
            if (m->fn_d(&tris[k], ray, &t) && t < best)
                best = t;
        }
    } else {
        float bestf = INFINITY;
        for (int k = 0; k < n; k++) {
            float t;
            if (m->fn_f(&trisf[k], rayf, &t) && t < bestf)
                bestf = t;
        }
        best = bestf;
    }
    return best;
}

/* ---- throughput ------------------------------------------------------------ */

static int stage_throughput(const char *scenes, bool quick, TriResults *tr, char *err, size_t errlen)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/cracks.scene", scenes);
    Scene scene;
    if (scene_load(&scene, path, err, errlen) != 0)
        return -1;
    int step = quick ? 4 : 1, nx = scene.nx, ny = scene.ny;
    int nr = ((nx + step - 1) / step) * ((ny + step - 1) / step), n = scene.ntriangles;
    Ray *rays = malloc((size_t)nr * sizeof *rays);
    Rayf *raysf = malloc((size_t)nr * sizeof *raysf);
    Trianglef *trisf = malloc((size_t)(n > 0 ? n : 1) * sizeof *trisf);
    int rounds = quick ? 3 : 21;
    double *secs = malloc((size_t)rounds * tri_nmethods * sizeof *secs);
    if (!rays || !raysf || !trisf || !secs) {
        snprintf(err, errlen, "out of memory");
        free(rays), free(raysf), free(trisf), free(secs);
        scene_free(&scene);
        return -1;
    }
    double w, h;
    image_plane_size(scene.fov_degrees, (double)nx / ny, scene.d, &w, &h);
    int r = 0;
    for (int j = 0; j < ny; j += step)
        for (int i = 0; i < nx; i += step, r++) {
            rays[r] = camera_ray(scene.eye, pixel_coordinates(i, j, nx, ny, w, h, scene.d));
            raysf[r] = rayf_from(&rays[r]);
        }
    for (int k = 0; k < n; k++)
        trisf[k] = trianglef_from(&scene.triangles[k]);
    tr->tp_rays = nr;
    tr->tp_triangles = n;
    /* Rounds of every method once, the order rotated each round. */
    for (int round = 0; round < rounds; round++) {
        progress("triangles: throughput", round, rounds);
        for (int q = 0; q < tri_nmethods; q++) {
            int m = (q + round) % tri_nmethods;
            double start = now_seconds(), sum = 0;
            for (int i = 0; i < nr; i++) {
                double t = tri_closest(&tri_methods[m], scene.triangles, trisf, n, &rays[i], &raysf[i]);
                sum += t < INFINITY ? t : 0;
            }
            secs[round * tri_nmethods + m] = now_seconds() - start;
            bench_sink += sum;
        }
    }
    for (int m = 0; m < tri_nmethods; m++) {
        double s[512];
        for (int round = 0; round < rounds; round++)
            s[round] = secs[round * tri_nmethods + m];
        double med = median(s, rounds);
        tr->mtests[m] = med > 0 ? (double)nr * n / med / 1e6 : 0;
    }
    free(rays), free(raysf), free(trisf), free(secs);
    scene_free(&scene);
    return 0;
}

/* ---- errors ------------------------------------------------------------------ */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int stage_errors(bool quick, uint64_t seed, TriResults *tr, char *err, size_t errlen)
{
    int n = HARD_PART5_FAMILIES * (quick ? 100 : 3000);
    HardCase5 *cases = malloc((size_t)n * sizeof *cases);
    double *rel = malloc((size_t)n * sizeof *rel);
    if (!cases || !rel) {
        snprintf(err, errlen, "out of memory");
        free(cases), free(rel);
        return -1;
    }
    progress("triangles: exact answers", 0, 1);
    hard_part5(seed, cases, n);
    tr->error_cases = n;
    for (int m = 0; m < tri_nmethods; m++) {
        progress("triangles: errors", m, tri_nmethods);
        TriErrors *e = &tr->err[m];
        memset(e, 0, sizeof *e);
        long nrel = 0;
        for (int k = 0; k < n; k++) {
            const OracleFlat *o = &cases[k].expect;
            double t = 0;
            bool hit = tri_one(&tri_methods[m], &cases[k].tri, &cases[k].ray, &t);
            e->hard_failed += !hard_check5(&cases[k], hit, t);
            if (o->ambiguous) {
                e->ambiguous++;
                continue;
            }
            if (hit != o->hit) {
                e->wrong++;
                continue;
            }
            if (!hit)
                continue;
            double r = fabs(t - o->t) / o->t;
            rel[nrel++] = r;
            if (r / (U * o->kappa) > e->max_over_kappa)
                e->max_over_kappa = r / (U * o->kappa);
            if (k % HARD_PART5_FAMILIES == 0 && r > e->max_rel_ordinary)
                e->max_rel_ordinary = r;
            if (o->kappa <= 100 && r / U > e->max_u_well)
                e->max_u_well = r / U;
        }
        qsort(rel, (size_t)nrel, sizeof *rel, cmp_double);
        e->hits = nrel;
        e->max_rel = nrel ? rel[nrel - 1] : 0;
        e->median_rel = nrel ? rel[nrel / 2] : 0;
    }
    free(cases);
    free(rel);
    return 0;
}

/* ---- cracks ------------------------------------------------------------------ */

static void stage_cracks(bool quick, uint64_t seed, TriResults *tr)
{
    /* Per method and kind (0 edge near, 1 vertex near, 2 edge far,
     * 3 vertex far): rays, and rays that went through.  A stop within
     * 1e-4 of the entry's t counts, whatever the precision: the far side
     * of a mesh is at least a fifth of that t further on. */
    const long per_kind = quick ? 3000 : 30000;
    const int per_mesh = 200;
    uint64_t s = seed ^ 0x5DEECE66Du;
    HardMesh mesh;
    memset(tr->cracks, 0, sizeof tr->cracks);
    for (int kind = 0; kind < 4; kind++) {
        bool vertex = kind % 2 == 1, far = kind >= 2;
        for (long done = 0, k = 0; done < per_kind; k++) {
            progress("triangles: cracks", (int)(kind * per_kind + done), (int)(4 * per_kind));
            double off = far ? draw_log(&s, 1e3, 1e6) : 0;
            Vec3 dir = vec3(hard_rng_uniform(&s) - 0.5, hard_rng_uniform(&s) - 0.5, hard_rng_uniform(&s) - 0.5);
            Vec3 offset = far ? vec3_scale(vec3_normalize(dir), off) : vec3_scale(dir, 20);
            double size = ldexp(1 + hard_rng_uniform(&s), (int)(hard_rng_next(&s) % 8) - 4);
            hard_mesh_make(&s, (int)(k % HARD_MESH_SHAPES), size, offset, &mesh);
            for (int r = 0; r < per_mesh && done < per_kind; r++, done++) {
                double entry;
                Ray ray = hard_mesh_ray_at(&s, &mesh, vertex, &entry);
                for (int m = 0; m < tri_nmethods; m++) {
                    bool stopped = false;
                    for (int i = 0; i < mesh.ntris && !stopped; i++) {
                        double t;
                        stopped = tri_one(&tri_methods[m], &mesh.tris[i], &ray, &t)
                                  && fabs(t - entry) <= 1e-4 * entry;
                    }
                    tr->cracks[m][kind] += !stopped;
                }
            }
        }
    }
    tr->crack_rays_per_kind = per_kind;
}

int triangle_bench(const char *scenes, bool quick, uint64_t seed, TriResults *tr, char *err,
                   size_t errlen)
{
    memset(tr, 0, sizeof *tr);
    tr->ran = true;
    if (stage_throughput(scenes, quick, tr, err, errlen) != 0)
        return -1;
    if (stage_errors(quick, seed, tr, err, errlen) != 0)
        return -1;
    stage_cracks(quick, seed, tr);
    return 0;
}

/* ---- output ---------------------------------------------------------------------- */

double tri_cracks_per_million(const TriResults *tr, int m)
{
    long through = 0;
    for (int k = 0; k < 4; k++)
        through += tr->cracks[m][k];
    return tr->crack_rays_per_kind > 0 ? 1e6 * through / (4.0 * tr->crack_rays_per_kind) : 0;
}

static double per_million(long count, long of)
{
    return of > 0 ? 1e6 * count / of : 0;
}

int triangles_write(const TriResults *tr, const char *dir, const char *subtitle, char *err,
                    size_t errlen)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/results_triangles.csv", dir);
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, errlen, "%s: cannot write", path);
        return -1;
    }
    fprintf(f, "method,precision,mtests_per_s,max_rel_err,median_rel_err,max_rel_err_ordinary,"
               "max_err_u_kappa_le_100,wrong_per_million,max_err_over_u_kappa,hard_failed,hard_cases,cracks_per_million,"
               "cracks_edges,cracks_vertices,cracks_far_edges,cracks_far_vertices,rays_per_kind\n");
    for (int m = 0; m < tri_nmethods; m++) {
        const TriErrors *e = &tr->err[m];
        long judged = tr->error_cases - e->ambiguous;
        fprintf(f, "%s,%s,%.6g,%.3e,%.3e,%.3e,%.3g,%.6g,%.3e,%ld,%d,%.6g,%ld,%ld,%ld,%ld,%ld\n",
                tri_methods[m].name, precision_name(tri_methods[m].precision), tr->mtests[m],
                e->max_rel, e->median_rel, e->max_rel_ordinary, e->max_u_well,
                per_million(e->wrong, judged),
                e->max_over_kappa, e->hard_failed, tr->error_cases, tri_cracks_per_million(tr, m),
                tr->cracks[m][0], tr->cracks[m][1], tr->cracks[m][2], tr->cracks[m][3],
                tr->crack_rays_per_kind);
    }
    if (fclose(f) != 0) {
        snprintf(err, errlen, "%s: write failed", path);
        return -1;
    }

    /* The plot: speed against cracks, and speed against the error of t. */
    static PlotPoint cracks[BENCH_MAX_METHODS], errs[BENCH_MAX_METHODS];
    static char labels[BENCH_MAX_METHODS][48];
    for (int m = 0; m < tri_nmethods; m++) {
        snprintf(labels[m], sizeof labels[m], "%s %s", tri_methods[m].name,
                 precision_name(tri_methods[m].precision));
        int group = tri_methods[m].precision == PREC_DOUBLE ? 0 : 1;
        PlotPoint c = { labels[m], fmax(tri_cracks_per_million(tr, m), 0.01), tr->mtests[m], group };
        PlotPoint e = { labels[m], tr->err[m].max_over_kappa, tr->mtests[m], group };
        cracks[m] = c;
        errs[m] = e;
    }
    PlotPanel panels[2] = {
        { cracks, tri_nmethods, "Rays through closed meshes, aimed at shared edges and vertices",
          "cracks per million rays (log scale; 0 is drawn at 0.01; smaller is better)",
          "million ray/triangle tests per second" },
        { errs, tri_nmethods, "Worst error of t on the hard families, in units of u kappa",
          "max |t - t_exact| / (u kappa t_exact), u = 2^-53 (log scale; smaller is better)",
          "million ray/triangle tests per second" },
    };
    snprintf(path, sizeof path, "%s/plot_triangles.svg", dir);
    return svg_plot(path, "Ray/triangle intersection: speed against watertightness and accuracy",
                    subtitle, panels, 2, err, errlen);
}

void triangles_md(FILE *f, const TriResults *tr)
{
    if (!tr->ran)
        return;
    fprintf(f, "\n## Part 5: ray/triangle\n\n");
    fprintf(f, "Throughput: every method's closest-hit loop over the camera rays of cracks.scene "
               "(%d rays x %d triangles, one thread). Errors: %d hard cases of Part 5's families "
               "(tests/oracle/hard.h) against the exact oracle. Cracks: %ld rays each at shared "
               "edges and at shared vertices of closed meshes near the origin, and as many at "
               "offsets 10^3 to 10^6; a crack is a ray that no triangle stops where it enters "
               "the mesh. kappa is the condition number of t (oracle.h): \"kappa <= 100\" are the "
               "well-conditioned hits.\n\n",
            tr->tp_rays, tr->tp_triangles, tr->error_cases, tr->crack_rays_per_kind);
    fprintf(f, "| method | precision | Mtests/s | max rel. error | median rel. error | max error in u, "
               "kappa <= 100 | wrong per million | max error / (u kappa) | grader's hard cases failed | "
               "cracks per million | edges | vertices | far edges | far vertices |\n");
    fprintf(f, "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int m = 0; m < tri_nmethods; m++) {
        const TriErrors *e = &tr->err[m];
        long judged = tr->error_cases - e->ambiguous;
        fprintf(f, "| %s | %s | %.0f | %.2g | %.2g | %.3g | %.0f | %.2g | %ld / %d | %.0f | %ld | %ld | "
                   "%ld | %ld |\n",
                tri_methods[m].name, precision_name(tri_methods[m].precision), tr->mtests[m],
                e->max_rel, e->median_rel, e->max_u_well, per_million(e->wrong, judged),
                e->max_over_kappa, e->hard_failed, tr->error_cases, tri_cracks_per_million(tr, m),
                tr->cracks[m][0], tr->cracks[m][1], tr->cracks[m][2], tr->cracks[m][3]);
    }
    fprintf(f, "\nThe reference pays for watertightness with a shear of the vertices per test "
               "and, near an edge, exact signs from fma: it lets no ray through, where "
               "Moller-Trumbore, faster, lets through some of the rays aimed at shared edges and "
               "more of those aimed at shared vertices. Woop, Benthin and Wald's test without "
               "exact signs let none through here either: two triangles that share an edge "
               "compute its function from the same two projected points, so an edge cannot "
               "leak; at a shared vertex three or more rounded edge functions meet, and only "
               "exact signs guarantee that their signs agree. The geometric method, which finds "
               "the hit point from t first, misjudges slivers and leaks. Float loses both "
               "accuracy and watertightness. Plot: plot_triangles.svg.\n");
}
