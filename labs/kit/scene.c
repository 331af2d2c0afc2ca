/*
 * scene.c - reading a scene file (the format is described in scene.h).
 *
 * The text is read line by line.  Each line is cut at '#', split into
 * words at white space, and the first word names what the line gives.
 * Every number is checked as it is read, so a bad file stops at its first
 * bad line with a message naming the file, the line and what was expected.
 */
#define _POSIX_C_SOURCE 200809L
#include "scene.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "image.h"

#define SCENE_MAX_LINE   4096                 /* characters, without the newline */
#define SCENE_MAX_WORDS  8                    /* the most a line needs: sphere's */
#define SCENE_MAX_BYTES  (64L * 1024 * 1024)  /* a larger file is not a scene    */

/* What one line holds once split: its keyword and its numbers. */
typedef struct {
    const char *name;              /* the file's name, for messages */
    int line;                      /* 1-based line number           */
    char *words[SCENE_MAX_WORDS];  /* the first words of the line  */
    int nwords;                    /* all of them, the keyword too  */
} SceneLine;

/* The keywords that may appear once, and where they were first seen. */
typedef struct {
    int image, fov, distance, background;    /* line numbers; 0 = not yet */
} SceneSeen;

/* Writes "name:line: message" (or "name: message" when line is 0) into err.
 * Never fails; a NULL err or errlen 0 writes nothing. */
static void scene_error(char *err, size_t errlen, const char *name, int line,
                        const char *fmt, ...) __attribute__((format(printf, 5, 6)));
static void scene_error(char *err, size_t errlen, const char *name, int line,
                        const char *fmt, ...)
{
    if (!err || errlen == 0)
        return;
    int used = line > 0 ? snprintf(err, errlen, "%s:%d: ", name, line)
                        : snprintf(err, errlen, "%s: ", name);
    if (used < 0 || (size_t)used >= errlen)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + used, errlen - (size_t)used, fmt, ap);
    va_end(ap);
}

/* Copies word into buf (SCENE_QUOTE_SIZE bytes) for a message: at most 40
 * characters, "..." after a cut, and '?' for any byte that is not printable
 * ASCII, so a binary file gives a readable message.  Returns buf. */
#define SCENE_QUOTE_SIZE 44
static const char *scene_quote(const char *word, char *buf)
{
    size_t n = 0;
    for (; word[n] && n < SCENE_QUOTE_SIZE - 4; n++)
        buf[n] = word[n] > ' ' && word[n] < 127 ? word[n] : '?';
    strcpy(buf + n, word[n] ? "..." : "");
    return buf;
}

/* True for the characters that separate words (a '\r' of a CRLF file too). */
static int scene_is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* Splits buf (one line, NUL-terminated, modified in place) into words,
 * dropping everything from '#' on.  Stores the first SCENE_MAX_WORDS in
 * words and returns how many there are in all, so that a line with too
 * many is reported with its count. */
static int scene_split(char *buf, char **words)
{
    char *hash = strchr(buf, '#');
    if (hash)
        *hash = '\0';
    int n = 0;
    char *p = buf;
    for (;;) {
        while (*p && scene_is_space(*p))
            p++;
        if (!*p)
            return n;
        if (n < SCENE_MAX_WORDS)
            words[n] = p;
        n++;
        while (*p && !scene_is_space(*p))
            p++;
        if (*p)
            *p++ = '\0';
    }
}

/* Reads word k of the line (k >= 1) as a finite number into *value.
 * Returns 0, or -1 with a message when it is not a number, has trailing
 * characters, is NaN or infinite, or overflows. */
static int scene_number(const SceneLine *ln, int k, double *value, char *err, size_t errlen)
{
    const char *word = ln->words[k];
    char quoted[SCENE_QUOTE_SIZE], *end;
    errno = 0;
    double v = strtod(word, &end);
    if (end == word || *end != '\0') {
        scene_error(err, errlen, ln->name, ln->line, "%s: '%s' is not a number",
                    ln->words[0], scene_quote(word, quoted));
        return -1;
    }
    if (isnan(v)) {
        scene_error(err, errlen, ln->name, ln->line, "%s: '%s' is not a number (NaN is refused)",
                    ln->words[0], scene_quote(word, quoted));
        return -1;
    }
    if (isinf(v)) {
        scene_error(err, errlen, ln->name, ln->line, "%s: '%s' is %s (numbers must be finite)",
                    ln->words[0], scene_quote(word, quoted),
                    errno == ERANGE ? "out of range" : "infinite");
        return -1;
    }
    *value = v;
    return 0;
}

