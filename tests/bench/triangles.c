/*
 * triangles.c - Part 5 in `make bench`: each ray/triangle formulation's
 * speed, its error of t against the exact answers of tests/oracle, and the
 * rays it lets through closed meshes.
 *
 *   throughput   every method's closest-hit loop over the camera rays of
 *                cracks.scene (a closed box of 516 triangles) at its own
 *                size, interleaved rounds, medians
 *   errors       every method on an ordinary workload (triangles ahead
 *                of the eye, camera rays) and on the hard families of
 *                Part 5 (tests/oracle/hard.h): relative error of t on the
 *                hits the oracle is sure of, wrong hit/miss per million,
 *                error in units of u kappa, and the grader's rule
 *   cracks       rays from outside aimed at shared edges and vertices of
 *                closed meshes (hard_mesh_ray_at), near the origin and at
 *                offsets 10^3 to 10^6: a crack is a ray no triangle stops
 *                where it enters the mesh; float methods are judged on
 *                the mesh rounded to float, with rays aimed at it
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

/* The formulations compared; the reference is the linked solution. */
enum { REF, MT, MT_FLOAT, WBW_PLAIN, GEOMETRIC };
const TriMethod tri_methods[] = {
    [REF] = { "reference", PREC_DOUBLE, triangle_intersect, NULL },
    [MT] = { "moller-trumbore", PREC_DOUBLE, tri_moller_trumbore_d, NULL },
    [MT_FLOAT] = { "moller-trumbore", PREC_FLOAT, NULL, tri_moller_trumbore_f },
    [WBW_PLAIN] = { "wbw-plain", PREC_DOUBLE, tri_wbw_plain_d, NULL },
    [GEOMETRIC] = { "geometric", PREC_DOUBLE, tri_geometric_d, NULL },
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

static int step_throughput(const char *scenes, bool quick, TriResults *tr, char *err, size_t errlen)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/cracks.scene", scenes);
    Scene scene;
    if (scene_load(&scene, path, err, errlen) != 0)
        return -1;
    RaySet rs;
    int n = scene.ntriangles, rounds = quick ? 3 : 21;
    int rsok = rayset_camera(&rs, &scene, scene.nx, scene.ny, quick ? 4 : 1) == 0, nr = rs.n;
    Trianglef *trisf = malloc((size_t)(n > 0 ? n : 1) * sizeof *trisf);
    double *secs = malloc((size_t)rounds * tri_nmethods * sizeof *secs);
    if (!rsok || !trisf || !secs) {
        snprintf(err, errlen, "out of memory");
        rayset_free(&rs);           /* rayset_camera leaves it empty if it fails */
        free(trisf), free(secs);
        scene_free(&scene);
        return -1;
    }
    for (int k = 0; k < n; k++)
        trisf[k] = trianglef_from(&scene.triangles[k]);
    tr->tp_rays = nr;
    tr->tp_triangles = n;
    for (Rounds it = { .n = tri_nmethods, .rounds = rounds }; rounds_next(&it);) {
        if (it.j == 0)
            progress("triangles: throughput", it.r, rounds);
        double start = now_seconds(), sum = 0;
        for (int i = 0; i < nr; i++) {
            double t = tri_closest(&tri_methods[it.m], scene.triangles, trisf, n, &rs.rays[i],
                                   &rs.raysf[i]);
            sum += t < INFINITY ? t : 0;
        }
        secs[it.m * rounds + it.r] = now_seconds() - start;
        bench_sink += sum;
    }
    for (int m = 0; m < tri_nmethods; m++) {
        double med = median(secs + m * rounds, rounds);
        tr->mtests[m] = med > 0 ? (double)nr * n / med / 1e6 : 0;
    }
    rayset_free(&rs);
    free(trisf), free(secs);
    scene_free(&scene);
    return 0;
}

/* ---- errors ------------------------------------------------------------------ */

