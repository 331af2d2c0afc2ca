/*
 * render_main.c - the `render` program: a scene file in, a PNG or PPM out.
 *
 *     render SCENE [--size WxH] [-o OUT] [--threads N] [--hierarchy auto|on|off]
 *            [--edges FILE] [--quiet]
 *
 * Prints the time taken and the rays per second, and for a scene with
 * triangles the time taken to read it and the hierarchy built.  Exit
 * status: 0 on success, 1 when the scene or the output fails, 2 on bad
 * usage.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <ctype.h>
#include <errno.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "edges.h"
#include "image.h"
#include "render.h"
#include "scene.h"
#include "textfile.h"

#define RENDER_MAIN_MAX_THREADS 1024

/* The command line, once read. */
typedef struct {
    const char *scene_path;
    const char *out_path;        /* NULL: out/<scene name>.png */
    const char *edges_path;      /* NULL: no file of edges     */
    int nx, ny;                  /* 0: the scene's own size    */
    int threads;                 /* 0: one per core            */
    RenderHierarchy hierarchy;
    bool quiet;
} RenderArgs;

/* Prints the usage to f. */
static void render_usage(FILE *f)
{
    fprintf(f,
            "usage: render SCENE [--size WxH] [-o OUT] [--threads N] [--hierarchy auto|on|off]"
            " [--edges FILE] [--quiet]\n"
            "  renders the scene file SCENE with the stage files built in\n"
            "  --size WxH   image size instead of the scene's, 1..%d each side\n"
            "  -o OUT       output image, .png or .ppm (default out/<scene name>.png)\n"
            "  --threads N  worker threads, 1..%d (default one per core)\n"
            "  --hierarchy  for a scene with planes or triangles, a bounding volume hierarchy\n"
            "               over its spheres and triangles: auto (with %d or more), on, off\n"
            "  --edges FILE also write the pixels on an edge, whose colour a ray moved by a\n"
            "               rounding changes, and their other colours (for compare --edges)\n"
            "  --quiet      print nothing but errors\n"
            "exit status: 0 done, 1 bad scene or output, 2 bad usage\n",
            IMAGE_MAX_SIDE, RENDER_MAIN_MAX_THREADS, RENDER_HIERARCHY_MIN);
}

/* Reads a whole decimal number from text (digits only, no sign or space)
 * in 1 .. max into *value, and stores where it stopped in *end.
 * Returns 0, or -1 when there are no digits or the number is out of range. */
static int render_main_count(const char *text, int max, int *value, const char **end)
{
    long n = 0;
    const char *p = text;
    while (*p >= '0' && *p <= '9') {
        n = 10 * n + (*p - '0');
        if (n > max)
            return -1;
        p++;
    }
    if (p == text || n < 1)
        return -1;
    *value = (int)n;
    *end = p;
    return 0;
}

/* Reads "WxH" into *nx, *ny, each 1 .. IMAGE_MAX_SIDE.
 * Returns 0, or -1 when text is anything else. */
static int render_main_size(const char *text, int *nx, int *ny)
{
    const char *p;
    if (render_main_count(text, IMAGE_MAX_SIDE, nx, &p) < 0 || *p != 'x')
        return -1;
    if (render_main_count(p + 1, IMAGE_MAX_SIDE, ny, &p) < 0 || *p != '\0')
        return -1;
    return 0;
}

/* True when path ends in .png or .ppm, in any case: the names image_write
 * takes, checked before a long render rather than after. */
static bool render_main_image_name(const char *path)
{
    size_t len = strlen(path);
    if (len < 5 || path[len - 4] != '.' || path[len - 5] == '/')
        return false;
    char ext[4];
    for (int k = 0; k < 3; k++)
        ext[k] = (char)tolower((unsigned char)path[len - 3 + k]);
    ext[3] = '\0';
    return strcmp(ext, "png") == 0 || strcmp(ext, "ppm") == 0;
}

/* Reads the command line into args.  Returns 0, or -1 after printing what
 * is wrong and the usage to stderr.  "--help" prints the usage and exits. */
