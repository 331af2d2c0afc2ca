/*
 * scene.c - reading a scene file (the format is described in scene.h).
 *
 * The text is read line by line.  Each line is cut at '#', split into
 * words at white space, and the first word names what the line gives.
 * Every number is checked as it is read, so a bad file stops at its first
 * bad line with a message naming the file, the line and what was expected.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "obj.h"
#include "textfile.h"

/* The keywords that may appear once, and where they were first seen. */
typedef struct {
    int image, fov, distance, background;    /* line numbers; 0 = not yet */
} SceneSeen;

/* The growing arrays of a scene being read, and its file's directory (for
 * the paths of meshes). */
typedef struct {
    int spheres, planes, triangles;          /* capacities */
    const char *dir;                         /* "" for the current directory */
} SceneBuild;

/* Reads words 1 .. n of the line as numbers into values[0 .. n-1], after
 * checking the line has exactly n of them (usage lists their names).
 * Returns 0, or -1 with a message. */
static int scene_numbers(const TextLine *ln, int n, const char *usage, double *values,
                         char *err, size_t errlen)
{
    int got = ln->nwords - 1;
    if (got != n)
        return text_error(err, errlen, ln->name, ln->line, "%s needs %d number%s: %s, got %d",
                          ln->words[0], n, n == 1 ? "" : "s", usage, got);
    for (int k = 0; k < n; k++)
        if (text_number(ln, k + 1, &values[k], err, errlen) < 0)
            return -1;
    return 0;
}

/* Checks that the three numbers at c, read from words first .. first + 2,
 * are a colour, each in [0, 1].  Returns 0, or -1 with a message naming the
 * first bad component. */
static int scene_check_color(const TextLine *ln, int first, const double *c,
                             char *err, size_t errlen)
{
    static const char *const names[3] = { "r", "g", "b" };
    for (int k = 0; k < 3; k++)
        if (!(c[k] >= 0 && c[k] <= 1))
            return text_error(err, errlen, ln->name, ln->line,
                              "%s colour %s must be in [0, 1], got %.40s",
                              ln->words[0], names[k], ln->words[first + k]);
    return 0;
}

/* Checks that a number read for the image size is a whole number of
 * pixels, 1 .. IMAGE_MAX_SIDE, and stores it in *side.
 * Returns 0, or -1 with a message quoting the word as written. */
static int scene_check_side(const TextLine *ln, int k, double value, const char *what,
                            int *side, char *err, size_t errlen)
{
    if (!(value >= 1 && value <= IMAGE_MAX_SIDE && value == floor(value)))
        return text_error(err, errlen, ln->name, ln->line,
                          "image %s must be a whole number from 1 to %d, got %.40s",
                          what, IMAGE_MAX_SIDE, ln->words[k]);
    *side = (int)value;
    return 0;
}

/* Records that keyword (first seen at *first, 0 if never) is on this line.
 * Returns 0, or -1 with a message when it was already given. */
static int scene_once(const TextLine *ln, int *first, char *err, size_t errlen)
{
    if (*first)
        return text_error(err, errlen, ln->name, ln->line, "%s given twice (first on line %d)",
                          ln->words[0], *first);
    *first = ln->line;
    return 0;
}

/* Appends the item (size bytes) to the array *items of *count items
 * (capacity *capacity), at most max in all; the one function serves
 * spheres, planes and triangles.  Returns 0, or -1 with a message naming
 * what when the limit is reached or memory runs out (the array then still
 * belongs to the scene). */
static int scene_add(void **items, int *count, int *capacity, const void *item, size_t size,
                     int max, const char *what, const TextLine *ln, char *err, size_t errlen)
{
    if (*count == max)
        return text_error(err, errlen, ln->name, ln->line, "too many %s: at most %d", what, max);
    if (*count == *capacity) {
        int grown = *capacity ? 2 * *capacity : 16;
        if (grown > max)
            grown = max;
        void *more = realloc(*items, (size_t)grown * size);
        if (!more)
            return text_error(err, errlen, ln->name, ln->line, "out of memory");
        *items = more;
        *capacity = grown;
    }
    memcpy((char *)*items + (size_t)*count * size, item, size);
    ++*count;
    return 0;
}

/* "mesh FILE s tx ty tz r g b": the OBJ file's triangles, read relative to
 * the scene file's directory.  Returns 0, or -1 with a message naming the
 * OBJ file and its line, then the scene's line that asked for it. */