/* The ordinary workload: a triangle 0.25 to 4 across, 3 to 20 ahead of the
 * eye and in its view, and the camera ray (from the eye at the origin,
 * unit direction) towards a point of its plane with barycentric coordinates
 * beta, gamma in [-0.1, 1.1]: about a third of the rays hit. */
static void ordinary_cases(uint64_t seed, HardCase5 *cases, int n)
{
    uint64_t s = seed ^ 0x9E3779B97F4A7C15u;
    for (int k = 0; k < n; k++) {
        HardCase5 *c = &cases[k];
        Vec3 centre = vec3(draw_uni(&s, -4, 4), draw_uni(&s, -3, 3), -draw_uni(&s, 3, 20));
        double size = draw_log(&s, 0.125, 2);
        c->tri.a = vec3_add(centre, draw_point(&s, size));
        c->tri.b = vec3_add(centre, draw_point(&s, size));
        c->tri.c = vec3_add(centre, draw_point(&s, size));
        c->tri.color = vec3(1, 1, 1);
        double beta = draw_uni(&s, -0.1, 1.1), gamma = draw_uni(&s, -0.1, 1.1);
        Vec3 p = vec3_add(c->tri.a, vec3_add(vec3_scale(vec3_sub(c->tri.b, c->tri.a), beta),
                                             vec3_scale(vec3_sub(c->tri.c, c->tri.a), gamma)));
        c->ray.origin = vec3(0, 0, 0);
        c->ray.direction = vec3_normalize(p);
        c->expect = oracle_triangle(&c->tri, &c->ray);
        draw_family(c->family, "ordinary: triangles in view, camera rays");
    }
}

/* One method's errors over n cases (rel: room for n doubles). */
static void measure_errors(const TriMethod *m, const HardCase5 *cases, int n, double *rel,
                           ErrorStats *e)
{
    memset(e, 0, sizeof *e);
    e->tests = n;
    for (int k = 0; k < n; k++) {
        const OracleFlat *o = &cases[k].expect;
        double t = 0;
        bool hit = tri_one(m, &cases[k].tri, &cases[k].ray, &t);
        e->hard_failed += !oracle_flat_accepts(&cases[k].expect, hit, t);
        errors_add(e, o->ambiguous, o->hit, o->t, o->kappa, hit, t, rel);
    }
    long nrel = e->hits;
    median(rel, (int)nrel);                 /* sorts rel */
    e->max_rel = nrel ? rel[nrel - 1] : 0;
    e->median_rel = nrel ? rel[nrel / 2] : 0;
}

static int step_errors(bool quick, uint64_t seed, TriResults *tr, char *err, size_t errlen)
{
    int nhard = HARD_PART5_FAMILIES * (quick ? 100 : 3000), nord = quick ? 5000 : 200000;
    int n = nhard > nord ? nhard : nord;
    HardCase5 *cases = malloc((size_t)n * sizeof *cases);
    double *rel = malloc((size_t)n * sizeof *rel);
    if (!cases || !rel) {
        snprintf(err, errlen, "out of memory");
        free(cases), free(rel);
        return -1;
    }
    progress("triangles: exact answers", 0, 2);
    ordinary_cases(seed, cases, nord);
    for (int m = 0; m < tri_nmethods; m++) {
        progress("triangles: errors", m, 2 * tri_nmethods);
        measure_errors(&tri_methods[m], cases, nord, rel, &tr->ordinary[m]);
    }
    progress("triangles: exact answers", 1, 2);
    hard_part5(seed, cases, nhard);
    for (int m = 0; m < tri_nmethods; m++) {
        progress("triangles: errors", tri_nmethods + m, 2 * tri_nmethods);
        measure_errors(&tri_methods[m], cases, nhard, rel, &tr->hard[m]);
    }
    free(cases);
    free(rel);
    return 0;
}

/* ---- cracks ------------------------------------------------------------------ */

