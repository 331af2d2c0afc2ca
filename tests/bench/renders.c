/*
 * renders.c - the render-level view: a lab scene rendered whole, with each
 * method as the renderer's intersection, against an exact render.
 *
 * Every renderer shoots the same camera rays (the reference's parts 1, 2
 * and 3b, linked), row by row, in the layout its loop reads; the time
 * covers ray generation and intersection, on one thread.  A pixel differs
 * when its nearest sphere (or the background) is not the exact render's;
 * where the exact render allows two answers (oracle_closest's ambiguous
 * pixels) either counts as right.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "kit/scene.h"
#include "bench.h"

/* A pixel of the exact render: its nearest sphere (-1: none), and where
 * either of two is right (amb), the other. */
typedef struct {
    int exact, alt;
    bool amb;
} ExactPixel;

/* Renders scene at nx x ny with method m into idx (nx * ny entries); with
 * m NULL only makes the rays (the part every renderer shares). */
static void render_once(const Method *m, const BenchScene *bs, const Scene *scene, int nx, int ny,
                        RaySet *row, double *trow, int *idx)
{
    double w, h;
    image_plane_size(scene->fov_degrees, (double)nx / ny, scene->d, &w, &h);
    row->n = nx;
    for (int j = 0; j < ny; j++) {
        for (int i = 0; i < nx; i++) {
            Vec3 pixel = pixel_coordinates(i, j, nx, ny, w, h, scene->d);
            rayset_put(row, i, camera_ray(scene->eye, pixel), m ? m->layouts : LAYOUT_SOA_D);
        }
        if (m)
            method_closest(m, bs, row, idx + (size_t)j * nx, trow);
        else
            idx[(size_t)j * nx] = (int)row->dx[nx - 1];
    }
}

static void scene_basename(const char *path, char *out, size_t outlen)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    snprintf(out, outlen, "%s", base);
    char *dot = strrchr(out, '.');
    if (dot && strcmp(dot, ".scene") == 0)
        *dot = '\0';
}

/* The exact render of scene at nx x ny into ex, by oracle_closest; counts
 * the ambiguous pixels in res->ambiguous. */
static void exact_render(const Scene *scene, int nx, int ny, ExactPixel *ex, RenderResult *res)
{
    double w, h;
    image_plane_size(scene->fov_degrees, (double)nx / ny, scene->d, &w, &h);
    for (int j = 0; j < ny; j++) {
        if (j % 16 == 0)
            progress(res->scene, j, ny);
        for (int i = 0; i < nx; i++) {
            Ray ray = camera_ray(scene->eye, pixel_coordinates(i, j, nx, ny, w, h, scene->d));
            ExactPixel *p = &ex[(size_t)j * nx + i];
            p->exact = oracle_closest(scene, &ray, &p->amb, &p->alt);
            res->ambiguous += p->amb;
        }
    }
}

/* How many of the np pixels of the render idx are not as the exact
 * render ex allows (every index goes into the bench's checksum). */
static long differ_from_exact(const int *idx, const ExactPixel *ex, size_t np)
{
    long differ = 0, sum = 0;
    for (size_t p = 0; p < np; p++) {
        sum += idx[p];
        if (idx[p] != ex[p].exact && !(ex[p].amb && idx[p] == ex[p].alt))
            differ++;
    }
    bench_sink += (double)sum;
    return differ;
}

int render_bench(const char *path, int nx, int ny, int reps, RenderResult *res,
                 char *err, size_t errlen)
{
    Scene scene;
    if (scene_load(&scene, path, err, errlen) != 0)
        return -1;
    if (scene.nplanes > 0 || scene.ntriangles > 0) {
        scene_free(&scene);
        return 1;
    }
    if (bench_nmethods > (int)(sizeof res->seconds / sizeof res->seconds[0])) {
        snprintf(err, errlen, "render_bench: too many methods");
        scene_free(&scene);
        return -1;
    }
    memset(res, 0, sizeof *res);
    scene_basename(path, res->scene, sizeof res->scene);
    res->nspheres = scene.nspheres;
    res->nx = nx;
    res->ny = ny;
    res->pixels = (long)nx * ny;

    size_t np = (size_t)nx * ny;
    FastScene fs;
    Spheref *sf = malloc((size_t)(scene.nspheres > 0 ? scene.nspheres : 1) * sizeof *sf);
    int *idx = malloc(np * sizeof *idx);
    double *trow = malloc((size_t)nx * sizeof *trow);
    double *samples = malloc((size_t)((bench_nmethods + 1) * reps) * sizeof *samples);
    ExactPixel *ex = malloc(np * sizeof *ex);
    RaySet row;
    int rowok = rayset_alloc(&row, nx) == 0;
    int fsok = fast_build(&fs, scene.spheres, scene.nspheres, scene.eye) == 0;
    int status = -1;
    if (!sf || !idx || !trow || !samples || !ex || !rowok || !fsok) {
        snprintf(err, errlen, "%s: out of memory", path);
        goto done;
    }
    for (int k = 0; k < scene.nspheres; k++)
        sf[k] = spheref_from(&scene.spheres[k]);
    BenchScene bs = { scene.spheres, sf, scene.nspheres, &fs };

    exact_render(&scene, nx, ny, ex, res);

    /* The renders, interleaved as in the throughput runs; "method"
     * bench_nmethods only makes the rays. */
    int nr = bench_nmethods + 1;
    for (Rounds it = { .n = nr, .rounds = reps }; rounds_next(&it);) {
        int m = it.m;
        progress(res->scene, ny + it.k - 1, ny + reps * nr);
        double t0 = now_seconds();
        render_once(m < bench_nmethods ? &bench_methods[m] : NULL, &bs, &scene, nx, ny, &row, trow,
                    idx);
        samples[m * reps + it.r] = now_seconds() - t0;
        if (m == bench_nmethods)
            bench_sink += idx[0];
        else
            res->differ[m] = differ_from_exact(idx, ex, np);  /* the same every repetition */
    }
    for (int m = 0; m < bench_nmethods; m++)
        res->seconds[m] = median(samples + m * reps, reps);
    res->rays_seconds = median(samples + bench_nmethods * reps, reps);
    status = 0;

done:
    free(sf);
    free(idx);
    free(trow);
    free(samples);
    free(ex);
    if (rowok)
        rayset_free(&row);
    if (fsok)
        fast_free(&fs);
    scene_free(&scene);
    return status;
}
