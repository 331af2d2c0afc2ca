/*
 * scaling.c - Part 5 at scale in `make bench`: rays per second against the
 * number of triangles, 1 to 10^6, with the kit's bounding volume hierarchy
 * (labs/kit/bvh.h) and without it (every triangle for every ray), through
 * the renderer itself (render_scene, on one thread, as the bench's other
 * timings); and the render program end to end on the largest mesh, on
 * every core, reading included, with its peak memory.
 *
 * The meshes are closed tubes around a trefoil knot, written by
 * tests/tools/knot-mesh.sh into the output directory and drawn in
 * knot.scene's view (its copy beside each mesh names that mesh); 1 and 10
 * triangles are the first ones of the 100-triangle knot.  Without the
 * hierarchy a render makes nx ny n tests: its image is made smaller (the
 * same view, fewer pixels) so that it makes about SCALE_BUDGET.  Medians
 * of three renders (one in --quick).  scaling_prepare writes the meshes
 * and runs the render program, first thing; scaling_bench measures.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include "kit/render.h"
#include "kit/scene.h"
#include "bench.h"

#define SCALE_BUDGET 5e7        /* tests per render without the hierarchy */
#define SCALE_SIZE   "640x480"  /* the render program's image */

/* The meshes: n triangles, the first n of the knot of u rings of v. */
static const struct { int n, u, v; } scale_meshes[SCALE_MAX] = {
    { 1, 10, 5 }, { 10, 10, 5 }, { 100, 10, 5 }, { 1000, 50, 10 }, { 10000, 250, 20 },
    { 100000, 1000, 50 }, { 1000000, 2500, 200 },
};

/* Writes the knot of u x v and its scene into dir (knot-U-V.obj and
 * knot-U-V.scene, the scene a copy of scenes/knot.scene naming that mesh;
 * each through a temporary file, renamed), and the scene's path into
 * path.  Returns 0, or -1 with a reason. */
static int scale_write_mesh(const char *dir, const char *scenes, int u, int v, char *path,
                            size_t len, char *err, size_t errlen)
{
    char cmd[8 * 1100];
    snprintf(path, len, "%s/knot-%d-%d.scene", dir, u, v);
    snprintf(cmd, sizeof cmd,
             "sh tests/tools/knot-mesh.sh %d %d >'%s/knot-%d-%d.obj.tmp' && "
             "mv '%s/knot-%d-%d.obj.tmp' '%s/knot-%d-%d.obj' && "
             "sed 's/knot\\.obj/knot-%d-%d.obj/' '%s/knot.scene' >'%s.tmp' && mv '%s.tmp' '%s'",
             u, v, dir, u, v, dir, u, v, dir, u, v, u, v, scenes, path, path, path);
    if (system(cmd) != 0) {
        snprintf(err, errlen, "cannot write the knot of %d x %d into %s (%s)", u, v, dir, cmd);
        return -1;
    }
    return 0;
}

/* The median time of reps renders of scene with the hierarchy as asked, at
 * nx x ny; the last render's statistics into *last.  -1 on failure. */
static double scale_render(Scene *scene, int nx, int ny, RenderHierarchy h, int reps,
                           RenderStats *last, char *err, size_t errlen)
{
    Image img;
    double secs[3];
    scene->nx = nx;
    scene->ny = ny;
    if (image_alloc(&img, nx, ny, err, errlen) != 0)
        return -1;
    RenderOptions opt = { 1, false, h, { 0, 0 } };
    for (int r = 0; r < reps; r++) {
        if (render_scene(scene, &img, &opt, last, err, errlen) != 0) {
            image_free(&img);
            return -1;
        }
        secs[r] = last->seconds;
        bench_sink += img.rgb[(size_t)3 * nx * ny / 2];
    }
    image_free(&img);
    return median(secs, reps);
}

/* Runs render (the program) on the scene at path, to dir/end-to-end.png:
 * its wall time and peak memory into sr.  Returns 0, or -1.  The peak is
 * the largest of the waited-for children's, and a child's counts what it
 * held before exec, a copy of this process: so this runs before the
 * bench has grown. */
static int scale_end_to_end(const char *render, const char *path, const char *dir,
                            ScaleResults *sr, char *err, size_t errlen)
{
    char out[1100];
    snprintf(out, sizeof out, "%s/end-to-end.png", dir);
    double t0 = now_seconds();
    pid_t pid = fork();
    if (pid == 0) {
        execl(render, render, path, "--size", SCALE_SIZE, "--quiet", "-o", out, (char *)NULL);
        _exit(127);
    }
    int status;
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        snprintf(err, errlen, "%s %s did not run to the end", render, path);
        return -1;
    }
    sr->e2e_seconds = now_seconds() - t0;
    struct rusage ru;
    getrusage(RUSAGE_CHILDREN, &ru);        /* the largest child: render */