/* Reads words 1 .. n of the line as numbers into values[0 .. n-1], after
 * checking the line has exactly n of them (usage lists their names).
 * Returns 0, or -1 with a message. */
static int scene_numbers(const SceneLine *ln, int n, const char *usage, double *values,
                         char *err, size_t errlen)
{
    int got = ln->nwords - 1;
    if (got != n) {
        scene_error(err, errlen, ln->name, ln->line, "%s needs %d number%s: %s, got %d",
                    ln->words[0], n, n == 1 ? "" : "s", usage, got);
        return -1;
    }
    for (int k = 0; k < n; k++)
        if (scene_number(ln, k + 1, &values[k], err, errlen) < 0)
            return -1;
    return 0;
}

/* Checks that the three numbers at c, read from words first .. first + 2,
 * are a colour, each in [0, 1].  Returns 0, or -1 with a message naming the
 * first bad component. */
static int scene_check_color(const SceneLine *ln, int first, const double *c,
                             char *err, size_t errlen)
{
    static const char *const names[3] = { "r", "g", "b" };
    for (int k = 0; k < 3; k++) {
        if (!(c[k] >= 0 && c[k] <= 1)) {
            scene_error(err, errlen, ln->name, ln->line, "%s colour %s must be in [0, 1], got %.40s",
                        ln->words[0], names[k], ln->words[first + k]);
            return -1;
        }
    }
    return 0;
}

/* Checks that a number read for the image size is a whole number of
 * pixels, 1 .. IMAGE_MAX_SIDE, and stores it in *side.
 * Returns 0, or -1 with a message quoting the word as written. */
static int scene_check_side(const SceneLine *ln, int k, double value, const char *what,
                            int *side, char *err, size_t errlen)
{
    if (!(value >= 1 && value <= IMAGE_MAX_SIDE && value == floor(value))) {
        scene_error(err, errlen, ln->name, ln->line,
                    "image %s must be a whole number from 1 to %d, got %.40s",
                    what, IMAGE_MAX_SIDE, ln->words[k]);
        return -1;
    }
    *side = (int)value;
    return 0;
}

/* Records that keyword (first seen at *first, 0 if never) is on this line.
 * Returns 0, or -1 with a message when it was already given. */
static int scene_once(const SceneLine *ln, int *first, char *err, size_t errlen)
{
    if (*first) {
        scene_error(err, errlen, ln->name, ln->line, "%s given twice (first on line %d)",
                    ln->words[0], *first);
        return -1;
    }
    *first = ln->line;
    return 0;
}

/* Appends a sphere to scene->spheres, growing the array by doubling.
 * Returns 0, or -1 with a message when there are already SCENE_MAX_SPHERES
 * or memory runs out (the array then still belongs to the scene). */
static int scene_add_sphere(Scene *scene, int *capacity, const Sphere *sphere,
                            const SceneLine *ln, char *err, size_t errlen)
{
    if (scene->nspheres == SCENE_MAX_SPHERES) {
        scene_error(err, errlen, ln->name, ln->line, "too many spheres: at most %d",
                    SCENE_MAX_SPHERES);
        return -1;
    }
    if (scene->nspheres == *capacity) {
        int grown = *capacity ? 2 * *capacity : 16;
        if (grown > SCENE_MAX_SPHERES)
            grown = SCENE_MAX_SPHERES;
        Sphere *more = realloc(scene->spheres, (size_t)grown * sizeof *more);
        if (!more) {
            scene_error(err, errlen, ln->name, ln->line, "out of memory");
            return -1;
        }
        scene->spheres = more;
        *capacity = grown;
    }
    scene->spheres[scene->nspheres++] = *sphere;
    return 0;
}

/* Interprets one split, non-empty line into scene.
 * Returns 0, or -1 with a message. */