static int render_main_args(int argc, char **argv, RenderArgs *args)
{
    RenderArgs none = { NULL, NULL, NULL, 0, 0, 0, RENDER_HIERARCHY_AUTO, false };
    *args = none;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k];
        const char *value = k + 1 < argc ? argv[k + 1] : NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            render_usage(stdout);
            exit(0);
        } else if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            args->quiet = true;
        } else if (strcmp(a, "--size") == 0 || strcmp(a, "-o") == 0 || strcmp(a, "--threads") == 0
                   || strcmp(a, "--hierarchy") == 0 || strcmp(a, "--edges") == 0) {
            if (!value) {
                fprintf(stderr, "render: %s needs a value\n", a);
                goto usage;
            }
            k++;
            const char *end;
            if (strcmp(a, "-o") == 0) {
                if (!render_main_image_name(value)) {
                    fprintf(stderr, "render: -o wants a file name ending in .png or .ppm, "
                            "got '%.40s'\n", value);
                    goto usage;
                }
                args->out_path = value;
            } else if (strcmp(a, "--edges") == 0) {
                args->edges_path = value;
            } else if (strcmp(a, "--hierarchy") == 0) {
                /* in RenderHierarchy's order */
                static const char *const modes[] = { "auto", "off", "on" };
                int m = 0;
                while (m < 3 && strcmp(value, modes[m]) != 0)
                    m++;
                if (m == 3) {
                    fprintf(stderr, "render: --hierarchy wants auto, on or off, got '%.40s'\n",
                            value);
                    goto usage;
                }
                args->hierarchy = (RenderHierarchy)m;
            } else if (strcmp(a, "--size") == 0) {
                if (render_main_size(value, &args->nx, &args->ny) < 0) {
                    fprintf(stderr, "render: --size wants WxH, each a whole number from 1 to %d, "
                            "got '%.40s'\n", IMAGE_MAX_SIDE, value);
                    goto usage;
                }
            } else if (render_main_count(value, RENDER_MAIN_MAX_THREADS, &args->threads, &end) < 0
                       || *end != '\0') {
                fprintf(stderr, "render: --threads wants a whole number from 1 to %d, got '%.40s'\n",
                        RENDER_MAIN_MAX_THREADS, value);
                goto usage;
            }
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "render: unknown option '%.40s'\n", a);
            goto usage;
        } else if (args->scene_path) {
            fprintf(stderr, "render: one scene at a time ('%.40s' and '%.40s')\n",
                    args->scene_path, a);
            goto usage;
        } else {
            args->scene_path = a;
        }
    }
    if (!args->scene_path) {
        fprintf(stderr, "render: no scene file given\n");
        goto usage;
    }
    return 0;
usage:
    render_usage(stderr);
    return -1;
}

