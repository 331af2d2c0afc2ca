/*
 * obj.c - reading the triangles of a Wavefront OBJ file (see obj.h).
 *
 * The file is read whole, then line by line like a scene (textfile.h).
 * Vertices are kept in a growing array, already transformed; each face is
 * split into the triangles (v0, v[k], v[k + 1]) of a fan.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "obj.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "textfile.h"

#define OBJ_MAX_VERTICES 4000000

/* The statements of the format that carry nothing a flat-coloured
 * triangle needs. */
static int obj_ignored(const char *key)
{
    static const char *const ignored[] = { "vt", "vn", "vp", "o", "g", "s", "usemtl", "mtllib", "l" };
    for (size_t k = 0; k < sizeof ignored / sizeof ignored[0]; k++)
        if (strcmp(key, ignored[k]) == 0)
            return 1;
    return 0;
}

/* Reads face index word k of ln ("i", "i/vt", "i//vn" or "i/vt/vn") into
 * a 0-based vertex index, nverts vertices having been read.  Returns 0, or
 * -1 with a message. */
static int obj_index(const TextLine *ln, int k, int nverts, int *index, char *err, size_t errlen)
{
    const char *word = ln->words[k];
    char quoted[TEXT_QUOTE_SIZE], *end;
    errno = 0;
    long v = strtol(word, &end, 10);
    if (end == word || (*end != '\0' && *end != '/') || errno == ERANGE)
        return text_error(err, errlen, ln->name, ln->line, "f: '%s' is not a vertex index",
                          text_quote(word, quoted));
    long i = v > 0 ? v - 1 : v + nverts;          /* negative: counted back from the last */
    if (v == 0 || i < 0 || i >= nverts)
        return text_error(err, errlen, ln->name, ln->line,
                          "f: vertex %ld does not exist (%d vertices so far; indices start at 1)",
                          v, nverts);
    *index = (int)i;
    return 0;
}

/* Appends one triangle.  Returns 0, or -1 with a message. */
static int obj_push(const TextLine *ln, Triangle tri, Triangle **tris, int *ntris, int *cap, int max,
                    char *err, size_t errlen)
{
    if (*ntris >= max)
        return text_error(err, errlen, ln->name, ln->line,
                          "too many triangles: at most %d in a scene", max);
    if (*ntris == *cap) {
        int grown = *cap ? 2 * *cap : 64;
        if (grown > max)
            grown = max;
        Triangle *more = realloc(*tris, (size_t)grown * sizeof *more);
        if (!more)
            return text_error(err, errlen, ln->name, ln->line, "out of memory");
        *tris = more;
        *cap = grown;
    }
    (*tris)[(*ntris)++] = tri;
    return 0;
}

/* Interprets one split, non-empty line.  Returns 0, or -1 with a message. */
static int obj_line(const TextLine *ln, double s, Vec3 t, Vec3 color, Vec3 **verts, int *nverts,
                    int *vcap, Triangle **tris, int *ntris, int *cap, int max, char *err, size_t errlen)
{
    const char *key = ln->words[0];
    char quoted[TEXT_QUOTE_SIZE];
    if (strcmp(key, "v") == 0) {
        int got = ln->nwords - 1;
        double v[4];
        if (got != 3 && got != 4)
            return text_error(err, errlen, ln->name, ln->line,
                              "v needs 3 numbers: x y z, got %d", got);
        for (int k = 0; k < got; k++)
            if (text_number(ln, k + 1, &v[k], err, errlen) < 0)
                return -1;
        if (*nverts == OBJ_MAX_VERTICES)
            return text_error(err, errlen, ln->name, ln->line,
                              "too many vertices: at most %d", OBJ_MAX_VERTICES);
        if (*nverts == *vcap) {
            int grown = *vcap ? 2 * *vcap : 64;
            Vec3 *more = realloc(*verts, (size_t)grown * sizeof *more);
            if (!more)
                return text_error(err, errlen, ln->name, ln->line, "out of memory");
            *verts = more;
            *vcap = grown;
        }
        /* once, here: every triangle that uses this vertex gets these bits */
        (*verts)[(*nverts)++] = vec3_add(vec3_scale(vec3(v[0], v[1], v[2]), s), t);
    } else if (strcmp(key, "f") == 0) {
        if (ln->nwords - 1 < 3)
            return text_error(err, errlen, ln->name, ln->line,
                              "f needs at least 3 vertices, got %d", ln->nwords - 1);
        if (ln->nwords > TEXT_MAX_WORDS)
            return text_error(err, errlen, ln->name, ln->line, "f has %d vertices: at most %d",
                              ln->nwords - 1, TEXT_MAX_WORDS - 1);
        int first, prev, next;
        if (obj_index(ln, 1, *nverts, &first, err, errlen) < 0
            || obj_index(ln, 2, *nverts, &prev, err, errlen) < 0)
            return -1;
        for (int k = 3; k < ln->nwords; k++) {
            if (obj_index(ln, k, *nverts, &next, err, errlen) < 0)
                return -1;
            Triangle tri = { (*verts)[first], (*verts)[prev], (*verts)[next], color };
            if (obj_push(ln, tri, tris, ntris, cap, max, err, errlen) < 0)
                return -1;
            prev = next;
        }
    } else if (!obj_ignored(key)) {
        return text_error(err, errlen, ln->name, ln->line,
                          "unknown statement '%s' (this kit reads v and f, and ignores vt, vn, vp, "
                          "o, g, s, usemtl, mtllib and l)", text_quote(key, quoted));
    }
    return 0;
}

int obj_load(const char *path, double s, Vec3 t, Vec3 color, Triangle **tris, int *ntris,
             int *cap, int max, char *err, size_t errlen)
{
    char *text;
    if (text_read_file(path, &text, err, errlen) < 0)
        return -1;
    Vec3 *verts = NULL;
    int nverts = 0, vcap = 0, got, status = 0, before = *ntris;
    char buf[TEXT_MAX_LINE + 1];
    TextLine ln;
    ln.name = path;
    ln.line = 0;
    const char *p = text;
    while ((got = text_next_line(&p, buf, &ln, err, errlen)) > 0)
        if (ln.nwords > 0 && obj_line(&ln, s, t, color, &verts, &nverts, &vcap, tris, ntris, cap,
                                      max, err, errlen) < 0) {
            status = -1;
            break;
        }
    if (got < 0)
        status = -1;
    if (status == 0 && *ntris == before) {
        text_error(err, errlen, path, 0, "no faces: an OBJ mesh needs 'f' lines");
        status = -1;
    }
    free(verts);
    free(text);
    return status;
}
