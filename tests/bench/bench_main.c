/*
 * bench_main.c - `make bench`: the order of the steps, the options, and
 * the progress line.
 *
 *     bench [--quick] [--out DIR] [--scenes DIR] [--size WxH] [--rounds N]
 *           [--seed N] [--placement FILE] [--render RENDER]
 *     bench --ratio-only [--quick] [--scenes DIR] [--rounds N]
 *
 *   1. throughput: every method's closest-hit loop over the camera rays of
 *      default.scene, interleaved rounds, medians
 *   2. the ceiling: clock and floating-point pipes, measured
 *   3. errors: every method against the exact answers, on the ordinary scene
 *      and on the hard families
 *   4. renders: each lab scene of spheres at full HD with every method,
 *      against an exact render
 *   5. Part 5: the ray/triangle formulations' speed, errors and cracks
 *      (triangles.c)
 *   6. Part 5 at scale: rays per second against triangles, with and
 *      without the kit's hierarchy; and first of all, before the bench
 *      grows, the render program (RENDER, default
 *      out/build/sub/solutions/render) on 10^6 of them (scaling.c)
 *   7. the report: results.csv, results_by_family.csv, renders.csv,
 *      results_triangles.csv, results_scaling.csv, report.md, plot.svg,
 *      plot_triangles.svg, plot_scaling.svg in DIR (default out/bench)
 * --quick does the same with small sizes, in a few seconds (make test).
 * --ratio-only runs step 1 alone and prints one line, "ratio R q1 Q1 q3
 * Q3" (the reference's time over the textbook's, double); `make bench`
 * runs it in the bench linked in the reverse order (bench-reordered) and
 * hands that line to the bench with --placement FILE, whose report then
 * gives the ratio under both placements of the code: where the code lies
 * moves it by more than the 5% of its target (tests/bench/README.md).
 * Exit status: 0, or 1 if something could not run (the reason on stderr).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <glob.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "kit/scene.h"
#include "../oracle/hard.h"
#include "bench.h"

volatile double bench_sink;

/* ---- progress ------------------------------------------------------------- */

static double start_time;
static bool progress_tty;

/* One line on stderr, rewritten in place on a terminal (at most ten times a
 * second); elsewhere one line per step. */
void progress(const char *step, int done, int total)
{
    static char last_step[64];
    static double last_time;
    double now = now_seconds();
    bool new_step = strncmp(step, last_step, sizeof last_step - 1) != 0;
    if (progress_tty) {
        if (!new_step && done < total && now - last_time < 0.1)
            return;
        fprintf(stderr, "\r\033[Kbench [%5.1fs] %s: %d/%d (%.0f%%)", now - start_time, step, done,
                total, total > 0 ? 100.0 * done / total : 100.0);
    } else if (new_step) {
        fprintf(stderr, "bench [%5.1fs] %s\n", now - start_time, step);
    }
    fflush(stderr);
    snprintf(last_step, sizeof last_step, "%s", step);
    last_time = now;
}

/* ---- small helpers -------------------------------------------------------------- */

static double load_average(void)
{
    FILE *f = fopen("/proc/loadavg", "r");     /* portable: -1 without /proc */
    double v = -1;
    if (f) {
        if (fscanf(f, "%lf", &v) != 1)
            v = -1;
        fclose(f);
    }
    return v;
}

static int mkdir_p(const char *dir)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            mkdir(buf, 0777);
            *p = '/';
        }
    mkdir(buf, 0777);
    struct stat st;
    return stat(buf, &st) == 0 && S_ISDIR(st.st_mode) ? 0 : -1;
}