/* Where a ray enters and leaves a closed convex mesh whose faces are wound
 * counter-clockwise seen from outside: the largest t at which it crosses
 * a face's plane inwards and the smallest at which it crosses one outwards
 * (plain double on the given vertices: no method's code).  False when the
 * ray misses the mesh or starts inside it. */
static bool mesh_chord(const Triangle *tris, int n, const Ray *ray, double *t_in, double *t_out)
{
    double lo = -INFINITY, hi = INFINITY;
    for (int i = 0; i < n; i++) {
        Vec3 normal = vec3_cross(vec3_sub(tris[i].b, tris[i].a), vec3_sub(tris[i].c, tris[i].a));
        double den = vec3_dot(normal, ray->direction);
        double num = vec3_dot(normal, vec3_sub(tris[i].a, ray->origin));
        if (den < 0)
            lo = fmax(lo, num / den);
        else if (den > 0)
            hi = fmin(hi, num / den);
        else if (num < 0)
            return false;
    }
    *t_in = lo;
    *t_out = hi;
    return lo > 0 && lo < hi;
}

static Vec3 vec3_of(Vec3f v)
{
    return vec3(v.x, v.y, v.z);
}

/* The float renderer's copy of a mesh: every vertex rounded to float
 * (shared vertices stay shared, so the copy is closed too). */
static void mesh_to_float(const HardMesh *mesh, HardMesh *mf)
{
    *mf = *mesh;
    for (int i = 0; i < mesh->ntris; i++) {
        Trianglef f = trianglef_from(&mesh->tris[i]);
        mf->tris[i].a = vec3_of(f.a);
        mf->tris[i].b = vec3_of(f.b);
        mf->tris[i].c = vec3_of(f.c);
    }
}

/* A ray at the rounded mesh's edge or vertex, as the double ray is at the
 * exact mesh's: drawn from a copy of the random state (so aimed at the same
 * edge or vertex), then its origin rounded to float and its direction made
 * again from there to the point aimed at, and rounded to float.  It passes
 * that point within float's rounding of the direction, as the double ray
 * passes its point within double's.  Coordinates kept in double (exact). */
static Ray float_ray_at(uint64_t state, const HardMesh *mf, bool vertex)
{
    double entry;
    Ray r = hard_mesh_ray_at(&state, mf, vertex, &entry);
    Vec3f o = vec3f_from(r.origin);
    /* r.origin - o is exact; r.direction * entry goes from r.origin to the
     * point aimed at. */
    Vec3 to_x = vec3_add(vec3_scale(r.direction, entry), vec3_sub(r.origin, vec3_of(o)));
    Vec3 d = vec3_scale(to_x, vec3_length(r.direction) / vec3_length(to_x));
    Ray rf = { vec3_of(o), vec3_of(vec3f_from(d)) };
    return rf;
}

