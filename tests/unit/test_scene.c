/* The scene reader of labs/kit/scene.c: good scenes give the right values,
 * every kind of bad scene gives -1 and a message saying where and what. */
#include "check.h"            /* first: it sets the POSIX feature level */
#include <errno.h>
#include "../../labs/kit/scene.h"
#include "../../labs/kit/image.h"

/* A bad scene, the "name:line:" its message must start with and a word it
 * must contain. */
typedef struct {
    const char *text;
    const char *where;
    const char *word;
} BadScene;

#define GOOD_HEAD "image 64 48\nfov 60\n"
#define ONE_SPHERE "sphere 0 0 -5 1 1 0 0\n"

static const BadScene bad_scenes[] = {
    /* malformed lines */
    { GOOD_HEAD "sphere 0 0 -5 1 1 0\n", "t.scene:3: ", "sphere needs 7 numbers: cx cy cz R r g b, got 6" },
    { GOOD_HEAD "sphere 0 0 -5 1 1 0 0 1\n", "t.scene:3: ", "got 8" },
    { GOOD_HEAD "sphere\n", "t.scene:3: ", "got 0" },
    { GOOD_HEAD "sphere 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20\n", "t.scene:3: ", "got 20" },
    { "image 64\nfov 60\n", "t.scene:1: ", "image needs 2 numbers: nx ny, got 1" },
    { "image 64 48\nfov\n", "t.scene:2: ", "fov needs 1 number: degrees, got 0" },
    { "image 64 48\nfov 60 70\n", "t.scene:2: ", "got 2" },
    { GOOD_HEAD "distance\n", "t.scene:3: ", "distance needs 1 number" },
    { GOOD_HEAD "background 0 0\n", "t.scene:3: ", "background needs 3 numbers: r g b, got 2" },
    /* unknown keywords */
    { GOOD_HEAD "spere 0 0 -5 1 1 0 0\n", "t.scene:3: ", "unknown keyword 'spere'" },
    { GOOD_HEAD "Sphere 0 0 -5 1 1 0 0\n", "t.scene:3: ", "unknown keyword" },
    { GOOD_HEAD "0 0 -5 1 1 0 0\n", "t.scene:3: ", "unknown keyword '0'" },
    { "x 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20\n", "t.scene:1: ", "unknown keyword 'x'" },
    /* a binary file: refused on its first line, the bytes shown as '?' */
    { "\x89PNG\r\n\x1A\n", "t.scene:1: ", "unknown keyword '?PNG'" },
    /* a byte-order mark anywhere but first is not text (test_defaults_crlf_and_edges) */
    { "image 2 3\n\xEF\xBB\xBF" "fov 60\n", "t.scene:2: ", "unknown keyword" },
    /* not numbers, trailing garbage */
    { GOOD_HEAD "sphere 0 0 -5 1 1 0 x\n", "t.scene:3: ", "'x' is not a number" },
    { GOOD_HEAD "sphere 0 0 -5 1.5x 1 0 0\n", "t.scene:3: ", "'1.5x' is not a number" },
    { GOOD_HEAD "sphere 0 0 -5 1 1,0 0 0\n", "t.scene:3: ", "'1,0' is not a number" },
    { "image 64 48\nfov 60deg\n", "t.scene:2: ", "'60deg' is not a number" },
    { "image 64 48\nfov 6O\n", "t.scene:2: ", "not a number" },
    /* NaN, infinity, overflow */
    { GOOD_HEAD "sphere nan 0 -5 1 1 0 0\n", "t.scene:3: ", "'nan' is not a number" },
    { GOOD_HEAD "sphere 0 NAN(123) -5 1 1 0 0\n", "t.scene:3: ", "NaN" },
    { GOOD_HEAD "sphere 0 0 -inf 1 1 0 0\n", "t.scene:3: ", "'-inf' is infinite" },
    { GOOD_HEAD "sphere 0 0 -5 infinity 1 0 0\n", "t.scene:3: ", "infinite" },
    { GOOD_HEAD "sphere 0 0 -1e999 1 1 0 0\n", "t.scene:3: ", "'-1e999' is out of range" },
    { "image 64 48\nfov 1e999\n", "t.scene:2: ", "out of range" },
    { GOOD_HEAD "distance inf\n", "t.scene:3: ", "infinite" },
    /* field of view outside (0, 180) */
    { "image 64 48\nfov 0\n", "t.scene:2: ", "fov must be between 0 and 180" },
    { "image 64 48\nfov 180\n", "t.scene:2: ", "got 180" },
    { "image 64 48\nfov -30\n", "t.scene:2: ", "fov must be" },
    { "image 64 48\nfov 360\n", "t.scene:2: ", "fov must be" },
    /* distance <= 0 */
    { GOOD_HEAD "distance 0\n", "t.scene:3: ", "distance d must be greater than 0, got 0" },
    { GOOD_HEAD "distance -1\n", "t.scene:3: ", "distance d must be greater than 0" },
    /* radius <= 0 */
    { GOOD_HEAD "sphere 0 0 -5 0 1 0 0\n", "t.scene:3: ", "radius R must be greater than 0, got 0" },
    { GOOD_HEAD "sphere 0 0 -5 -1 1 0 0\n", "t.scene:3: ", "radius" },
    { GOOD_HEAD "sphere 0 0 -5 -0 1 0 0\n", "t.scene:3: ", "radius" },
    /* colours outside [0, 1] */
    { GOOD_HEAD "sphere 0 0 -5 1 1.5 0 0\n", "t.scene:3: ", "sphere colour r must be in [0, 1], got 1.5" },
    { GOOD_HEAD "sphere 0 0 -5 1 1 -0.1 0\n", "t.scene:3: ", "colour g" },
    { GOOD_HEAD "sphere 0 0 -5 1 1 0 255\n", "t.scene:3: ", "colour b" },
    { GOOD_HEAD "background 0.5 0.5 2\n", "t.scene:3: ", "background colour b must be in [0, 1]" },
    /* image sizes */
    { "image 0 48\nfov 60\n", "t.scene:1: ", "image width nx must be a whole number from 1 to 16384, got 0" },
    { "image 64 0\nfov 60\n", "t.scene:1: ", "image height ny" },
    { "image 16385 48\nfov 60\n", "t.scene:1: ", "got 16385" },
    { "image 64 99999\nfov 60\n", "t.scene:1: ", "height" },
    { "image 640.5 480\nfov 60\n", "t.scene:1: ", "whole number" },
    { "image -640 480\nfov 60\n", "t.scene:1: ", "whole number" },
    { "image 4294967360 480\nfov 60\n", "t.scene:1: ", "whole number" },
    { "image 1e300 480\nfov 60\n", "t.scene:1: ", "whole number" },
    /* duplicated keywords */
    { "image 64 48\nfov 60\nimage 32 32\n", "t.scene:3: ", "image given twice (first on line 1)" },
    { "image 64 48\nfov 60\nfov 30\n", "t.scene:3: ", "fov given twice (first on line 2)" },
    { GOOD_HEAD "distance 1\ndistance 2\n", "t.scene:4: ", "distance given twice" },
    { GOOD_HEAD "background 0 0 0\n\nbackground 1 1 1\n", "t.scene:5: ", "background given twice" },
    /* missing image or fov */
    { "fov 60\nsphere 0 0 -5 1 1 0 0\n", "t.scene: ", "no image line" },
    { "image 64 48\nsphere 0 0 -5 1 1 0 0\n", "t.scene: ", "no fov line" },
    { "", "t.scene: ", "no image line" },
    { "# only a comment\n\n", "t.scene: ", "no image line" },
    /* words that are not separated by white space */
    { "image 64 48 fov 60\n", "t.scene:1: ", "got 4" },
    /* planes: counts, a zero normal, colours, NaN */
    { GOOD_HEAD "plane 0 -1 0 0 1 0 1 1\n", "t.scene:3: ", "plane needs 9 numbers: px py pz nx ny nz r g b, got 8" },
    { GOOD_HEAD "plane 0 -1 0 0 0 0 1 1 1\n", "t.scene:3: ", "plane normal must not be zero" },
    { GOOD_HEAD "plane 0 -1 0 0 -0 0 1 1 1\n", "t.scene:3: ", "plane normal must not be zero" },
    { GOOD_HEAD "plane 0 -1 0 0 1 0 1 1 2\n", "t.scene:3: ", "plane colour b must be in [0, 1], got 2" },
    { GOOD_HEAD "plane 0 nan 0 0 1 0 1 1 1\n", "t.scene:3: ", "NaN" },
    /* triangles: counts, no area, colours */
    { GOOD_HEAD "triangle 0 0 -4 1 0 -4 0 1 -4 1 1\n", "t.scene:3: ", "triangle needs 12 numbers" },
    { GOOD_HEAD "triangle 0 0 -4 0 0 -4 0 1 -4 1 1 1\n", "t.scene:3: ", "triangle has no area" },
    { GOOD_HEAD "triangle 0 0 -4 1 1 -4 2 2 -4 1 1 1\n", "t.scene:3: ", "all three on a line" },
    { GOOD_HEAD "triangle 0 0 -4 1 0 -4 0 1 -4 1 -1 1\n", "t.scene:3: ", "triangle colour g" },
    { GOOD_HEAD "triangle 0 0 -4 1 0 -4 0 1 inf 1 1 1\n", "t.scene:3: ", "infinite" },
    /* meshes: the line itself */
    { GOOD_HEAD "mesh box.obj 1 0 0 0 1 1\n", "t.scene:3: ", "mesh needs a file and 7 numbers: FILE s tx ty tz r g b, got 7 words" },
    { GOOD_HEAD "mesh box.obj 0 0 0 0 1 1 1\n", "t.scene:3: ", "mesh scale s must be greater than 0, got 0" },
    { GOOD_HEAD "mesh box.obj -2 0 0 0 1 1 1\n", "t.scene:3: ", "mesh scale" },
    { GOOD_HEAD "mesh box.obj 1 0 0 0 1 1 1.5\n", "t.scene:3: ", "mesh colour b" },
    { GOOD_HEAD "mesh no-such-file.obj 1 0 0 0 1 1 1\n", "no-such-file.obj: ", "(the mesh of t.scene:3)" },
    { GOOD_HEAD "cone 0 0 -5 1 1 1 1\n", "t.scene:3: ", "expected image, fov, distance, background, sphere, plane, triangle or mesh" },
    /* a bad line after objects: they are freed (the sanitized build finds a leak) */
    { GOOD_HEAD ONE_SPHERE "plane 0 -1 0 0 1 0 1 1 1\ntriangle 0 0 -4 1 0 -4 0 1 -4 1 1 1\nsphere 0 0 -5 1 1 0\n",
      "t.scene:6: ", "sphere needs 7 numbers" },
};