static void pool_stats(ErrorStats *all, const ErrorStats *fam, double *errs, long nerrs)
{
    memset(all, 0, sizeof *all);
    for (int f = 0; f < FAMILY_COUNT; f++) {
        all->tests += fam[f].tests;
        all->ambiguous += fam[f].ambiguous;
        all->wrong += fam[f].wrong;
        all->hits += fam[f].hits;
        all->over_tol += fam[f].over_tol;
        if (fam[f].max_rel > all->max_rel)
            all->max_rel = fam[f].max_rel;
        if (fam[f].max_over_kappa > all->max_over_kappa)
            all->max_over_kappa = fam[f].max_over_kappa;
    }
    all->median_rel = nerrs > 0 ? median(errs, (int)nerrs) : 0;
}

/* ---- the steps -------------------------------------------------------------------- */

typedef struct {
    bool quick, ratio_only;
    const char *out, *scenes, *placement, *render;
    int width, height, rounds;
    uint64_t seed;
} Options;

/* Loads the scenes' default.scene, its path in path.  0, or -1 with err. */
static int load_default(const Options *o, Scene *scene, char *path, size_t size, char *err, size_t errlen)
{
    snprintf(path, size, "%s/default.scene", o->scenes);
    return scene_load(scene, path, err, errlen) != 0 ? -1 : 0;
}

/* Where the reference's miss test stops on the workload (rays rs against
 * scene's spheres), checked against the reference itself. */
static void count_reference_exits(const Scene *scene, const RaySet *rs, BenchResults *br)
{
    for (int i = 0; i < rs->n; i++)
        for (int k = 0; k < scene->nspheres; k++) {
            int stage = reference_stage(&scene->spheres[k], &rs->rays[i]);
            double t = 0;
            br->ref_stage[stage]++;
            br->ref_stage_pairs++;
            if (stage <= REF_STAGE_NN && sphere_intersect(&scene->spheres[k], &rs->rays[i], &t))
                br->ref_stage_wrong++;
        }
}

/* From R rounds' pass times secs[m * R + r] and clock
 * readings mhz (tests tests a pass): every method's Mtests/s and the
 * reference / textbook ratio, medians and quartiles, and the clock.  col
 * (R numbers) is room to work in. */
static void throughput_stats(BenchResults *br, const double *secs, double *mhz, int R, double tests,
                             double *col)
{
    int nm = bench_nmethods;
    for (int m = 0; m < nm; m++) {
        for (int r = 0; r < R; r++)
            col[r] = tests / secs[m * R + r] / 1e6;
        br->mtests[m] = median(col, R);
        br->mtests_q1[m] = quantile(col, R, 0.25);
        br->mtests_q3[m] = quantile(col, R, 0.75);
    }
    int ref = REFERENCE_D, tb = TEXTBOOK_D;
    for (int r = 0; r < R; r++)
        col[r] = secs[ref * R + r] / secs[tb * R + r];
    br->ratio_paired = median(col, R);
    br->ratio_q1 = quantile(col, R, 0.25);
    br->ratio_q3 = quantile(col, R, 0.75);
    br->ratio_of_medians = br->mtests[tb] / br->mtests[ref];
    br->ceiling.mhz_measured = median(mhz, R);
}

/* The fast path's filter alone over rs: R samples of at least sample_s
 * seconds each (tests tests a pass); the median Mtests/s.  col (R numbers)
 * is room to work in. */
static double time_filter(const FastScene *fs, const RaySet *rs, int R, double sample_s, double tests,
                          double *col)
{
    long passed = 0;
    for (int r = 0; r < R; r++) {
        int passes = 0;
        double t0 = now_seconds(), dt;
        do {
            passed += fast_filter_only(fs, rs->dx, rs->dy, rs->dz, rs->n);
            passes++;
            dt = now_seconds() - t0;
        } while (dt < sample_s);
        col[r] = tests * passes / dt / 1e6;
    }
    bench_sink += (double)passed;
    return median(col, R);
}