#ifdef __APPLE__
    sr->e2e_bytes = (double)ru.ru_maxrss;
#else
    sr->e2e_bytes = 1024.0 * (double)ru.ru_maxrss;
#endif
    return 0;
}

int scaling_prepare(const char *dir, const char *scenes, const char *render, bool quick,
                    ScaleResults *sr, char *err, size_t errlen)
{
    memset(sr, 0, sizeof *sr);
    sr->n = quick ? 4 : SCALE_MAX;
    for (int k = 0; k < sr->n; k++) {
        progress("scaling: the meshes", k, sr->n);
        if (k > 0 && scale_meshes[k].u == scale_meshes[k - 1].u)
            snprintf(sr->paths[k], sizeof sr->paths[k], "%s", sr->paths[k - 1]);
        else if (scale_write_mesh(dir, scenes, scale_meshes[k].u, scale_meshes[k].v, sr->paths[k],
                                  sizeof sr->paths[k], err, errlen) != 0)
            return -1;
    }
    progress("scaling: the render program", 0, 1);
    return scale_end_to_end(render, sr->paths[sr->n - 1], dir, sr, err, errlen);
}

/* The render times of the largest mesh and of the one of 10,000 triangles
 * at nx x ny with the hierarchy, taken in turn (the load of the machine
 * drifts between rows), medians of seven, into sr.  Returns 0, or -1. */
static int scale_ratio(ScaleResults *sr, int mid, int nx, int ny, char *err, size_t errlen)
{
    Scene small, big;
    if (scene_load(&small, sr->paths[mid], err, errlen) != 0)
        return -1;
    if (scene_load(&big, sr->paths[sr->n - 1], err, errlen) != 0) {
        scene_free(&small);
        return -1;
    }
    double ts[7], tb[7];
    RenderStats st;
    int status = 0;
    for (int r = 0; r < 7 && status == 0; r++) {
        ts[r] = scale_render(&small, nx, ny, RENDER_HIERARCHY_ON, 1, &st, err, errlen);
        tb[r] = scale_render(&big, nx, ny, RENDER_HIERARCHY_ON, 1, &st, err, errlen);
        status = ts[r] < 0 || tb[r] < 0 ? -1 : 0;
    }
    if (status == 0) {
        sr->ratio_small = median(ts, 7);
        sr->ratio_big = median(tb, 7);
    }
    scene_free(&small);
    scene_free(&big);
    return status;
}

int scaling_bench(bool quick, ScaleResults *sr, char *err, size_t errlen)
{
    const int reps = quick ? 1 : 3, nx = quick ? 160 : 640, ny = quick ? 120 : 480;
    const double budget = quick ? SCALE_BUDGET / 10 : SCALE_BUDGET;
    for (int k = 0; k < sr->n; k++) {
        progress("scaling", k, sr->n);
        ScaleRow *row = &sr->rows[k];
        row->triangles = scale_meshes[k].n;
        Scene scene;
        double t0 = now_seconds();
        if (scene_load(&scene, sr->paths[k], err, errlen) != 0)
            return -1;
        row->read_seconds = now_seconds() - t0;
        scene.ntriangles = row->triangles;
        RenderStats st;
        row->seconds_with = scale_render(&scene, nx, ny, RENDER_HIERARCHY_ON, reps, &st, err, errlen);
        row->nodes = st.nodes;
        row->build_seconds = st.build_seconds;
        row->pixels_with = nx * ny;
        /* the same view with fewer pixels: about budget tests */
        double fewer = sqrt(budget / ((double)row->triangles * nx * ny));
        int bx = fewer < 1 ? (int)(nx * fewer) : nx, by = fewer < 1 ? (int)(ny * fewer) : ny;
        bx = bx < 8 ? 8 : bx;
        by = by < 6 ? 6 : by;
        row->seconds_without = row->seconds_with < 0 ? -1
                               : scale_render(&scene, bx, by, RENDER_HIERARCHY_OFF, reps, &st, err, errlen);
        row->pixels_without = bx * by;
        scene_free(&scene);
        if (row->seconds_without < 0)
            return -1;
    }
    sr->nx = nx;
    sr->ny = ny;
    sr->budget = budget;
    sr->reps = reps;
    if (sr->n == SCALE_MAX) {       /* every mesh: the fifth has 10^4 triangles, the last 10^6 */
        progress("scaling: 10^6 against 10^4", 0, 1);
        if (scale_ratio(sr, 4, nx, ny, err, errlen) != 0)
            return -1;
    }
    sr->ran = true;
    return 0;
}

static double mrays(int pixels, double seconds)
{
    return seconds > 0 ? pixels / seconds / 1e6 : 0;
}