/* Every bad scene above: -1, an empty scene, and a message that starts with
 * the file's name and the line and contains the word. */
static void test_bad_scenes(void)
{
    for (int k = 0; k < CHECK_COUNT(bad_scenes); k++) {
        const BadScene *b = &bad_scenes[k];
        Scene scene;
        char err[256] = "unchanged";
        int status = scene_parse(&scene, b->text, "t.scene", err, sizeof err);
        CHECK_MSG(status == -1, "scene %d (\"%s\") returned %d, want -1", k, b->text, status);
        CHECK_MSG(strncmp(err, b->where, strlen(b->where)) == 0,
                  "scene %d: message \"%s\" does not start with \"%s\"", k, err, b->where);
        CHECK_MSG(strstr(err, b->word) != NULL,
                  "scene %d: message \"%s\" does not contain \"%s\"", k, err, b->word);
        CHECK_MSG(strchr(err, '\n') == NULL, "scene %d: message \"%s\" is not one line", k, err);
        CHECK_MSG(!scene.spheres && !scene.planes && !scene.triangles && !scene.nspheres &&
                      !scene.nplanes && !scene.ntriangles, "scene %d: the scene is not left empty", k);
        scene_free(&scene);           /* harmless on a failed scene */
    }
}

/* Checks that the n objects at got, of size bytes each, are those at want
 * bit for bit, naming the first that is not. */