/* The file name of path without its directories: "labs/scenes/a.scene" -> "a.scene". */
static const char *render_main_basename(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* Writes "out/<scene name>.png" into buf (the name without its last
 * extension) and makes the directory out if it is missing.
 * Returns 0, or -1 with a message in err. */
static int render_main_default_out(const char *scene_path, char *buf, size_t len,
                                   char *err, size_t errlen)
{
    const char *name = render_main_basename(scene_path);
    const char *dot = strrchr(name, '.');
    int stem = dot && dot != name ? (int)(dot - name) : (int)strlen(name);
    int n = snprintf(buf, len, "out/%.*s.png", stem, name);
    if (n < 0 || (size_t)n >= len)
        return kit_fail(err, errlen, "render: the scene's name is too long for an output name");
    if (mkdir("out", 0777) != 0 && errno != EEXIST)
        return kit_fail(err, errlen, "render: cannot make the directory out: %s", strerror(errno));
    return 0;
}

/* ---- when the student's code crashes ------------------------------------ */

/* Not under a sanitizer, whose own report of a crash says more. */
#if defined(__SANITIZE_ADDRESS__)
#define RENDER_MAIN_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RENDER_MAIN_SANITIZED 1
#endif
#endif

#ifndef RENDER_MAIN_SANITIZED

/* Appends text to buf at *len (within size); for the signal handler, which
 * may call neither printf nor malloc. */
static void crash_put(char *buf, size_t size, size_t *len, const char *text)
{
    while (*text && *len + 1 < size)
        buf[(*len)++] = *text++;
}

/* Appends the row number n (never negative) in decimal. */
static void crash_put_row(char *buf, size_t size, size_t *len, int n)
{
    char digits[12];
    char *p = digits + sizeof digits - 1;
    *p = '\0';
    do
        *--p = (char)('0' + n % 10);
    while ((n /= 10) > 0);
    crash_put(buf, size, len, p);
}

/* Says what crashed and where, then lets the signal end the program as it
 * would have (make still reports the status). */
static atomic_flag render_main_crash_told = ATOMIC_FLAG_INIT;

static void render_main_crashed(int sig)
{
    /* Every thread may crash at once: the first says so and ends the
     * program; the others wait for that. */
    if (atomic_flag_test_and_set(&render_main_crash_told))
        for (;;)
            pause();
    static const struct { int sig; const char *what; } names[] = {
        { SIGSEGV, "a segmentation fault (SIGSEGV), a read or write of memory the program does "
                   "not own, such as an index past the end of an array or a pointer that is NULL "
                   "or was never set" },
        { SIGBUS, "a bus error (SIGBUS), a read or write through a bad pointer" },
        { SIGFPE, "an arithmetic error (SIGFPE), such as an integer divided by zero" },
        { SIGILL, "an illegal instruction (SIGILL)" },
        { SIGABRT, "abort() was called (SIGABRT), or an assert failed" },
    };
    char msg[768];
    size_t len = 0;
    const char *what = "a signal";
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (names[k].sig == sig)
            what = names[k].what;
    crash_put(msg, sizeof msg, &len, "\nrender: the code of the parts crashed");
    int j0 = 0, j1 = 0, at = render_crash_rows(&j0, &j1);
    if (at == 0) {
        crash_put(msg, sizeof msg, &len, " in image_plane_size (Part 1)");
    } else if (at > 0) {
        crash_put(msg, sizeof msg, &len, " while drawing row");
        crash_put(msg, sizeof msg, &len, j1 - j0 > 1 ? "s " : " ");
        crash_put_row(msg, sizeof msg, &len, j0);
        if (j1 - j0 > 1) {
            crash_put(msg, sizeof msg, &len, " to ");
            crash_put_row(msg, sizeof msg, &len, j1 - 1);
        }
    }
    crash_put(msg, sizeof msg, &len, ": ");
    crash_put(msg, sizeof msg, &len, what);
    crash_put(msg, sizeof msg, &len, ". `make grade` runs each part on its own tests, and "
              "shows the input that crashes it.\n");
    ssize_t ignored = write(STDERR_FILENO, msg, len);
    (void)ignored;
    signal(sig, SIG_DFL);
    raise(sig);
}

/* render_main_crashed for each signal a crash raises. */
static void render_main_on_crash(void)
{
    static const int sigs[] = { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT };
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = render_main_crashed;
    sa.sa_flags = 0;
    sigemptyset(&sa.sa_mask);
    for (size_t k = 0; k < sizeof sigs / sizeof sigs[0]; k++)
        sigaction(sigs[k], &sa, NULL);
}
#else
static void render_main_on_crash(void)   /* the sanitizer reports the crash */
{
}
#endif

/* A scene named without its folder or ending ("wide", "wide.scene"):
 * names the shipped scene it most likely means, when there is one. */
static void render_main_suggest_scene(const char *path)
{
    struct stat st;
    if (strchr(path, '/') || stat(path, &st) == 0)
        return;
    char guess[512];
    size_t n = strlen(path);
    bool ends = n > 6 && strcmp(path + n - 6, ".scene") == 0;
    snprintf(guess, sizeof guess, "labs/scenes/%s%s", path, ends ? "" : ".scene");
    if (stat(guess, &st) == 0 && S_ISREG(st.st_mode))
        fprintf(stderr, "render: the kit's scenes are in labs/scenes: SCENE=%s\n", guess);
}

/* Prints what the render did before its "rendered" line: for a scene with
 * triangles, how long reading it took, and the hierarchy built, if any. */
static void render_main_report(const char *name, const Scene *scene, double read_seconds,
                               const RenderStats *stats)
{
    if (scene->ntriangles > 0)
        printf("read %s in %.3f s: %d triangle%s\n", name, read_seconds, scene->ntriangles,
               scene->ntriangles == 1 ? "" : "s");
    if (stats->objects == 0)
        return;
    printf("built a hierarchy of %d triangle%s", scene->ntriangles,
           scene->ntriangles == 1 ? "" : "s");
    if (scene->nspheres > 0)
        printf(" and %d sphere%s", scene->nspheres, scene->nspheres == 1 ? "" : "s");
    printf(" in %d nodes in %.3f s%s\n", stats->nodes, stats->build_seconds,
           stats->stray ? ", then set it aside: a stray hit (see the note above)" : "");
}

/* Renders scene four more times, each pixel centre nudged by EDGES_NUDGE
 * of the image plane left, right, up and down, and writes the pixels of
 * img whose colour changes to path (edges.h).  Returns 0, or -1 with a
 * reason in err. */
static int render_main_edges(const Scene *scene, const Image *img, RenderOptions opt,
                             const char *path, bool quiet, char *err, size_t errlen)
{
    static const double way[4][2] = { { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } };
    Image nudged[4] = { { 0, 0, NULL } };
    Edges edges = { 0, 0, 0, NULL };
    int status = 0;
    opt.progress = false;
    for (int k = 0; k < 4 && status == 0; k++) {
        opt.nudge[0] = way[k][0] * EDGES_NUDGE;
        opt.nudge[1] = way[k][1] * EDGES_NUDGE;
        status = image_alloc(&nudged[k], scene->nx, scene->ny, err, errlen);
        if (status == 0)
            status = render_scene(scene, &nudged[k], &opt, NULL, err, errlen);
    }
    if (status == 0)
        status = edges_find(&edges, img, nudged, err, errlen);
    if (status == 0)
        status = edges_write(&edges, path, err, errlen);
    if (status == 0 && !quiet)
        printf("wrote %s: %zu pixel%s on an edge\n", path, edges.count, edges.count == 1 ? "" : "s");
    edges_free(&edges);
    for (int k = 0; k < 4; k++)
        image_free(&nudged[k]);
    return status;
}

/* Renders as the command line says.  Returns the exit status: 0 done,
 * 1 bad scene or output, 2 bad usage. */
int main(int argc, char **argv)
{
    RenderArgs args;
    if (render_main_args(argc, argv, &args) < 0)
        return 2;
    render_main_on_crash();

    char err[512], default_out[4096];
    Scene scene;
    double read_start = render_now();
    if (scene_load(&scene, args.scene_path, err, sizeof err) < 0) {
        fprintf(stderr, "render: %s\n", err);
        render_main_suggest_scene(args.scene_path);
        return 1;
    }
    double read_seconds = render_now() - read_start;
    if (args.nx > 0) {
        scene.nx = args.nx;
        scene.ny = args.ny;
    }
    const char *out = args.out_path;
    if (!out) {
        if (render_main_default_out(args.scene_path, default_out, sizeof default_out,
                                    err, sizeof err) < 0) {
            fprintf(stderr, "%s\n", err);
            scene_free(&scene);
            return 1;
        }
        out = default_out;
    }

    Image img;
    RenderStats stats;
    RenderOptions opt = { args.threads, !args.quiet, args.hierarchy, { 0, 0 } };
    int status = 1;
    if (image_alloc(&img, scene.nx, scene.ny, err, sizeof err) < 0) {
        fprintf(stderr, "render: %s\n", err);
    } else {
        if (render_scene(&scene, &img, &opt, &stats, err, sizeof err) < 0) {
            fprintf(stderr, "%s\n", err);
        } else if (image_write(&img, out, err, sizeof err) < 0) {
            fprintf(stderr, "render: %s\n", err);
        } else {
            status = 0;
            if (!args.quiet) {
                render_main_report(render_main_basename(args.scene_path), &scene, read_seconds, &stats);
                printf("rendered %s %dx%d with %d thread%s in %.3f s: "
                       "%.1f million rays/s (%.1f million per thread)\n",
                       render_main_basename(args.scene_path), scene.nx, scene.ny,
                       stats.threads, stats.threads == 1 ? "" : "s", stats.seconds,
                       stats.rays_per_second / 1e6, stats.rays_per_second / 1e6 / stats.threads);
                printf("wrote %s\n", out);
            }
            if (args.edges_path
                && render_main_edges(&scene, &img, opt, args.edges_path, args.quiet, err, sizeof err) < 0) {
                fprintf(stderr, "render: %s\n", err);
                status = 1;
            }
        }
        image_free(&img);
    }
    scene_free(&scene);
    return status;
}
