/*
 * render.c - the renderer's main loop: every pixel through Parts 1 to 3b.
 *
 * Part 1 runs once; then worker threads, one per core unless told
 * otherwise, take rows in chunks from a shared atomic counter until none
 * are left, so a thread that drew cheap rows simply takes more of them.
 * Every pixel depends only on (i, j), so the image is the same whatever the
 * number of threads.  The calling thread waits, and in a terminal shows how
 * far the render has got once it has taken more than a second.
 *
 * A scene drawn by closest.h with enough spheres and triangles gets a
 * hierarchy first (bvh.h), probed for stray hits (closest_probe).  When a
 * thread meets a stray hit during the render, every thread stops and the
 * whole image is drawn again without it.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "render.h"
#include "closest.h"
#include "textfile.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define RENDER_MAX_THREADS   256
#define RENDER_CHUNK_PIXELS  2048   /* a chunk is at least one row, else about this many pixels */
#define RENDER_RUN           16     /* pixels whose rays are made before their colours */
#define RENDER_PROGRESS_AFTER 1.0   /* seconds before the progress line appears */
#define RENDER_PROGRESS_EVERY 0.25  /* seconds between its updates */
#define RENDER_LINE_EVERY    5.0    /* seconds between progress lines, not on a terminal */
#define RENDER_STALLED       10.0   /* seconds with no row drawn before a word on endless loops
                                       (RENDER_STALLED_SECONDS sets it, for the kit's tests) */


/* What the threads share: the inputs, and the counters of rows taken and drawn. */
typedef struct {
    const Scene *scene;
    Image *img;
    double w, h;                 /* the image plane's size (Part 1)           */
    double nudge[2];             /* RenderOptions' nudge                      */
    bool closest;                /* drawn by closest.h, not by ray_color      */
    const Bvh *bvh;              /* closest.h's hierarchy, or NULL            */
    atomic_bool stray;           /* a thread met a stray hit (closest.h)      */
    int rows_per_chunk;
    atomic_int next_row;         /* the first row no thread has taken yet     */
    atomic_int rows_done;        /* rows drawn, for the progress line         */
    pthread_mutex_t lock;        /* guards running, and signals finished      */
    pthread_cond_t finished;
    int running;                 /* worker threads not yet finished           */
} RenderJob;

/* What this thread is drawing (render_crash_rows): rows crash_j0 ..
 * crash_j1 - 1, or Part 1 (crash_j0 = -2), or nothing (-1).  Set once per
 * chunk of rows, never per pixel. */
static _Thread_local volatile int crash_j0 = -1, crash_j1 = -1;

int render_crash_rows(int *j0, int *j1)
{
    if (crash_j0 == -2)
        return 0;
    if (crash_j0 < 0)
        return -1;
    *j0 = crash_j0;
    *j1 = crash_j1;
    return 1;
}

double render_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The number of cores online, at least 1. */
static int render_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        return 1;
    return n > RENDER_MAX_THREADS ? RENDER_MAX_THREADS : (int)n;
}

/* Draws rows j0 .. j1 - 1 of the image: for each pixel, its centre
 * (Part 2), the ray from the eye through it and the colour the ray sees
 * (Part 3b), stored as three bytes.  Never fails.
 *
 * Two things make the loop faster without changing a byte of the image.
 * The rays of a run of RENDER_RUN pixels are made first, then their
 * colours: making a ray is a square root and a division whose results
 * take long to arrive, and in a loop of their own the processor overlaps
 * them instead of waiting for each.  And a colour equal, bit for bit, to
 * the previous pixel's reuses its bytes: neighbouring pixels mostly see
 * the same sphere. */