static int step_throughput(const Options *o, BenchResults *br, char *err, size_t errlen)
{
    char path[1024];
    Scene scene;
    if (load_default(o, &scene, path, sizeof path, err, errlen) != 0)
        return -1;
    RaySet rs;
    FastScene fs;
    Spheref sf[64];
    int pixel_step = o->quick ? 8 : 4;
    if (scene.nspheres > 64 || rayset_camera(&rs, &scene, scene.nx, scene.ny, pixel_step) != 0) {
        snprintf(err, errlen, "%s: too many spheres, or out of memory", path);
        scene_free(&scene);
        return -1;
    }
    if (fast_build(&fs, scene.spheres, scene.nspheres, scene.eye) != 0) {
        snprintf(err, errlen, "out of memory");
        rayset_free(&rs);
        scene_free(&scene);
        return -1;
    }
    for (int k = 0; k < scene.nspheres; k++)
        sf[k] = spheref_from(&scene.spheres[k]);
    BenchScene bs = { scene.spheres, sf, scene.nspheres, &fs };
    br->tp_rays = rs.n;
    br->tp_spheres = scene.nspheres;
    br->rounds = o->rounds;
    count_reference_exits(&scene, &rs, br);
    br->fast_pairs = (long)((rs.n + FAST_PACKET - 1) / FAST_PACKET) * fs.n;
    br->fast_solved = fast_filter_only(&fs, rs.dx, rs.dy, rs.dz, rs.n);

    int nm = bench_nmethods, R = o->rounds;
    double *secs = malloc((size_t)(R * nm) * sizeof *secs);
    double *mhz = malloc((size_t)R * sizeof *mhz);
    double *col = malloc((size_t)R * sizeof *col);
    int status = -1;
    if (secs && mhz && col &&
        measure_throughput(&bs, &rs, R, o->quick ? 0.001 : 0.005, secs, mhz) == 0) {
        double tests = (double)rs.n * scene.nspheres;
        throughput_stats(br, secs, mhz, R, tests, col);
        /* The fast path's filter alone, timed the same way (R samples of
         * about the same length), right after the rounds. */
        br->fast_filter_mtests = time_filter(&fs, &rs, R, o->quick ? 0.001 : 0.005, tests, col);
        status = 0;
    } else {
        snprintf(err, errlen, "out of memory");
    }
    free(secs);
    free(mhz);
    free(col);
    fast_free(&fs);
    rayset_free(&rs);
    scene_free(&scene);
    return status;
}

/* The float transliteration of the reference, compiled as double, must
 * give the linked reference's answers exactly: counts the n cases where it
 * does not. */
static void check_transliteration(const Case *cases, int n, BenchResults *br)
{
    for (int i = 0; i < n; i++) {
        double t1 = 0, t2 = 0;
        bool h1 = sphere_intersect(&cases[i].sphere, &cases[i].ray, &t1);
        bool h2 = isect_reference_d(&cases[i].sphere, &cases[i].ray, &t2);
        br->translit_cases++;
        if (h1 != h2 || (h1 && memcmp(&t1, &t2, sizeof t1) != 0))
            br->translit_differ++;
    }
}

/* Cost by outcome: the ordinary scene's n cases that surely miss and
 * surely hit (exact: their answers), a sample of each timed with every
 * method; and the share of hits.  0, or -1 out of memory. */
static int cost_by_outcome(const Options *o, const Case *cases, const OracleHit *exact, int n,
                           BenchResults *br)
{
    const int cap = o->quick ? 2000 : 20000;
    Case *miss = malloc((size_t)cap * sizeof *miss), *hit = malloc((size_t)cap * sizeof *hit);
    int nmiss = 0, nhit = 0, status = 0;
    long counted = 0, hits = 0;
    for (int i = 0; i < n; i++)
        if (!exact[i].ambiguous) {
            counted++;
            hits += exact[i].hit;
        }
    br->hit_share = counted > 0 ? (double)hits / (double)counted : 0;
    long step_hit = hits / cap + 1, step_miss = (counted - hits) / cap + 1, kh = 0, km = 0;
    for (int i = 0; miss && hit && i < n; i++) {
        const OracleHit *e = &exact[i];
        if (e->ambiguous)
            continue;
        if (e->hit && kh++ % step_hit == 0 && nhit < cap)
            hit[nhit++] = cases[i];
        else if (!e->hit && km++ % step_miss == 0 && nmiss < cap)
            miss[nmiss++] = cases[i];
    }
    if (!miss || !hit || measure_outcomes(miss, nmiss, hit, nhit, o->quick ? 3 : 31,
                                          o->quick ? 0.0005 : 0.002, br->miss_ns,
                                          br->hit_ns) != 0)
        status = -1;
    free(miss);
    free(hit);
    return status;
}