static int scene_mesh(Scene *scene, SceneBuild *b, const TextLine *ln, char *err, size_t errlen)
{
    double v[7];
    int got = ln->nwords - 1;
    if (got != 8)
        return text_error(err, errlen, ln->name, ln->line,
                          "mesh needs a file and 7 numbers: FILE s tx ty tz r g b, got %d word%s",
                          got, got == 1 ? "" : "s");
    for (int k = 0; k < 7; k++)
        if (text_number(ln, k + 2, &v[k], err, errlen) < 0)
            return -1;
    if (!(v[0] > 0))
        return text_error(err, errlen, ln->name, ln->line,
                          "mesh scale s must be greater than 0, got %.40s",
                          ln->words[2]);
    if (scene_check_color(ln, 6, v + 4, err, errlen) < 0)
        return -1;
    const char *file = ln->words[1];
    size_t len = strlen(b->dir) + strlen(file) + 2;
    char *path = malloc(len);
    if (!path)
        return text_error(err, errlen, ln->name, ln->line, "out of memory");
    if (file[0] == '/' || !b->dir[0])
        snprintf(path, len, "%s", file);
    else
        snprintf(path, len, "%s/%s", b->dir, file);
    char inner[512];
    int status = obj_load(path, v[0], vec3(v[1], v[2], v[3]), vec3(v[4], v[5], v[6]),
                          &scene->triangles, &scene->ntriangles, &b->triangles, SCENE_MAX_TRIANGLES,
                          inner, sizeof inner);
    if (status < 0 && err && errlen > 0)         /* the OBJ's file and line first */
        snprintf(err, errlen, "%s (the mesh of %s:%d)", inner, ln->name, ln->line);
    free(path);
    return status;
}

/* Interprets one split, non-empty line into scene.
 * Returns 0, or -1 with a message. */
static int scene_line(Scene *scene, SceneSeen *seen, SceneBuild *b, const TextLine *ln,
                      char *err, size_t errlen)
{
    const char *key = ln->words[0];
    char quoted[TEXT_QUOTE_SIZE];
    double v[12];

    if (strcmp(key, "image") == 0) {
        if (scene_once(ln, &seen->image, err, errlen) < 0
            || scene_numbers(ln, 2, "nx ny", v, err, errlen) < 0
            || scene_check_side(ln, 1, v[0], "width nx", &scene->nx, err, errlen) < 0
            || scene_check_side(ln, 2, v[1], "height ny", &scene->ny, err, errlen) < 0)
            return -1;
    } else if (strcmp(key, "fov") == 0) {
        if (scene_once(ln, &seen->fov, err, errlen) < 0
            || scene_numbers(ln, 1, "degrees", v, err, errlen) < 0)
            return -1;
        if (!(v[0] > 0 && v[0] < 180))
            return text_error(err, errlen, ln->name, ln->line,
                              "fov must be between 0 and 180 degrees (both excluded), got %.40s",
                              ln->words[1]);
        scene->fov_degrees = v[0];
    } else if (strcmp(key, "distance") == 0) {
        if (scene_once(ln, &seen->distance, err, errlen) < 0
            || scene_numbers(ln, 1, "d", v, err, errlen) < 0)
            return -1;
        if (!(v[0] > 0))
            return text_error(err, errlen, ln->name, ln->line,
                              "distance d must be greater than 0, got %.40s", ln->words[1]);
        scene->d = v[0];
    } else if (strcmp(key, "background") == 0) {
        if (scene_once(ln, &seen->background, err, errlen) < 0
            || scene_numbers(ln, 3, "r g b", v, err, errlen) < 0
            || scene_check_color(ln, 1, v, err, errlen) < 0)
            return -1;
        scene->background = vec3(v[0], v[1], v[2]);
    } else if (strcmp(key, "sphere") == 0) {
        if (scene_numbers(ln, 7, "cx cy cz R r g b", v, err, errlen) < 0)
            return -1;
        if (!(v[3] > 0))
            return text_error(err, errlen, ln->name, ln->line,
                              "sphere radius R must be greater than 0, got %.40s", ln->words[4]);
        if (scene_check_color(ln, 5, v + 4, err, errlen) < 0)
            return -1;
        Sphere sphere = { vec3(v[0], v[1], v[2]), v[3], vec3(v[4], v[5], v[6]) };
        void *items = scene->spheres;
        int status = scene_add(&items, &scene->nspheres, &b->spheres, &sphere, sizeof sphere,
                               SCENE_MAX_SPHERES, "spheres", ln, err, errlen);
        scene->spheres = items;
        return status;
    } else if (strcmp(key, "plane") == 0) {
        if (scene_numbers(ln, 9, "px py pz nx ny nz r g b", v, err, errlen) < 0
            || scene_check_color(ln, 7, v + 6, err, errlen) < 0)
            return -1;
        if (v[3] == 0 && v[4] == 0 && v[5] == 0)
            return text_error(err, errlen, ln->name, ln->line, "plane normal must not be zero");
        Plane plane = { vec3(v[0], v[1], v[2]), vec3(v[3], v[4], v[5]), vec3(v[6], v[7], v[8]) };
        void *items = scene->planes;
        int status = scene_add(&items, &scene->nplanes, &b->planes, &plane, sizeof plane,
                               SCENE_MAX_PLANES, "planes", ln, err, errlen);
        scene->planes = items;
        return status;
    } else if (strcmp(key, "triangle") == 0) {
        if (scene_numbers(ln, 12, "ax ay az bx by bz cx cy cz r g b", v, err, errlen) < 0
            || scene_check_color(ln, 10, v + 9, err, errlen) < 0)
            return -1;
        Triangle tri = { vec3(v[0], v[1], v[2]), vec3(v[3], v[4], v[5]), vec3(v[6], v[7], v[8]),
                         vec3(v[9], v[10], v[11]) };
        Vec3 n = vec3_cross(vec3_sub(tri.b, tri.a), vec3_sub(tri.c, tri.a));
        if (n.x == 0 && n.y == 0 && n.z == 0)
            return text_error(err, errlen, ln->name, ln->line,
                              "triangle has no area (two vertices are equal, or all three on a "
                              "line)");
        void *items = scene->triangles;
        int status = scene_add(&items, &scene->ntriangles, &b->triangles, &tri, sizeof tri,
                               SCENE_MAX_TRIANGLES, "triangles", ln, err, errlen);
        scene->triangles = items;
        return status;
    } else if (strcmp(key, "mesh") == 0) {
        return scene_mesh(scene, b, ln, err, errlen);
    } else {
        return text_error(err, errlen, ln->name, ln->line,
                          "unknown keyword '%s' (expected image, fov, distance, background, "
                          "sphere, plane, triangle or mesh)", text_quote(key, quoted));
    }
    return 0;
}