static void render_rows(const RenderJob *job, int j0, int j1)
{
    const Scene *scene = job->scene;
    const int nx = scene->nx, ny = scene->ny;
    const double w = job->w, h = job->h, d = scene->d;
    const Vec3 e = scene->eye;
    const bool nudged = job->nudge[0] != 0 || job->nudge[1] != 0;
    for (int j = j0; j < j1; j++) {
        unsigned char *px = job->img->rgb + (size_t)3 * nx * (size_t)j;
        Vec3 last = { 0, 0, 0 };        /* the previous pixel's colour, once have_last */
        unsigned char rgb[3] = { 0, 0, 0 };
        bool have_last = false;
        for (int i0 = 0; i0 < nx; i0 += RENDER_RUN) {
            const int n = nx - i0 < RENDER_RUN ? nx - i0 : RENDER_RUN;
            Ray rays[RENDER_RUN];
            for (int k = 0; k < n; k++) {
                Vec3 s = pixel_coordinates(i0 + k, j, nx, ny, w, h, d);
                if (nudged)
                    s = vec3(s.x + job->nudge[0], s.y + job->nudge[1], s.z);
                rays[k] = camera_ray(e, s);
            }
            for (int k = 0; k < n; k++) {
                Vec3 color = ray_color(scene, &rays[k]);
                if (!have_last || memcmp(&color, &last, sizeof color) != 0) {
                    rgb[0] = image_channel(color.x);
                    rgb[1] = image_channel(color.y);
                    rgb[2] = image_channel(color.z);
                    last = color;
                    have_last = true;
                }
                px[0] = rgb[0];
                px[1] = rgb[1];
                px[2] = rgb[2];
                px += 3;
            }
        }
    }
}

/* A worker thread: takes chunks of rows until none are left, then says it
 * has finished.  Returns NULL. */
static void *render_worker(void *arg)
{
    RenderJob *job = arg;
    const int ny = job->scene->ny;
    while (!atomic_load(&job->stray)) {
        int j0 = atomic_fetch_add(&job->next_row, job->rows_per_chunk);
        if (j0 >= ny)
            break;
        int j1 = ny - j0 < job->rows_per_chunk ? ny : j0 + job->rows_per_chunk;
        crash_j1 = j1;
        crash_j0 = j0;
        if (!job->closest)
            render_rows(job, j0, j1);
        else if (!closest_rows(job->scene, job->bvh, job->img, job->w, job->h, job->nudge,
                                   j0, j1))
            atomic_store(&job->stray, true);
        atomic_fetch_add(&job->rows_done, j1 - j0);
    }
    pthread_mutex_lock(&job->lock);
    job->running--;
    pthread_cond_signal(&job->finished);
    pthread_mutex_unlock(&job->lock);
    return NULL;
}

/* Waits until every worker has finished.  With show set: on a terminal
 * (tty), writes "\r  rendering  43%" to stderr a few times a second once
 * the render has run for more than a second, and clears the line at the
 * end; elsewhere, a line "render: 43% of the rows drawn after 5 s" every
 * RENDER_LINE_EVERY seconds; either way a line once no row has been drawn
 * for RENDER_STALLED seconds.  Never fails. */