/* results_scaling.csv's body, for out_write (outfile.c): data is the ScaleResults. */
static void csv_scaling(FILE *f, const void *data)
{
    const ScaleResults *sr = data;
    fprintf(f, "triangles,nodes,read_s,build_s,mrays_per_s_with,mrays_per_s_without,"
               "pixels_with,pixels_without\n");
    for (int k = 0; k < sr->n; k++) {
        const ScaleRow *r = &sr->rows[k];
        fprintf(f, "%d,%d,%.4f,%.4f,%.4g,%.4g,%d,%d\n", r->triangles, r->nodes, r->read_seconds,
                r->build_seconds, mrays(r->pixels_with, r->seconds_with),
                mrays(r->pixels_without, r->seconds_without), r->pixels_with, r->pixels_without);
    }
}

int scaling_write(const ScaleResults *sr, const char *dir, const char *subtitle, char *err,
                  size_t errlen)
{
    if (out_write(dir, "results_scaling.csv", csv_scaling, sr, err, errlen) != 0)
        return -1;
    static PlotPoint with[SCALE_MAX], without[SCALE_MAX];
    for (int k = 0; k < sr->n; k++) {
        const ScaleRow *r = &sr->rows[k];
        PlotPoint a = { "", r->triangles, mrays(r->pixels_with, r->seconds_with), 0 };
        PlotPoint b = { "", r->triangles, mrays(r->pixels_without, r->seconds_without), 1 };
        with[k] = a;
        without[k] = b;
    }
    const PlotSeries series[2] = { { with, sr->n, "with the hierarchy" },
                                   { without, sr->n, "without: every triangle for every ray" } };
    return svg_lines(dir, "plot_scaling.svg", "Meshes at scale: rays per second against triangles",
                     subtitle, "triangles in the mesh (log scale)",
                     "million rays per second (log scale)",
                     series, 2, err, errlen);
}

void scaling_md(FILE *f, const ScaleResults *sr)
{
    fprintf(f, "\n## Part 5 at scale: rays per second against triangles\n\n");
    fprintf(f, "The renderer (render_scene, one thread) with the reference, on closed tubes "
               "around a trefoil knot (tests/tools/knot-mesh.sh) in knot.scene's view: with the "
               "bounding volume hierarchy at %dx%d; without it, every triangle for every ray, "
               "at fewer pixels of the same view (about %.0f million tests a render). Million "
               "rays per second, the median of %s; reading is the scene reader's time for the "
               "OBJ file, building the hierarchy's (and its probe for stray hits).\n\n",
            sr->nx, sr->ny, sr->budget / 1e6, sr->reps == 1 ? "one render" : "three renders");
    fprintf(f, "| triangles |");
    for (int k = 0; k < sr->n; k++)
        fprintf(f, " %d |", sr->rows[k].triangles);
    fprintf(f, "\n|---|");
    for (int k = 0; k < sr->n; k++)
        fprintf(f, "---:|");
    /* then a row per quantity */
    static const struct { const char *name, *format; } rows[] = {
        { "with the hierarchy (Mrays/s)", " %.3g |" }, { "without (Mrays/s)", " %.3g |" },
        { "nodes", " %.0f |" }, { "reading (s)", " %.3f |" }, { "building (s)", " %.3f |" },
    };
    for (int q = 0; q < 5; q++) {
        fprintf(f, "\n| %s |", rows[q].name);
        for (int k = 0; k < sr->n; k++) {
            const ScaleRow *r = &sr->rows[k];
            double v[] = { mrays(r->pixels_with, r->seconds_with),
                           mrays(r->pixels_without, r->seconds_without), r->nodes,
                           r->read_seconds, r->build_seconds };
            fprintf(f, rows[q].format, v[q]);
        }
    }
    fprintf(f, "\n\n![Rays per second against triangles](plot_scaling.svg)\n\n");

    const ScaleRow *big = &sr->rows[sr->n - 1];
    fprintf(f, "The render program on the largest mesh (%d triangles) at %s, end to end "
               "(starting, reading the OBJ file, building, rendering, writing the PNG): %.2f s, "
               "peak memory %.0f MB, %.0f bytes per triangle.",
            big->triangles, SCALE_SIZE, sr->e2e_seconds, sr->e2e_bytes / 1e6,
            sr->e2e_bytes / big->triangles);
    if (sr->ratio_small > 0)
        fprintf(f, " Rendering it (one thread) took %.2f times as long as rendering the mesh of "
                   "10,000 triangles at the same size (%.3f s against %.3f s, medians of seven "
                   "renders of each, taken in turn).",
                sr->ratio_big / sr->ratio_small, sr->ratio_big, sr->ratio_small);
    fprintf(f, "\n");
}