static void step_cracks(bool quick, uint64_t seed, TriResults *tr)
{
    /* Each ray is judged on the mesh as its method's precision holds it:
     * the ray crosses the mesh's surface where it enters (t_in) and again
     * where it leaves (t_out).  It is stopped where it enters when some
     * triangle reports a hit before the middle of that chord; a crack, when
     * none does.  A hit on the far side alone does not stop it: that is the
     * ray that went through.  Rounded to float, a small mesh far from the
     * origin can be squashed flat; a ray whose chord is shorter than 1% of
     * t_in is not judged, and the counts say how many were. */
    const long per_kind = quick ? 3000 : 30000;
    const int per_mesh = 200;
    uint64_t s = seed ^ 0x5DEECE66Du;
    HardMesh mesh, mf;
    tr->crack_rays_per_kind = per_kind;
    tr->min_chord = INFINITY;
    tr->max_entry_gap = 0;
    for (int kind = 0; kind < CRACK_KINDS; kind++) {
        bool vertex = kind == CRACK_VERTEX || kind == CRACK_FAR_VERTEX;
        bool far = kind == CRACK_FAR_EDGE || kind == CRACK_FAR_VERTEX;
        for (long done = 0, k = 0; done < per_kind; k++) {
            progress("triangles: cracks", (int)(kind * per_kind + done), (int)(CRACK_KINDS * per_kind));
            double off = far ? draw_log(&s, 1e3, 1e6) : 0;
            Vec3 dir = vec3(hard_rng_uniform(&s) - 0.5, hard_rng_uniform(&s) - 0.5, hard_rng_uniform(&s) - 0.5);
            Vec3 offset = far ? vec3_scale(vec3_normalize(dir), off) : vec3_scale(dir, 20);
            double size = ldexp(1 + hard_rng_uniform(&s), (int)(hard_rng_next(&s) % 8) - 4);
            hard_mesh_make(&s, (int)(k % HARD_MESH_SHAPES), size, offset, &mesh);
            mesh_to_float(&mesh, &mf);
            for (int r = 0; r < per_mesh && done < per_kind; r++, done++) {
                uint64_t before = s;
                double entry;
                Ray rays[2];
                rays[0] = hard_mesh_ray_at(&s, &mesh, vertex, &entry);
                rays[1] = float_ray_at(before, &mf, vertex);
                for (int p = 0; p < 2; p++) {
                    const HardMesh *view = p == 0 ? &mesh : &mf;
                    Precision prec = p == 0 ? PREC_DOUBLE : PREC_FLOAT;
                    double t_in = 0, t_out = 0;
                    if (!mesh_chord(view->tris, view->ntris, &rays[p], &t_in, &t_out)
                        || t_out - t_in < 0.01 * t_in)
                        continue;
                    tr->min_chord = fmin(tr->min_chord, (t_out - t_in) / t_in);
                    if (p == 0)
                        tr->max_entry_gap = fmax(tr->max_entry_gap, fabs(t_in - entry) / entry);
                    for (int m = 0; m < tri_nmethods; m++) {
                        if (tri_methods[m].precision != prec)
                            continue;
                        bool stopped = false, any = false;
                        for (int i = 0; i < view->ntris && !stopped; i++) {
                            double t;
                            if (tri_one(&tri_methods[m], &view->tris[i], &rays[p], &t)) {
                                any = true;
                                stopped = t < (t_in + t_out) / 2;
                            }
                        }
                        tr->rays[m][kind]++;
                        tr->cracks[m][kind] += !stopped;
                        tr->missed_all[m] += !any;
                    }
                }
            }
        }
    }
}

int triangle_bench(const char *scenes, bool quick, uint64_t seed, TriResults *tr, char *err,
                   size_t errlen)
{
    memset(tr, 0, sizeof *tr);
    tr->ran = true;
    if (step_throughput(scenes, quick, tr, err, errlen) != 0)
        return -1;
    if (step_errors(quick, seed, tr, err, errlen) != 0)
        return -1;
    step_cracks(quick, seed, tr);
    return 0;
}

/* ---- output ---------------------------------------------------------------------- */

/* A method's count over the four kinds of crack rays (tr->rays[m]: the
 * rays judged, tr->cracks[m]: those through). */
static long all_kinds(const long count[CRACK_KINDS])
{
    long n = 0;
    for (int k = 0; k < CRACK_KINDS; k++)
        n += count[k];
    return n;
}

static double tri_cracks_per_million(const TriResults *tr, int m)
{
    return per_million(all_kinds(tr->cracks[m]), all_kinds(tr->rays[m]));
}

