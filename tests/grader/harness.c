/*
 * harness.c - the child side of a test: the only grader code that shares a
 * process with student code.  Built once per part (-DHARNESS_PART=PART_1,
 * PART_2, PART_3A, PART_3B, PART_4 or PART_5, below) and linked with that
 * part's student file; it calls no other part's function itself.
 *
 * Reads from stdin, one or more tests, each:
 *                     KIND N
 *                     [background r g b] [spheres M, then M lines cx cy cz R r g b]
 *                     [triangles M, then M lines ax ay az bx by bz cx cy cz]
 *                     N lines of inputs (numbers)
 * Writes to fd 3:     per test, one line of outputs (%a, hexfloat.h) per case, then
 *                     "end N".
 * Input that starts with the word "alone" (a test run alone, or a probe) has
 * each answer written as soon as it is made: what the code answered before
 * it crashed or hung reaches the grader, which shows the case that stopped
 * it.  A part's tests run together keep their answers in a buffer, written
 * at the end: the grader takes nothing but passes from that run.
 * Built with -DHARNESS_LOAD (Linux) it is a prebuilt runner instead, which
 * loads the student's file, built as a shared object, from its first
 * argument (harness_load.c); `runner --check OBJECT` only loads and checks
 * it, and writes "link-ok" or "link-error WHY" to fd 3.
 * It knows nothing of the expected answers: the parent judges.  Several
 * tests in one process are only a shortcut for the parent (grade.c): it
 * takes from such a run nothing but passes, and only when the process ran
 * every test to its end and exited cleanly; it runs any other test alone.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "raytracer.h"
#include "kit/scene.h"                  /* the guard sphere */
#include "harness_init.h"
#ifdef HARNESS_LOAD
#include "harness_load.h"
#endif

#include "hexfloat.h"

/* The parts, counted from 0 in the contract's order (contract.h), as the
 * grader's PART1 ... PART5 count them: HARNESS_PART is one of these. */
#define PART_1  0
#define PART_2  1
#define PART_3A 2
#define PART_3B 3
#define PART_4  4
#define PART_5  5

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static FILE *answers;
static bool alone;                      /* each answer written when made */

/* The whole of stdin, read before the first test, and where reading is:
 * the numbers are read with hexfloat_read and written with hexfloat_format,
 * as scanf and printf would read and write them, at a fraction of the cost. */
static char *input;
static const char *at;

/* Reads stdin into input; 0, or -1 out of memory or at a read error. */
static int read_input(void)
{
    size_t len = 0, cap = 1 << 16;
    input = malloc(cap);
    while (input) {
        len += fread(input + len, 1, cap - 1 - len, stdin);
        if (len < cap - 1)
            break;
        char *more = realloc(input, 2 * cap);
        if (!more)
            free(input);
        input = more;
        cap *= 2;
    }
    if (!input || ferror(stdin))
        return -1;
    input[len] = '\0';
    at = input;
    return 0;
}

static int is_space(char c)
{
    return c == ' ' || c == '\n' || c == '\t' || c == '\r';
}

static void skip_space(void)
{
    while (is_space(*at))
        at++;
}

/* The next word, if it is w; 0, or -1. */
static int word(const char *w)
{
    skip_space();
    size_t n = strlen(w);
    if (strncmp(at, w, n) != 0 || (at[n] && !is_space(at[n])))
        return -1;
    at += n;
    return 0;
}

/* The next word, up to size - 1 bytes; 0, or -1 at the end. */
static int next_word(char *buf, size_t size)
{
    skip_space();
    size_t n = 0;
    while (at[n] && !is_space(at[n]))
        n++;
    if (n == 0 || n >= size)
        return -1;
    memcpy(buf, at, n);
    buf[n] = '\0';
    at += n;
    return 0;
}

static int get_int(int *v)
{
    char *end;
    long x = strtol(at, &end, 10);
    if (end == at || x < INT_MIN || x > INT_MAX)
        return -1;
    *v = (int)x;
    at = end;
    return 0;
}

static void put(const double *v, int n)
{
    char line[6 * (HEXFLOAT_MAX + 1)];
    size_t len = 0;
    for (int k = 0; k < n; k++) {
        if (k)
            line[len++] = ' ';
        len += hexfloat_format(line + len, v[k]);
    }
    line[len++] = '\n';
    fwrite(line, 1, len, answers);
    if (alone)
        fflush(answers);
}