static void render_wait(RenderJob *job, bool show, bool tty, double start)
{
    bool shown = false, stall_told = false;
    double last = 0, last_row_at = start, stalled = RENDER_STALLED;
    int rows_seen = 0;
    const char *env = getenv("RENDER_STALLED_SECONDS");
    if (env && atof(env) > 0)
        stalled = atof(env);
    pthread_mutex_lock(&job->lock);
    while (job->running > 0) {
        if (!show) {
            pthread_cond_wait(&job->finished, &job->lock);
            continue;
        }
        /* The wake-up time is on the real-time clock, the only one
         * pthread_cond_timedwait takes everywhere; a jump of that clock
         * only changes when the next update is drawn. */
        struct timespec until;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_nsec += (long)(RENDER_PROGRESS_EVERY * 1e9);
        if (until.tv_nsec >= 1000000000L) {
            until.tv_sec += 1;
            until.tv_nsec -= 1000000000L;
        }
        pthread_cond_timedwait(&job->finished, &job->lock, &until);
        double now = render_now();
        int rows = atomic_load(&job->rows_done);
        if (rows != rows_seen)
            rows_seen = rows, last_row_at = now;
        if (job->running > 0 && !stall_told && now - last_row_at > stalled) {
            fprintf(stderr, "%sno row finished in the last %.0f s: if the code loops forever, stop it "
                            "with Ctrl-C (make grade stops each test after a few seconds, and names "
                            "the ones that do not finish)\n", tty ? "\r  " : "render: ", stalled);
            fflush(stderr);
            stall_told = true;
        }
        /* On a terminal a line redrawn in place; elsewhere (a log, an
         * editor's pane) a line every few seconds, so that a long render
         * or an endless loop does not wait in silence. */
        double every = tty ? RENDER_PROGRESS_EVERY * 0.9 : RENDER_LINE_EVERY;
        if (job->running > 0 && now - start > (tty ? RENDER_PROGRESS_AFTER : RENDER_LINE_EVERY)
            && now - last >= every) {
            int percent = (int)(100.0 * atomic_load(&job->rows_done) / job->scene->ny);
            if (tty)
                fprintf(stderr, "\r  rendering %3d%%", percent);
            else
                fprintf(stderr, "render: %d%% of the rows drawn after %.0f s\n", percent, now - start);
            fflush(stderr);
            shown = tty;
            last = now;
        }
    }
    pthread_mutex_unlock(&job->lock);
    if (shown) {
        fprintf(stderr, "\r                  \r");
        fflush(stderr);
    }
}

/* Starts nthreads workers on job from its first row and waits for them
 * (with show set, with a progress line from start on).  Returns the
 * number of threads started: 0 when none could start, with the reason in
 * err. */
static int render_pass(RenderJob *job, int nthreads, bool show, double start,
                       char *err, size_t errlen)
{
    pthread_t threads[RENDER_MAX_THREADS];
    int started = 0, status = 0;
    atomic_store(&job->next_row, 0);
    atomic_store(&job->rows_done, 0);
    pthread_mutex_lock(&job->lock);
    for (; started < nthreads; started++) {
        status = pthread_create(&threads[started], NULL, render_worker, job);
        if (status != 0)
            break;                    /* the threads already started share the rows */
        job->running++;
    }
    pthread_mutex_unlock(&job->lock);
    if (started == 0) {
        kit_fail(err, errlen, "render: cannot start a thread: %s", strerror(status));
        return 0;
    }
    render_wait(job, show, isatty(STDERR_FILENO), start);
    for (int k = 0; k < started; k++)
        pthread_join(threads[k], NULL);
    return started;
}

/* Builds the hierarchy of a scene that closest.h draws, when opt asks for
 * one, and probes it for stray hits (closest_probe).  Returns it, or NULL
 * when there is none to use; fills in the hierarchy's part of stats.  A
 * hierarchy that cannot be built (no memory) only makes the render slower. */
static const Bvh *render_hierarchy(const Scene *scene, Bvh *bvh, const RenderOptions *opt,
                                   RenderStats *stats)
{
    int objects = scene->nspheres + scene->ntriangles;
    RenderHierarchy want = opt ? opt->hierarchy : RENDER_HIERARCHY_AUTO;
    if (want == RENDER_HIERARCHY_OFF || objects == 0
        || (want == RENDER_HIERARCHY_AUTO && objects < RENDER_HIERARCHY_MIN))
        return NULL;
    double start = render_now();
    char err[128];
    if (bvh_build(bvh, scene, err, sizeof err) < 0)
        return NULL;
    stats->objects = objects;
    stats->nodes = bvh->nnodes;
    stats->stray = closest_probe(scene, bvh);
    stats->build_seconds = render_now() - start;
    if (!stats->stray)
        return bvh;
    bvh_free(bvh);                      /* the plain loop needs none of it */
    return NULL;
}