/* results_triangles.csv's body, for out_write (outfile.c): data is the TriResults. */
static void csv_triangles(FILE *f, const void *data)
{
    const TriResults *tr = data;
    fprintf(f, "method,precision,mtests_per_s,"
               "ordinary_max_rel_err,ordinary_median_rel_err,ordinary_wrong_per_million,"
               "ordinary_max_err_over_u_kappa,ordinary_cases,"
               "hard_max_rel_err,hard_median_rel_err,hard_max_err_u_kappa_le_100,"
               "hard_wrong_per_million,hard_max_err_over_u_kappa,hard_failed,hard_cases,"
               "cracks_per_million,cracks_edges,cracks_vertices,cracks_far_edges,cracks_far_vertices,"
               "rays_edges,rays_vertices,rays_far_edges,rays_far_vertices,missed_whole_mesh\n");
    for (int m = 0; m < tri_nmethods; m++) {
        const ErrorStats *o = &tr->ordinary[m], *h = &tr->hard[m];
        fprintf(f, "%s,%s,%.6g,%.3e,%.3e,%.6g,%.3e,%ld,%.3e,%.3e,%.3g,%.6g,%.3e,%ld,%ld,%.6g",
                tri_methods[m].name, precision_name(tri_methods[m].precision), tr->mtests[m],
                o->max_rel, o->median_rel, wrong_per_million(o), o->max_over_kappa, o->tests,
                h->max_rel, h->median_rel, h->max_u_well, wrong_per_million(h), h->max_over_kappa,
                h->hard_failed, h->tests, tri_cracks_per_million(tr, m));
        for (int k = 0; k < CRACK_KINDS; k++)
            fprintf(f, ",%ld", tr->cracks[m][k]);
        for (int k = 0; k < CRACK_KINDS; k++)
            fprintf(f, ",%ld", tr->rays[m][k]);
        fprintf(f, ",%ld\n", tr->missed_all[m]);
    }
}

int triangles_write(const TriResults *tr, const char *dir, const char *subtitle, char *err,
                    size_t errlen)
{
    if (out_write(dir, "results_triangles.csv", csv_triangles, tr, err, errlen) != 0)
        return -1;
    /* The plot: speed against cracks, and speed against the error of t. */
    MethodPoint pts[TRI_MAX_METHODS];
    for (int m = 0; m < tri_nmethods; m++)
        pts[m] = (MethodPoint){ tri_methods[m].name, tri_methods[m].precision, tr->mtests[m],
                                { fmax(tri_cracks_per_million(tr, m), 0.01),
                                  tr->hard[m].max_over_kappa } };
    static const PlotPanel panels[2] = {
        { "Rays through closed meshes, aimed at shared edges and vertices",
          "cracks per million rays (log scale; 0 is drawn at 0.01; smaller is better)" },
        { "Worst error of t on the hard families, in units of u kappa",
          "max |t - t_exact| / (u kappa t_exact), u = 2^-53 (log scale; smaller is better)" },
    };
    return svg_plot(dir, "plot_triangles.svg",
                    "Ray/triangle intersection: speed against watertightness and accuracy",
                    subtitle, pts, tri_nmethods, panels, "million ray/triangle tests per second",
                    err, errlen);
}