#if HARNESS_PART == PART_3A || HARNESS_PART == PART_4 || HARNESS_PART == PART_5
/* The answer of Parts 3a, 4 and 5: 1 and t for a hit, 0 and 0 for a miss. */
static void put_hit(bool hit, double t)
{
    double out[2] = { hit ? 1 : 0, hit ? t : 0 };
    put(out, 2);
}
#endif

static int get(double *v, int n)
{
    for (int k = 0; k < n; k++) {
        char *end;
        v[k] = hexfloat_read(at, &end);
        if (end == at)
            return -1;
        at = end;
    }
    return 0;
}

#if HARNESS_PART == PART_3B
static Scene scene;                     /* a color or image test's */

/* Reads the scene of a color or image test (KIND) into scene, in place of
 * the previous test's; a camera test has none.  0, or 3 on malformed
 * input. */
static int read_scene(const char *kind)
{
    free(scene.spheres);                /* the previous test's */
    scene.spheres = NULL;
    scene.nspheres = 0;
    if (strcmp(kind, "color") != 0 && strcmp(kind, "image") != 0)
        return 0;
    double bg[3];
    int m;
    if (word("background") || get(bg, 3) || word("spheres") || get_int(&m) || m < 0)
        return 3;
    scene.background = vec3(bg[0], bg[1], bg[2]);
    scene.spheres = calloc((size_t)m + 1, sizeof *scene.spheres);
    if (!scene.spheres)
        return 3;
    scene.nspheres = m;
    scene.spheres[m] = scene_guard_sphere();     /* past the last: scene.h */
    for (int s = 0; s < m; s++) {
        double v[7];
        if (get(v, 7))
            return 3;
        scene.spheres[s].center = vec3(v[0], v[1], v[2]);
        scene.spheres[s].radius = v[3];
        scene.spheres[s].color = vec3(v[4], v[5], v[6]);
    }
    return 0;
}
#endif

#if HARNESS_PART == PART_5
static Triangle *mesh;                  /* a mesh test's, or NULL */
static int nmesh;

/* Reads the triangles of a mesh test (KIND) into mesh, in place of the
 * previous test's; a triangle test has none.  0, or 3 on malformed input. */
static int read_mesh(const char *kind)
{
    nmesh = 0;
    free(mesh);                         /* the previous test's */
    mesh = NULL;
    if (strcmp(kind, "mesh") != 0)
        return 0;
    if (word("triangles") || get_int(&nmesh) || nmesh < 0)
        return 3;
    mesh = calloc((size_t)nmesh + 1, sizeof *mesh);
    for (int k = 0; k < nmesh; k++) {
        double v[9];
        if (!mesh || get(v, 9))
            return 3;
        mesh[k].a = vec3(v[0], v[1], v[2]);
        mesh[k].b = vec3(v[3], v[4], v[5]);
        mesh[k].c = vec3(v[6], v[7], v[8]);
        mesh[k].color = vec3(1, 1, 1);
    }
    return 0;
}
#endif

/* One case of a KIND test: reads its inputs, calls the part's function,
 * writes its answer.  0, or 3 on malformed input. */
static int one_case(const char *kind)
{
    (void)kind;                         /* Part 3b reads it */
    double in[15];
#if HARNESS_PART == PART_1
    if (get(in, 3))
        return 3;
    double out[2];
    image_plane_size(in[0], in[1], in[2], &out[0], &out[1]);
    put(out, 2);
#elif HARNESS_PART == PART_2
    if (get(in, 7))
        return 3;
    Vec3 p = pixel_coordinates((int)in[0], (int)in[1], (int)in[2], (int)in[3], in[4], in[5], in[6]);
    double out[3] = { p.x, p.y, p.z };
    put(out, 3);
#elif HARNESS_PART == PART_3A
    if (get(in, 10))
        return 3;
    Sphere s = { vec3(in[0], in[1], in[2]), in[3], vec3(1, 1, 1) };
    Ray r = { vec3(in[4], in[5], in[6]), vec3(in[7], in[8], in[9]) };
    double t = 0;
    bool hit = sphere_intersect(&s, &r, &t);
    put_hit(hit, t);
#elif HARNESS_PART == PART_3B
    double out[6];
    if (strcmp(kind, "camera") == 0) {
        if (get(in, 6))
            return 3;
        Ray r = camera_ray(vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]));
        out[0] = r.origin.x, out[1] = r.origin.y, out[2] = r.origin.z;
        out[3] = r.direction.x, out[4] = r.direction.y, out[5] = r.direction.z;
        put(out, 6);
    } else if (strcmp(kind, "color") == 0) {
        if (get(in, 6))
            return 3;
        Ray r = { vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]) };
        Vec3 col = ray_color(&scene, &r);
        out[0] = col.x, out[1] = col.y, out[2] = col.z;
        put(out, 3);
    } else {
        if (get(in, 3))
            return 3;
        Ray r = camera_ray(vec3(0, 0, 0), vec3(in[0], in[1], in[2]));
        Vec3 col = ray_color(&scene, &r);
        out[0] = col.x, out[1] = col.y, out[2] = col.z;
        put(out, 3);
    }