static int step_errors(const Options *o, BenchResults *br, char *err, size_t errlen)
{
    char path[1024];
    Scene scene;
    if (load_default(o, &scene, path, sizeof path, err, errlen) != 0)
        return -1;
    Case *cases[FAMILY_COUNT];
    int n[FAMILY_COUNT];
    int hard_n = o->quick ? 3000 : 200000;
    cases[FAMILY_SCENE] = cases_scene(&scene, o->quick ? 8 : 1, &n[FAMILY_SCENE]);
    scene_free(&scene);
    for (int f = 1; f < FAMILY_COUNT; f++) {
        n[f] = hard_n;
        cases[f] = cases_hard((Family)f, hard_n, o->seed);
    }
    long total = 0;
    for (int f = 0; f < FAMILY_COUNT; f++) {
        total += n[f];
        br->family_cases[f] = n[f];
    }
    OracleHit *exact[FAMILY_COUNT] = { NULL };
    double *errs = malloc((size_t)total * sizeof *errs);
    int status = errs ? 0 : -1;
    for (int f = 0; f < FAMILY_COUNT && status == 0; f++) {
        char label[64];
        snprintf(label, sizeof label, "exact answers, %s", family_names[f]);
        progress(label, 0, 1);
        exact[f] = cases[f] ? exact_answers(cases[f], n[f]) : NULL;
        if (!exact[f])
            status = -1;
    }
    for (int f = 0; f < FAMILY_COUNT && status == 0; f++)
        check_transliteration(cases[f], n[f], br);
    if (status == 0)
        status = cost_by_outcome(o, cases[FAMILY_SCENE], exact[FAMILY_SCENE], n[FAMILY_SCENE], br);
    for (int m = 0; m < bench_nmethods && status == 0; m++) {
        progress("errors", m, bench_nmethods);
        long used = 0;
        for (int f = 0; f < FAMILY_COUNT; f++) {
            long ne = 0;
            accuracy_run(&bench_methods[m], cases[f], exact[f], n[f], &br->fam[m][f], errs + used,
                         &ne);
            used += ne;
        }
        pool_stats(&br->all[m], br->fam[m], errs, used);
    }
    progress("errors", bench_nmethods, bench_nmethods);
    if (status != 0)
        snprintf(err, errlen, "out of memory");
    for (int f = 0; f < FAMILY_COUNT; f++) {
        free(cases[f]);
        free(exact[f]);
    }
    free(errs);
    return status;
}

/* The grader's Part 3a hard cases, judged by the grader's own rule. */
static int step_grader(const Options *o, BenchResults *br, char *err, size_t errlen)
{
    int max = HARD_PART3A_FAMILIES * (o->quick ? 10 : 100);
    HardCase3a *cases = malloc((size_t)max * sizeof *cases);
    if (!cases) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    progress("grader's hard cases", 0, 1);
    int n = hard_part3a(o->seed, cases, max);
    br->grader_cases = n;
    for (int m = 0; m < bench_nmethods; m++) {
        br->grader_failed[m] = 0;
        for (int i = 0; i < n; i++) {
            /* a method that assumes |r| = 1 gets r / |r|, and its t is
             * scaled back: what a caller would do */
            Ray ray = cases[i].ray;
            double len = vec3_length(ray.direction), t = 0;
            bool scale = bench_methods[m].unit_dir && len > 0 && len < INFINITY;
            if (scale)
                ray.direction = vec3_scale(ray.direction, 1 / len);
            bool hit = method_one(&bench_methods[m], &cases[i].sphere, &ray, &t);
            if (hit && scale)
                t /= len;
            if (!oracle_sphere_accepts(&cases[i].sphere, &cases[i].ray, hit, t))
                br->grader_failed[m]++;
        }
    }
    free(cases);
    return 0;
}