static void check_objects(const void *got, const void *want, int n, size_t size, const char *what)
{
    for (int k = 0; k < n; k++)
        if (memcmp((const char *)got + k * size, (const char *)want + k * size, size) != 0) {
            CHECK_MSG(0, "%s %d is not the one written", what, k);
            return;
        }
}

/* A scene holding every keyword gives exactly the values written, the
 * planes and the triangles in file order, each kind in its own list. */
static void test_good_scene_values(void)
{
    const char *text =
        "# a comment line\n"
        "   \n"
        "image 640 480        # nx ny\n"
        "fov\t60\n"
        "distance 2.5\n"
        "background 0.53 0.70 0.92\n"
        "plane 0 -1 0  0 2 0  0.5 0.25 1\n"
        "sphere 0 0 -6 1.5 0.9 0.2 0.2\n"
        "sphere -2.4 -0.8 -8 1.2 0.25 0.35 0.90#no space before the comment\n"
        "triangle -1 -1 -4  1 -1 -4  0 1 -4  0 1 0.5\n"
        "sphere 0x1p-2 1e2 -1E+3 0.5e-1 0 1 1\n"
        "plane 0x1p-3 0 -40  0 0 -1  1 1 1\n";
    const Sphere spheres[3] = {
        { { 0, 0, -6 }, 1.5, { 0.9, 0.2, 0.2 } },
        { { -2.4, -0.8, -8 }, 1.2, { 0.25, 0.35, 0.90 } },
        { { 0.25, 100, -1000 }, 0.05, { 0, 1, 1 } },
    };
    const Plane planes[2] = {
        { { 0, -1, 0 }, { 0, 2, 0 }, { 0.5, 0.25, 1 } },
        { { 0.125, 0, -40 }, { 0, 0, -1 }, { 1, 1, 1 } },
    };
    const Triangle triangle = { { -1, -1, -4 }, { 1, -1, -4 }, { 0, 1, -4 }, { 0, 1, 0.5 } };
    Scene scene;
    char err[256] = "";
    CHECK_EQ_INT(scene_parse(&scene, text, "good.scene", err, sizeof err), 0);
    CHECK_MSG(err[0] == '\0', "message \"%s\" on success", err);
    CHECK_EQ_INT(scene.nx, 640);
    CHECK_EQ_INT(scene.ny, 480);
    CHECK_EQ_DOUBLE(scene.fov_degrees, 60);
    CHECK_EQ_DOUBLE(scene.d, 2.5);
    CHECK_EQ_DOUBLE(scene.eye.x, 0);
    CHECK_EQ_DOUBLE(scene.eye.y, 0);
    CHECK_EQ_DOUBLE(scene.eye.z, 0);
    CHECK_EQ_DOUBLE(scene.background.x, 0.53);
    CHECK_EQ_DOUBLE(scene.background.y, 0.70);
    CHECK_EQ_DOUBLE(scene.background.z, 0.92);
    CHECK_EQ_INT(scene.nspheres, 3);
    CHECK_EQ_INT(scene.nplanes, 2);
    CHECK_EQ_INT(scene.ntriangles, 1);
    if (scene.nspheres == 3 && scene.nplanes == 2 && scene.ntriangles == 1) {
        check_objects(scene.spheres, spheres, 3, sizeof *spheres, "sphere");
        check_objects(scene.planes, planes, 2, sizeof *planes, "plane");
        check_objects(scene.triangles, &triangle, 1, sizeof triangle, "triangle");
    }
    scene_free(&scene);
    CHECK(scene.spheres == NULL && scene.planes == NULL && scene.triangles == NULL);
    CHECK(scene.nspheres == 0 && scene.nplanes == 0 && scene.ntriangles == 0);
    scene_free(&scene);               /* twice is harmless */
}