#elif HARNESS_PART == PART_4
    if (get(in, 12))
        return 3;
    Plane pl = { vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]), vec3(1, 1, 1) };
    Ray r = { vec3(in[6], in[7], in[8]), vec3(in[9], in[10], in[11]) };
    double t = 0;
    bool hit = plane_intersect(&pl, &r, &t);
    put_hit(hit, t);
#elif HARNESS_PART == PART_5
    bool hit = false;
    double t = 0;
    if (mesh) {
        /* The first hit over the mesh, as a renderer finds it. */
        if (get(in, 6))
            return 3;
        Ray r = { vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]) };
        for (int k = 0; k < nmesh; k++) {
            double tk = 0;
            if (triangle_intersect(&mesh[k], &r, &tk) && (!hit || tk < t)) {
                hit = true;
                t = tk;
            }
        }
    } else {
        if (get(in, 15))
            return 3;
        Triangle tr = { vec3(in[0], in[1], in[2]), vec3(in[3], in[4], in[5]),
                        vec3(in[6], in[7], in[8]), vec3(1, 1, 1) };
        Ray r = { vec3(in[9], in[10], in[11]), vec3(in[12], in[13], in[14]) };
        hit = triangle_intersect(&tr, &r, &t);
    }
    put_hit(hit, t);
#else
#error "HARNESS_PART must be PART_1, PART_2, PART_3A, PART_3B, PART_4 or PART_5"
#endif
    return 0;
}

/* One test: its KIND and N are read; reads the rest (Parts 3b and 5: a
 * scene or a mesh, then) N cases, writes their answers and "end N".
 * 0 on success, 3 on malformed input. */
static int one_test(const char *kind, int n)
{
#if HARNESS_PART == PART_3B
    if (read_scene(kind) != 0)
        return 3;
#elif HARNESS_PART == PART_5
    if (read_mesh(kind) != 0)
        return 3;
#endif
    for (int c = 0; c < n; c++)
        if (one_case(kind) != 0)
            return 3;
    fprintf(answers, "end %d\n", n);
    return 0;
}

int main(int argc, char **argv)
{
    char kind[16];
    int n, tests = 0;
    harness_init();
    answers = fdopen(3, "w");
    if (!answers)
        return 3;
#ifdef HARNESS_LOAD
    bool check = argc == 3 && strcmp(argv[1], "--check") == 0;
    if (argc != 2 && !check)
        return 3;
    char why[512];
#ifdef HARNESS_REFS
    bool refs = true;
#else
    bool refs = false;
#endif
    if (harness_load(HARNESS_PART, refs, argv[check ? 2 : 1], why, sizeof why) != 0) {
        fprintf(answers, "link-error %s\n", why);
        fflush(answers);
        return 4;
    }
    if (check) {
        fprintf(answers, "link-ok\n");
        return fflush(answers) == 0 ? 0 : 3;
    }
#else
    (void)argc, (void)argv;
#endif
    static char buf[1 << 16];
    setvbuf(answers, buf, _IOFBF, sizeof buf);
    if (read_input() != 0)
        return 3;
    alone = word("alone") == 0;
    while (next_word(kind, sizeof kind) == 0) {
        if (get_int(&n) || n < 0 || one_test(kind, n) != 0)
            return 3;
        tests++;
    }
    skip_space();
    if (tests == 0 || *at)
        return 3;
    return fflush(answers) == 0 ? 0 : 3;
}