static int step_renders(const Options *o, BenchResults *br, char *err, size_t errlen)
{
    char pattern[1100];
    glob_t g;                       /* the *.scene files of the directory, sorted */
    snprintf(pattern, sizeof pattern, "%s/*.scene", o->scenes);
    int found = glob(pattern, GLOB_ERR, NULL, &g);
    if (found != 0 && found != GLOB_NOMATCH) {
        snprintf(err, errlen, "%s: cannot list scenes", o->scenes);
        return -1;
    }
    int n = found == 0 ? (int)g.gl_pathc : 0;
    n = n < BENCH_MAX_SCENES ? n : BENCH_MAX_SCENES;
    br->render_reps = o->quick ? 1 : 3;
    int status = 0;
    br->nrenders = 0;
    for (int s = 0; s < n && status == 0; s++) {
        int got = render_bench(g.gl_pathv[s], o->width, o->height, br->render_reps,
                               &br->renders[br->nrenders], err, errlen);
        if (got == 0)
            br->nrenders++;
        else if (got < 0)
            status = -1;                /* 1: a scene of planes or triangles, skipped */
    }
    if (found == 0)
        globfree(&g);
    return status;
}

static void usage(void)
{
    fprintf(stderr, "usage: bench [--quick] [--out DIR] [--scenes DIR] [--size WxH] "
                    "[--rounds N] [--seed N] [--placement FILE] [--render RENDER]\n"
                    "       bench --ratio-only [--quick] [--scenes DIR] [--rounds N]\n");
}

/* The line bench --ratio-only printed, from file path, into br. */
static int read_placement(const char *path, BenchResults *br, char *err, size_t errlen)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, errlen, "%s: cannot read it", path);
        return -1;
    }
    int got = fscanf(f, "ratio %lf q1 %lf q3 %lf", &br->placed_ratio, &br->placed_q1, &br->placed_q3);
    fclose(f);
    if (got != 3 || !(br->placed_ratio > 0) || !(br->placed_q1 > 0) || !(br->placed_q3 > 0)) {
        snprintf(err, errlen, "%s: not a line of bench --ratio-only (\"ratio R q1 Q1 q3 Q3\")", path);
        return -1;
    }
    br->placed = true;
    return 0;
}

/* Reads the options into o, with the defaults the others leave; 0, or -1
 * (and the usage on stderr) for an option it does not know. */
static int parse_options(int argc, char **argv, Options *o)
{
    Options defaults = { false, false, "out/bench", "labs/scenes", NULL, "out/build/sub/solutions/render",
                         1920, 1080, 0, 20260101 };
    *o = defaults;
    /* the options that take a path */
    const struct { const char *name; const char **to; } paths[] = {
        { "--placement", &o->placement }, { "--out", &o->out }, { "--render", &o->render },
        { "--scenes", &o->scenes },
    };
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        size_t p = 0;
        while (p < sizeof paths / sizeof paths[0] && strcmp(a, paths[p].name) != 0)
            p++;
        if (strcmp(a, "--quick") == 0) {
            o->quick = true;
        } else if (strcmp(a, "--ratio-only") == 0) {
            o->ratio_only = true;
        } else if (p < sizeof paths / sizeof paths[0] && v) {
            *paths[p].to = v;
            i++;
        } else if (strcmp(a, "--size") == 0 && v && sscanf(v, "%dx%d", &o->width, &o->height) == 2 &&
                   o->width > 0 && o->height > 0 && o->width <= 16384 && o->height <= 16384) {
            i++;
        } else if (strcmp(a, "--rounds") == 0 && v && atoi(v) > 0) {
            o->rounds = atoi(v);
            i++;
        } else if (strcmp(a, "--seed") == 0 && v) {
            o->seed = strtoull(v, NULL, 10);
            i++;
        } else {
            usage();
            return -1;
        }
    }
    if (o->quick && o->width == 1920 && o->height == 1080) {
        o->width = 192;
        o->height = 108;
    }
    if (o->rounds == 0)
        o->rounds = o->quick ? 7 : 151;
    return 0;
}