/* Only image and fov are required: distance 1, a black background and no
 * spheres by default; CRLF line ends, a last line without a newline; sizes
 * at both ends, a whole number written with a fraction, a tiny field of
 * view, colours at both ends of [0, 1]; a byte-order mark first, as some
 * Windows editors save UTF-8, skipped (it was read as a keyword, '???';
 * anywhere else it is not text: bad_scenes). */
static void test_defaults_crlf_and_edges(void)
{
    static const struct { const char *text; int nx, ny; double fov, green; int nspheres; } good[] = {
        { "fov 179.5\r\nimage 1 16384\r\n", 1, IMAGE_MAX_SIDE, 179.5, 0, 0 },
        { "image 16384.0 1\nfov 1e-5\nbackground 0 1 0\nsphere 0 0 -1 1e-300 1 0 1", 16384, 1, 1e-5, 1, 1 },
        { "\xEF\xBB\xBF# a comment\r\nimage 2 3\r\nfov 60\r\n", 2, 3, 60, 0, 0 },
        { "\xEF\xBB\xBFimage 2 3\nfov 60\n", 2, 3, 60, 0, 0 },
    };
    for (int k = 0; k < CHECK_COUNT(good); k++) {
        Scene scene;
        char err[256] = "";
        CHECK_MSG(scene_parse(&scene, good[k].text, "t.scene", err, sizeof err) == 0, "scene %d: %s", k, err);
        CHECK_MSG(scene.nx == good[k].nx && scene.ny == good[k].ny && scene.fov_degrees == good[k].fov,
                  "scene %d: image %d %d, fov %.17g", k, scene.nx, scene.ny, scene.fov_degrees);
        CHECK_MSG(scene.d == 1 && scene.background.x == 0 && scene.background.y == good[k].green &&
                      scene.background.z == 0 && scene.nspheres == good[k].nspheres,
                  "scene %d: distance %.17g, background %g %g %g, %d spheres", k, scene.d,
                  scene.background.x, scene.background.y, scene.background.z, scene.nspheres);
        scene_free(&scene);
    }
}