static int scene_line(Scene *scene, SceneSeen *seen, int *capacity, const SceneLine *ln,
                      char *err, size_t errlen)
{
    const char *key = ln->words[0];
    char quoted[SCENE_QUOTE_SIZE];
    double v[7];

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
        if (!(v[0] > 0 && v[0] < 180)) {
            scene_error(err, errlen, ln->name, ln->line,
                        "fov must be between 0 and 180 degrees (both excluded), got %.40s",
                        ln->words[1]);
            return -1;
        }
        scene->fov_degrees = v[0];
    } else if (strcmp(key, "distance") == 0) {
        if (scene_once(ln, &seen->distance, err, errlen) < 0
            || scene_numbers(ln, 1, "d", v, err, errlen) < 0)
            return -1;
        if (!(v[0] > 0)) {
            scene_error(err, errlen, ln->name, ln->line,
                        "distance d must be greater than 0, got %.40s", ln->words[1]);
            return -1;
        }
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
        if (!(v[3] > 0)) {
            scene_error(err, errlen, ln->name, ln->line,
                        "sphere radius R must be greater than 0, got %.40s", ln->words[4]);
            return -1;
        }
        if (scene_check_color(ln, 5, v + 4, err, errlen) < 0)
            return -1;
        Sphere sphere = { vec3(v[0], v[1], v[2]), v[3], vec3(v[4], v[5], v[6]) };
        if (scene_add_sphere(scene, capacity, &sphere, ln, err, errlen) < 0)
            return -1;
    } else {
        scene_error(err, errlen, ln->name, ln->line,
                    "unknown keyword '%s' (expected image, fov, distance, background or sphere)",
                    scene_quote(key, quoted));
        return -1;
    }
    return 0;
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
    int capacity = 0;
    char buf[SCENE_MAX_LINE + 1];
    SceneLine ln;
    ln.name = name;
    ln.line = 0;
    const char *p = text ? text : "";
    while (*p) {
        ln.line++;
        size_t len = strcspn(p, "\n");
        if (len > SCENE_MAX_LINE) {
            scene_error(err, errlen, name, ln.line, "line is longer than %d characters",
                        SCENE_MAX_LINE);
            goto fail;
        }
        memcpy(buf, p, len);
        buf[len] = '\0';
        p += len;
        if (*p == '\n')
            p++;
        ln.nwords = scene_split(buf, ln.words);
        if (ln.nwords > 0 && scene_line(scene, &seen, &capacity, &ln, err, errlen) < 0)
            goto fail;
    }
    if (!seen.image) {
        scene_error(err, errlen, name, 0, "no image line: 'image nx ny' is required");
        goto fail;
    }
    if (!seen.fov) {
        scene_error(err, errlen, name, 0, "no fov line: 'fov degrees' is required");
        goto fail;
    }
    return 0;

fail:
    scene_free(scene);
    return -1;
}

/* Reads the whole of f into a fresh NUL-terminated buffer stored in *text.
 * Returns 0, or -1 with a message (read error, file too large, NUL byte,
 * out of memory); *text is then NULL. */
static int scene_read_all(FILE *f, const char *path, char **text, char *err, size_t errlen)
{
    size_t size = 0, capacity = 4096;
    char *buf = malloc(capacity);
    *text = NULL;
    if (!buf) {
        scene_error(err, errlen, path, 0, "out of memory");
        return -1;
    }
    for (;;) {
        if (size + 1 == capacity) {
            if (capacity >= (size_t)SCENE_MAX_BYTES) {
                scene_error(err, errlen, path, 0, "larger than %ld MiB: not a scene file",
                            SCENE_MAX_BYTES / (1024 * 1024));
                free(buf);
                return -1;
            }
            char *more = realloc(buf, 2 * capacity);
            if (!more) {
                scene_error(err, errlen, path, 0, "out of memory");
                free(buf);
                return -1;
            }
            buf = more;
            capacity *= 2;
        }
        size_t got = fread(buf + size, 1, capacity - 1 - size, f);
        size += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        scene_error(err, errlen, path, 0, "%s", strerror(errno ? errno : EIO));
        free(buf);
        return -1;
    }
    buf[size] = '\0';
    const char *nul = memchr(buf, '\0', size);
    if (nul) {
        int line = 1;
        for (const char *q = buf; q < nul; q++)
            line += *q == '\n';
        scene_error(err, errlen, path, line, "contains a NUL byte: not a text file");
        free(buf);
        return -1;
    }
    *text = buf;
    return 0;
}

/* Loads the scene file at path (see scene.h).  Returns 0, or -1 with a
 * message "path: reason" or "path:line: reason"; on failure the scene holds
 * nothing that needs freeing. */
int scene_load(Scene *scene, const char *path, char *err, size_t errlen)
{
    Scene empty = { 0 };
    *scene = empty;
    FILE *f = fopen(path, "rb");
    if (!f) {
        scene_error(err, errlen, path, 0, "%s", strerror(errno));
        return -1;
    }
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        scene_error(err, errlen, path, 0, "%s", strerror(EISDIR));
        fclose(f);
        return -1;
    }
    errno = 0;
    char *text;
    int status = scene_read_all(f, path, &text, err, errlen);
    fclose(f);
    if (status < 0)
        return -1;
    status = scene_parse(scene, text, path, err, errlen);
    free(text);
    return status;
}

/* Frees the spheres and leaves an empty scene; safe to call twice. */
void scene_free(Scene *scene)
{
    free(scene->spheres);
    scene->spheres = NULL;
    scene->nspheres = 0;
}