/* How the bench runs: its options, the machine's load and CPU, the
 * compiler, the date. */
static void describe_run(const Options *o, BenchResults *br)
{
    br->quick = o->quick;
    br->seed = o->seed;
    br->load_before = load_average();
    if (!cpuinfo("model name", br->cpu, sizeof br->cpu))
        snprintf(br->cpu, sizeof br->cpu, "unknown CPU");
#ifdef __VERSION__
    snprintf(br->compiler, sizeof br->compiler, "%s", __VERSION__);
#endif
    time_t now = time(NULL);
    strftime(br->date, sizeof br->date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
}

/* Every step in order, then the report, until one fails; 0, or -1 with
 * err. */
static int run_steps(const Options *o, BenchResults *br, char *err, size_t errlen)
{
    int status = scaling_prepare(o->out, o->scenes, o->render, o->quick, &br->scale, err, errlen);
    if (status == 0)
        status = step_throughput(o, br, err, errlen);
    if (status == 0) {
        progress("ceiling", 0, 1);
        /* the clock read between throughput rounds is the one that counts */
        measure_ceiling(&br->ceiling, o->quick, br->ceiling.mhz_measured);
        status = step_errors(o, br, err, errlen);
    }
    if (status == 0)
        status = step_grader(o, br, err, errlen);
    if (status == 0)
        status = step_renders(o, br, err, errlen);
    if (status == 0)
        status = triangle_bench(o->scenes, o->quick, o->seed, &br->tri, err, errlen);
    if (status == 0)
        status = scaling_bench(o->quick, &br->scale, err, errlen);
    br->load_after = load_average();
    br->seconds_total = now_seconds() - start_time;
    if (status == 0) {
        progress("report", 0, 1);
        status = report_write(br, o->out, err, errlen);
    }
    return status;
}

int main(int argc, char **argv)
{
    Options o;
    if (parse_options(argc, argv, &o) != 0)
        return 1;
    static BenchResults br;
    char err[1200] = "";
    start_time = now_seconds();
    progress_tty = isatty(2);
    int status;
    if (o.ratio_only) {             /* the throughput step alone, and its one line */
        status = step_throughput(&o, &br, err, sizeof err);
    } else if (o.placement && read_placement(o.placement, &br, err, sizeof err) != 0) {
        status = -1;
    } else {
        describe_run(&o, &br);
        status = mkdir_p(o.out);
        if (status != 0)
            snprintf(err, sizeof err, "%s: cannot create the directory", o.out);
        else
            status = run_steps(&o, &br, err, sizeof err);
    }
    if (progress_tty)
        fprintf(stderr, "\r\033[K");          /* the progress line, cleared */
    if (status != 0) {
        fprintf(stderr, "bench: %s\n", err);
        return 1;
    }
    if (o.ratio_only)
        printf("ratio %.4f q1 %.4f q3 %.4f\n", br.ratio_of_medians, br.ratio_q1, br.ratio_q3);
    else
        printf("bench: wrote %s/results.csv, %s/report.md, %s/plot.svg in %.0f s (checksum %g)\n",
               o.out, o.out, o.out, br.seconds_total, bench_sink);
    return 0;
}