/* A line of 4096 characters is fine; one of 4097 is refused with its number. */
static void test_long_lines(void)
{
    size_t size = 3 * 5000;
    char *text = malloc(size);
    CHECK(text != NULL);
    if (!text)
        return;
    strcpy(text, GOOD_HEAD);
    size_t len = strlen(text);
    memset(text + len, ' ', 4096 - 1);       /* blank, then a comment mark */
    text[len + 4095] = '#';
    strcpy(text + len + 4096, "\n");
    Scene scene;
    char err[256];
    CHECK_EQ_INT(scene_parse(&scene, text, "long.scene", err, sizeof err), 0);
    scene_free(&scene);

    memset(text + len, ' ', 4097);
    strcpy(text + len + 4097, "\nsphere 0 0 -5 1 1 0 0\n");
    CHECK_EQ_INT(scene_parse(&scene, text, "long.scene", err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "long.scene:3: line is longer than 4096 characters");

    /* a very long last line without a newline */
    memset(text + len, '7', size - len - 1);
    text[size - 1] = '\0';
    CHECK_EQ_INT(scene_parse(&scene, text, "long.scene", err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "long.scene:3: line is longer");
    free(text);
}

/* GOOD_HEAD and n lines ONE_SPHERE (malloc'd). */
static char *spheres_text(size_t n)
{
    size_t head = strlen(GOOD_HEAD), len = strlen(ONE_SPHERE);
    char *text = malloc(head + n * len + 1);
    if (!text)
        return NULL;
    memcpy(text, GOOD_HEAD, head);
    for (size_t k = 0; k < n; k++)
        memcpy(text + head + k * len, ONE_SPHERE, len);
    text[head + n * len] = '\0';
    return text;
}

/* One sphere more than SCENE_MAX_SPHERES (which load: test_guard_sphere) is
 * refused on its line. */
static void test_sphere_limit(void)
{
    char *text = spheres_text(SCENE_MAX_SPHERES + 1);
    CHECK(text != NULL);
    if (!text)
        return;
    Scene scene;
    char err[256], where[64];
    CHECK_EQ_INT(scene_parse(&scene, text, "max.scene", err, sizeof err), -1);
    snprintf(where, sizeof where, "max.scene:%d: too many spheres", SCENE_MAX_SPHERES + 3);
    CHECK_STR_CONTAINS(err, where);
    CHECK(scene.spheres == NULL);
    free(text);
}

/* Past the last sphere, the guard (scene.h): for no sphere, for a number
 * that fills the array's capacity (16, then 32) and for one that does not,
 * and at the limit.  (In the sanitized build an array with no room for it
 * would be caught writing or reading it.) */
static void test_guard_sphere(void)
{
    static const int counts[] = { 0, 1, 15, 16, 17, 32, SCENE_MAX_SPHERES };
    for (int c = 0; c < CHECK_COUNT(counts); c++) {
        int n = counts[c];
        char *text = spheres_text((size_t)n);
        CHECK(text != NULL);
        if (!text)
            return;
        Scene scene;
        char err[256];
        CHECK_EQ_INT(scene_parse(&scene, text, "guard.scene", err, sizeof err), 0);
        CHECK_EQ_INT(scene.nspheres, n);
        Sphere guard = scene_guard_sphere();
        CHECK_MSG(scene.spheres && memcmp(&scene.spheres[n], &guard, sizeof guard) == 0,
                  "%d spheres: no guard sphere after the last", n);
        scene_free(&scene);
        free(text);
    }
}

/* A short err buffer is truncated safely; a NULL one is allowed. */
static void test_small_error_buffers(void)
{
    Scene scene;
    char err[8];
    memset(err, 'x', sizeof err);
    CHECK_EQ_INT(scene_parse(&scene, "fov 60\n", "a-long-name.scene", err, sizeof err), -1);
    CHECK(memchr(err, '\0', sizeof err) != NULL);
    CHECK_EQ_INT(scene_parse(&scene, "fov 60\n", "t.scene", NULL, 0), -1);
    CHECK_EQ_INT(scene_parse(&scene, NULL, "t.scene", err, sizeof err), -1);
}

/* scene_load: the message names the file and says why it cannot be read. */
static void test_load_errors(void)
{
    Scene scene;
    char err[512];
    CHECK_EQ_INT(scene_load(&scene, "no/such/file.scene", err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "no/such/file.scene: ");
    CHECK_STR_CONTAINS(err, strerror(ENOENT));
    CHECK(scene.spheres == NULL);

    CHECK_EQ_INT(scene_load(&scene, "labs/scenes", err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "labs/scenes: ");
    CHECK_STR_CONTAINS(err, strerror(EISDIR));
}

/* scene_load of a file: a NUL byte is refused with its line; a bad line is
 * reported with the file's path.  (That it reads a good file's values:
 * test_default_scene_values.) */
static void test_load_files(void)
{
    char dir[64], path[512], err[512], want[600];
    if (check_temp_dir(dir, sizeof dir, "load") < 0)
        return;
    Scene scene;
    const char nul[] = "image 8 4\nfov 45\nsph\0ere 1 2 -3 0.5 0 0.5 1\n";
    CHECK(check_write_in(path, sizeof path, dir, "t.scene", nul, sizeof nul - 1) == 0);
    CHECK_EQ_INT(scene_load(&scene, path, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s:3: contains a NUL byte", path);
    CHECK_STR_CONTAINS(err, want);

    CHECK(check_write_in(path, sizeof path, dir, "t.scene",
                         "image 8 4\n\n\nfov 45\nsphere 1 2 -3 0.5 0 0.5\n", 0) == 0);
    CHECK_EQ_INT(scene_load(&scene, path, err, sizeof err), -1);
    snprintf(want, sizeof want, "%s:5: sphere needs 7 numbers", path);
    CHECK_STR_CONTAINS(err, want);
    CHECK(check_remove_tree(dir) == 0);
}

/* Every scene shipped in labs/scenes loads (so its size, field of view and
 * distance are in range: bad_scenes) and holds an object. */
static void test_shipped_scenes_load(void)
{
    DIR *dir = opendir("labs/scenes");
    CHECK_MSG(dir != NULL, "cannot open labs/scenes (run from the kit's top directory)");
    if (!dir)
        return;
    int count = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        size_t len = strlen(entry->d_name);
        if (len < 7 || strcmp(entry->d_name + len - 6, ".scene") != 0)
            continue;
        char path[512], err[512];
        snprintf(path, sizeof path, "labs/scenes/%s", entry->d_name);
        Scene scene;
        int status = scene_load(&scene, path, err, sizeof err);
        CHECK_MSG(status == 0, "%s: %s", path, err);
        if (status == 0)
            CHECK_MSG(scene.nspheres + scene.nplanes + scene.ntriangles >= 1, "%s holds nothing", path);
        scene_free(&scene);
        count++;
    }
    closedir(dir);
    CHECK_MSG(count >= 8, "found %d scenes in labs/scenes, want at least 8", count);
}

/* A mesh: read next to the scene, faces of 3 and 4 vertices (a fan),
 * index forms i, i/t, i//n, i/t/n and negative ones, the statements that
 * are ignored; every vertex moved once to s v + t, so triangles that share
 * a vertex share its bits. */
static void test_mesh_files(void)
{
    char dir[64], path[512], err[512];
    check_temp_dir(dir, sizeof dir, "mesh");
    snprintf(path, sizeof path, "%s/meshes", dir);
    CHECK(mkdir(path, 0700) == 0);
    CHECK(check_write_in(path, sizeof path, dir, "meshes/quad.obj",
                         "# a unit square split in a fan, and a triangle\n"
                         "o square\nmtllib none.mtl\nusemtl red\ns off\ng one\n"
                         "v 0 0 0\nv 1 0 0\nv 1 1 0 1\nv 0 1 0\n"
                         "vt 0 0\nvn 0 0 1\nvp 0.5\n"
                         "f 1 2/1 3//1 4/1/1\n"
                         "v 0.1 0.3 0.7\n"
                         "f -1 -3 -5\n"
                         "l 1 2\n", 0) == 0);
    CHECK(check_write_in(path, sizeof path, dir, "box.scene",
                         "image 8 8\nfov 60\nmesh meshes/quad.obj 0.1 1 2 -3 0.5 0.5 0.5\n", 0) == 0);
    Scene scene;
    int status = scene_load(&scene, path, err, sizeof err);
    CHECK_MSG(status == 0, "%s", err);
    CHECK_EQ_INT(scene.ntriangles, 3);
    if (status == 0 && scene.ntriangles == 3) {
        const Triangle *t = scene.triangles;
        /* s v + t as a double expression, computed once per vertex */
        Vec3 v1 = vec3_add(vec3_scale(vec3(1, 0, 0), 0.1), vec3(1, 2, -3));
        Vec3 v3 = vec3_add(vec3_scale(vec3(1, 1, 0), 0.1), vec3(1, 2, -3));
        CHECK_EQ_DOUBLE(t[0].b.x, v1.x);
        CHECK_EQ_DOUBLE(t[0].c.y, v3.y);
        /* the fan (1 2 3) (1 3 4): vertex 3 is shared, bit for bit */
        CHECK(memcmp(&t[0].c, &t[1].b, sizeof t[0].c) == 0);
        CHECK(memcmp(&t[0].a, &t[1].a, sizeof t[0].a) == 0);
        CHECK_EQ_DOUBLE(t[1].c.x, 0 * 0.1 + 1);
        CHECK_EQ_DOUBLE(t[1].c.y, 1 * 0.1 + 2);
        /* -1 -3 -5 after 5 vertices: 5, 3, 1 */
        CHECK_EQ_DOUBLE(t[2].a.z, 0.7 * 0.1 - 3);
        CHECK(memcmp(&t[2].b, &t[0].c, sizeof t[2].b) == 0);
        CHECK(memcmp(&t[2].c, &t[0].a, sizeof t[2].c) == 0);
        CHECK_EQ_DOUBLE(t[2].color.x, 0.5);
    }
    scene_free(&scene);

    /* From the scene's text with its path as the name: the same. */
    const char *text = "image 8 8\nfov 60\nmesh meshes/quad.obj 1 0 0 0 1 1 1\n";
    CHECK_EQ_INT(scene_parse(&scene, text, path, err, sizeof err), 0);
    CHECK_EQ_INT(scene.ntriangles, 3);
    scene_free(&scene);

    CHECK(check_remove_tree(dir) == 0);
}

/* Bad OBJ files: the OBJ's own file and line first, then the scene's. */
static void test_mesh_errors(void)
{
    static const struct { const char *obj, *line, *word; } bad[] = {
        { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", ":4: ",
          "f: vertex 4 does not exist (3 vertices so far; indices start at 1)" },
        { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", ":4: ", "vertex 0 does not exist" },
        { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", ":4: ", "vertex -4 does not exist" },
        { "v 0 0 0\nv 1 0 0\nf 1 2\n", ":3: ", "f needs at least 3 vertices, got 2" },
        { "v 0 0\n", ":1: ", "v needs 3 numbers: x y z, got 2" },
        { "v 0 nan 0\n", ":1: ", "NaN" },
        { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", ":4: ", "f: 'x' is not a vertex index" },
        { "v 0 0 0\ncurv 0 1\n", ":2: ", "unknown statement 'curv'" },
        { "v 0 0 0\nv 1 0 0\nv 0 1 0\n", ": ", "no faces" },
        { "v 0 0 0\n\0 1 0\n", ":2: ", "NUL" },
    };
    char dir[64], path[512], err[512], want[600];
    check_temp_dir(dir, sizeof dir, "mesh");
    for (int k = 0; k < CHECK_COUNT(bad); k++) {
        /* a text that holds a NUL: write it too */
        CHECK(check_write_in(path, sizeof path, dir, "bad.obj", bad[k].obj,
                             strstr(bad[k].word, "NUL") ? 14 : 0) == 0);
        Scene scene;
        char scene_text[700];
        snprintf(scene_text, sizeof scene_text, "image 8 8\nfov 60\n\nmesh %s 1 0 0 0 1 1 1\n", path);
        CHECK_EQ_INT(scene_parse(&scene, scene_text, "m.scene", err, sizeof err), -1);
        snprintf(want, sizeof want, "%s%s", path, bad[k].line);
        CHECK_MSG(strncmp(err, want, strlen(want)) == 0, "obj %d: \"%s\" does not start with \"%s\"", k, err, want);
        CHECK_MSG(strstr(err, bad[k].word) != NULL, "obj %d: \"%s\" does not say \"%s\"", k, err, bad[k].word);
        CHECK_STR_CONTAINS(err, "(the mesh of m.scene:4)");
        CHECK(scene.triangles == NULL && scene.ntriangles == 0);
    }
    CHECK(check_remove_tree(dir) == 0);
}

/* The default scene holds what its file says. */
static void test_default_scene_values(void)
{
    Scene scene;
    char err[512];
    CHECK_EQ_INT(scene_load(&scene, "labs/scenes/default.scene", err, sizeof err), 0);
    CHECK_EQ_INT(scene.nx, 640);
    CHECK_EQ_INT(scene.ny, 480);
    CHECK_EQ_DOUBLE(scene.fov_degrees, 60);
    CHECK_EQ_DOUBLE(scene.d, 1);
    CHECK_EQ_DOUBLE(scene.background.y, 0.70);
    const Sphere spheres[5] = {
        { { 0, 0, -6 }, 1.5, { 0.90, 0.20, 0.20 } },
        { { 1.6, 0.5, -4.5 }, 0.8, { 0.20, 0.70, 0.30 } },
        { { -2.4, -0.8, -8 }, 1.2, { 0.25, 0.35, 0.90 } },
        { { 0, -101, -7 }, 100, { 0.85, 0.80, 0.60 } },
        { { 4.3, 1.8, -7 }, 1.6, { 0.95, 0.75, 0.15 } },
    };
    CHECK_EQ_INT(scene.nspheres, 5);
    if (scene.nspheres == 5)
        check_objects(scene.spheres, spheres, 5, sizeof *spheres, "sphere");
    scene_free(&scene);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_bad_scenes),
    CHECK_TEST(test_good_scene_values),
    CHECK_TEST(test_defaults_crlf_and_edges),
    CHECK_TEST(test_long_lines),
    CHECK_TEST(test_sphere_limit),
    CHECK_TEST(test_guard_sphere),
    CHECK_TEST(test_small_error_buffers),
    CHECK_TEST(test_load_errors),
    CHECK_TEST(test_load_files),
    CHECK_TEST(test_shipped_scenes_load),
    CHECK_TEST(test_default_scene_values),
    CHECK_TEST(test_mesh_files),
    CHECK_TEST(test_mesh_errors),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