/* Says, when the progress line may show, why a big scene may now be slow. */
static void render_stray_note(const RenderOptions *opt)
{
    if (opt && opt->progress)
        fprintf(stderr, "render: note: sphere_intersect or triangle_intersect said a ray hit an "
                        "object at a point outside the object's box, which the hierarchy that "
                        "speeds up big scenes may skip: every object is tested for every ray "
                        "instead, so that the picture is the one your code makes (it takes "
                        "longer)\n");
}

/* Renders scene into img (see render.h).  Returns 0, or -1 with a reason
 * in err when the image does not match the scene or no thread could start. */
int render_scene(const Scene *scene, Image *img, const RenderOptions *opt,
                 RenderStats *stats, char *err, size_t errlen)
{
    const int nx = scene->nx, ny = scene->ny;
    if (nx < 1 || ny < 1 || !img->rgb || img->width != nx || img->height != ny) {
        kit_fail(err, errlen, "render: the image is %dx%d but the scene is %dx%d",
                 img->width, img->height, nx, ny);
        return -1;
    }
    RenderStats unused;
    if (!stats)
        stats = &unused;
    memset(stats, 0, sizeof *stats);

    RenderJob job;
    Bvh bvh = { 0 };
    job.scene = scene;
    job.img = img;
    job.closest = scene->nplanes > 0 || scene->ntriangles > 0;
    job.bvh = job.closest ? render_hierarchy(scene, &bvh, opt, stats) : NULL;
    if (stats->stray)
        render_stray_note(opt);
    atomic_init(&job.stray, false);
    double start = render_now();
    crash_j0 = -2;
    image_plane_size(scene->fov_degrees, (double)nx / ny, scene->d, &job.w, &job.h);
    crash_j0 = -1;
    job.nudge[0] = opt ? opt->nudge[0] * job.w : 0;
    job.nudge[1] = opt ? opt->nudge[1] * job.h : 0;
    job.rows_per_chunk = nx >= RENDER_CHUNK_PIXELS ? 1 : RENDER_CHUNK_PIXELS / nx;
    atomic_init(&job.next_row, 0);
    atomic_init(&job.rows_done, 0);
    job.running = 0;

    int chunks = (ny + job.rows_per_chunk - 1) / job.rows_per_chunk;
    int nthreads = opt && opt->threads > 0 ? opt->threads : render_cores();
    if (nthreads > RENDER_MAX_THREADS)
        nthreads = RENDER_MAX_THREADS;
    if (nthreads > chunks)
        nthreads = chunks;            /* a thread with no rows would only cost */

    if (pthread_mutex_init(&job.lock, NULL) != 0) {
        bvh_free(&bvh);
        kit_fail(err, errlen, "render: cannot create a mutex");
        return -1;
    }
    if (pthread_cond_init(&job.finished, NULL) != 0) {
        pthread_mutex_destroy(&job.lock);
        bvh_free(&bvh);
        kit_fail(err, errlen, "render: cannot create a condition variable");
        return -1;
    }
    bool show = opt && opt->progress;
    int started = render_pass(&job, nthreads, show, start, err, errlen);
    if (started > 0 && atomic_load(&job.stray)) {
        render_stray_note(opt);
        stats->stray = true;
        job.bvh = NULL;
        atomic_store(&job.stray, false);
        started = render_pass(&job, nthreads, show, start, err, errlen);
    }
    pthread_cond_destroy(&job.finished);
    pthread_mutex_destroy(&job.lock);
    bvh_free(&bvh);
    if (started == 0)
        return -1;

    double seconds = render_now() - start;
    if (!(seconds > 0))
        seconds = 1e-9;               /* a clock too coarse to see the render */
    stats->seconds = seconds;
    stats->rays_per_second = (double)nx * ny / seconds;
    stats->threads = started;
    return 0;
}