void triangles_md(FILE *f, const TriResults *tr)
{
    fprintf(f, "\n## Part 5: ray/triangle\n\n");
    fprintf(f, "Throughput: every method's closest-hit loop over the camera rays of cracks.scene "
               "(%d rays x %d triangles, one thread). Errors: %ld ordinary cases (a triangle "
               "0.25 to 4 across, 3 to 20 ahead of the eye, and a camera ray towards a point of "
               "its plane; about a third hit) and %ld hard cases of Part 5's families "
               "(tests/oracle/hard.h), against the exact oracle; wrong per million counts the "
               "cases outside the oracle's band of doubt. Cracks: %ld rays each at shared edges "
               "and at shared vertices of closed meshes (a cube of 12 triangles, an "
               "octahedron, an icosahedron) near the origin, and as many at offsets 10^3 to "
               "10^6; a crack is a ray that no triangle stops where it enters the mesh (before "
               "the middle of its chord through the mesh). The four columns after it are per "
               "million rays of their kind. kappa is the condition number of t (oracle.h).\n\n",
            tr->tp_rays, tr->tp_triangles, tr->ordinary[0].tests, tr->hard[0].tests,
            tr->crack_rays_per_kind);
    fprintf(f, "| method | precision | Mtests/s | max rel. error (ordinary) | median rel. error "
               "(ordinary) | wrong per million (ordinary) | max error / (u kappa) (hard) | wrong "
               "per million (hard) | hard cases failed | cracks per million | edges | vertices | "
               "far edges | far vertices |\n");
    fprintf(f, "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int m = 0; m < tri_nmethods; m++) {
        const ErrorStats *o = &tr->ordinary[m], *h = &tr->hard[m];
        fprintf(f, "| %s | %s | %.0f | %.2g | %.2g | %.0f | %.2g | %.0f | %ld / %ld | %.0f",
                tri_methods[m].name, precision_name(tri_methods[m].precision), tr->mtests[m],
                o->max_rel, o->median_rel, wrong_per_million(o), h->max_over_kappa,
                wrong_per_million(h), h->hard_failed, h->tests, tri_cracks_per_million(tr, m));
        for (int k = 0; k < CRACK_KINDS; k++)
            fprintf(f, " | %.0f", per_million(tr->cracks[m][k], tr->rays[m][k]));
        fprintf(f, " |\n");
    }

    /* What it shows, in figures of this run. */
    fprintf(f, "\nOf %ld rays aimed at shared edges and vertices, %ld went through the "
               "reference's meshes and %ld through Moller-Trumbore's in double (%ld of %ld "
               "at edges, %ld of %ld at vertices), which runs %.2f times as fast as the "
               "reference. Counting only the rays that hit no triangle at all would hide "
               "those cracks (Moller-Trumbore: %ld): a ray that slips through where it "
               "enters still hits the far side.",
            all_kinds(tr->rays[REF]), all_kinds(tr->cracks[REF]), all_kinds(tr->cracks[MT]),
            tr->cracks[MT][CRACK_EDGE] + tr->cracks[MT][CRACK_FAR_EDGE],
            tr->rays[MT][CRACK_EDGE] + tr->rays[MT][CRACK_FAR_EDGE],
            tr->cracks[MT][CRACK_VERTEX] + tr->cracks[MT][CRACK_FAR_VERTEX],
            tr->rays[MT][CRACK_VERTEX] + tr->rays[MT][CRACK_FAR_VERTEX],
            tr->mtests[REF] > 0 ? tr->mtests[MT] / tr->mtests[REF] : 0, tr->missed_all[MT]);
    fprintf(f, " In float, judged on the mesh and ray rounded to float, %ld of %ld rays "
               "went through (%ld of the %ld far rays were not judged: rounding to "
               "float squashed their mesh or moved the ray off it).",
            all_kinds(tr->cracks[MT_FLOAT]), all_kinds(tr->rays[MT_FLOAT]),
            2 * tr->crack_rays_per_kind - tr->rays[MT_FLOAT][CRACK_FAR_EDGE]
                - tr->rays[MT_FLOAT][CRACK_FAR_VERTEX],
            2 * tr->crack_rays_per_kind);
    fprintf(f, " The chords were at least %.2f times the entry's t, so the middle of the "
               "chord tells a hit where the ray enters from one where it leaves; the entry "
               "found by clipping the ray against the faces' planes and the one the rays "
               "were built with differ by at most %.1e relative.\n",
            tr->min_chord, tr->max_entry_gap);
    fprintf(f, "\nThe reference pays for watertightness with a shear of the vertices per test "
               "and, near an edge, exact signs from fma. Woop, Benthin and Wald's test without "
               "exact signs (wbw-plain) computes a shared edge's function from the same two "
               "projected points in both triangles, so its signs there are opposite and an "
               "edge cannot leak; at a vertex only a rounding that flips a nearly zero product "
               "difference can open a hole, which random rays almost never meet. The geometric "
               "method finds the hit point from t first, and t's error moves it: it misjudges "
               "slivers. Plot: plot_triangles.svg.\n");
}