/* The directory part of path ("" when it has none), in a fresh string. */
static char *scene_dir(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (slash && n == 0)
        n = 1;                                    /* "/x.scene": the root */
    char *dir = malloc(n + 1);
    if (dir) {
        memcpy(dir, path, n);
        dir[n] = '\0';
    }
    return dir;
}

/* Parses text into scene (see scene.h).  Returns 0, or -1 with a message;
 * on failure the scene holds nothing that needs freeing. */
int scene_parse(Scene *scene, const char *text, const char *name, char *err, size_t errlen)
{
    Scene empty = { 0 };
    *scene = empty;
    scene->d = 1;                                 /* the defaults */
    scene->eye = vec3(0, 0, 0);
    scene->background = vec3(0, 0, 0);
    if (err && errlen > 0)
        err[0] = '\0';
    if (!name)
        name = "(scene)";

    SceneSeen seen = { 0, 0, 0, 0 };
    SceneBuild b = { 0, 0, 0, NULL };
    char *dir = scene_dir(name);
    if (!dir)
        return text_error(err, errlen, name, 0, "out of memory");
    b.dir = dir;
    char buf[TEXT_MAX_LINE + 1];
    TextLine ln;
    ln.name = name;
    ln.line = 0;
    const char *p = text ? text : "";
    int got;
    while ((got = text_next_line(&p, buf, &ln, err, errlen)) > 0)
        if (ln.nwords > 0 && scene_line(scene, &seen, &b, &ln, err, errlen) < 0)
            goto fail;
    if (got < 0)
        goto fail;
    if (!seen.image) {
        text_error(err, errlen, name, 0, "no image line: 'image nx ny' is required");
        goto fail;
    }
    if (!seen.fov) {
        text_error(err, errlen, name, 0, "no fov line: 'fov degrees' is required");
        goto fail;
    }
    if (scene->nspheres == b.spheres) {           /* room for the guard (scene.h) */
        Sphere *more = realloc(scene->spheres, ((size_t)scene->nspheres + 1) * sizeof *more);
        if (!more) {
            text_error(err, errlen, name, 0, "out of memory");
            goto fail;
        }
        scene->spheres = more;
    }
    scene->spheres[scene->nspheres] = scene_guard_sphere();
    free(dir);
    return 0;

fail:
    free(dir);
    scene_free(scene);
    return -1;
}

/* Loads the scene file at path (see scene.h).  Returns 0, or -1 with a
 * message "path: reason" or "path:line: reason"; on failure the scene holds
 * nothing that needs freeing. */
int scene_load(Scene *scene, const char *path, char *err, size_t errlen)
{
    Scene empty = { 0 };
    *scene = empty;
    char *text;
    if (text_read_file(path, &text, err, errlen) < 0)
        return -1;
    int status = scene_parse(scene, text, path, err, errlen);
    free(text);
    return status;
}

/* Frees the spheres, planes and triangles and leaves an empty scene; safe
 * to call twice. */
void scene_free(Scene *scene)
{
    free(scene->spheres);
    free(scene->planes);
    free(scene->triangles);
    scene->spheres = NULL;
    scene->planes = NULL;
    scene->triangles = NULL;
    scene->nspheres = scene->nplanes = scene->ntriangles = 0;
}
