/* The renderer of labs/kit/render.c, end to end with the reference stage
 * files (this test is linked with solutions/), on scenes whose pixels are
 * known by construction. */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "render_check.h"
#include "../../labs/kit/compare.h"

/* A scene of nx x ny pixels with the given spheres, eye at the origin. */
static Scene make_scene(int nx, int ny, double fov, Vec3 background, Sphere *spheres, int n)
{
    Scene scene = { .nx = nx, .ny = ny, .fov_degrees = fov, .d = 1, .eye = { 0, 0, 0 },
                    .background = background, .spheres = spheres, .nspheres = n };
    return scene;
}

/* True when pixel (i, j) of img holds colour c as the kit stores it. */
static int pixel_is(const Image *img, int i, int j, Vec3 c)
{
    const unsigned char *p = img->rgb + 3 * ((size_t)j * img->width + i);
    return p[0] == image_channel(c.x) && p[1] == image_channel(c.y) && p[2] == image_channel(c.z);
}

/* Checks pixel (i, j) is colour c, naming the pixel on failure. */
#define CHECK_PIXEL(img, i, j, c, what)                                        \
    do { const unsigned char *p_ = (img)->rgb + 3 * ((size_t)(j) * (img)->width + (i)); \
         CHECK_MSG(pixel_is((img), (i), (j), (c)),                             \
                   "pixel (%d, %d) is (%d, %d, %d), want %s", (i), (j), p_[0], p_[1], p_[2], what); \
    } while (0)

/* The number of pixels of img in columns i0 .. i1-1, rows j0 .. j1-1 that are colour c. */
static int count_color(const Image *img, int i0, int i1, int j0, int j1, Vec3 c)
{
    int n = 0;
    for (int j = j0; j < j1; j++)
        for (int i = i0; i < i1; i++)
            n += pixel_is(img, i, j, c);
    return n;
}

static const Vec3 BACKGROUND = { 0.1, 0.2, 0.3 };
static const Vec3 RED = { 0.9, 0.2, 0.25 };
static const Vec3 GREEN = { 0.2, 0.8, 0.4 };

/* One sphere straight ahead: the centre pixel (on the axis, the image
 * being odd-sized) is the sphere's colour, the four corners the background. */
static void test_sphere_straight_ahead(void)
{
    Sphere sphere = { { 0, 0, -5 }, 1, RED };
    Scene scene = make_scene(33, 25, 60, BACKGROUND, &sphere, 1);
    Image img;
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 2, &img, NULL) < 0)
        return;
    CHECK_PIXEL(&img, 16, 12, RED, "the sphere at the centre");
    CHECK_PIXEL(&img, 0, 0, BACKGROUND, "the background at the top left");
    CHECK_PIXEL(&img, 32, 0, BACKGROUND, "the background at the top right");
    CHECK_PIXEL(&img, 0, 24, BACKGROUND, "the background at the bottom left");
    CHECK_PIXEL(&img, 32, 24, BACKGROUND, "the background at the bottom right");
    /* the disc is symmetric: as many sphere pixels left and right of the axis */
    CHECK_EQ_INT(count_color(&img, 0, 16, 0, 25, RED), count_color(&img, 17, 33, 0, 25, RED));
    CHECK_EQ_INT(count_color(&img, 0, 33, 0, 12, RED), count_color(&img, 0, 33, 13, 25, RED));
    image_free(&img);
}

/* A sphere up and to the left lies wholly in the top-left quadrant: any
 * flip of the image or mix-up of i and j moves it. */
static void test_asymmetric_quadrant(void)
{
    /* seen from the eye, the sphere spans about 2 to 20 degrees left of
     * and above the axis, so it stays clear of the central row and column */
    Sphere sphere = { { -1, 1, -5 }, 0.8, GREEN };
    Scene scene = make_scene(64, 48, 60, BACKGROUND, &sphere, 1);
    Image img;
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 3, &img, NULL) < 0)
        return;
    /* the pixel on the line of sight through the centre: x = y = 0.2 on the plane */
    double h = 2 * tan(30 * M_PI / 180), w = h * 64 / 48;
    int i = (int)((-0.2 + w / 2) / w * 64), j = (int)((h / 2 - 0.2) / h * 48);
    CHECK_PIXEL(&img, i, j, GREEN, "the sphere in the top-left quadrant");
    CHECK_PIXEL(&img, 63 - i, j, BACKGROUND, "the background (mirrored left-right)");
    CHECK_PIXEL(&img, i, 47 - j, BACKGROUND, "the background (mirrored top-bottom)");
    CHECK_PIXEL(&img, 63 - i, 47 - j, BACKGROUND, "the background (turned half round)");
    CHECK(count_color(&img, 0, 32, 0, 24, GREEN) > 20);
    CHECK_EQ_INT(count_color(&img, 32, 64, 0, 48, GREEN), 0);
    CHECK_EQ_INT(count_color(&img, 0, 64, 24, 48, GREEN), 0);
    image_free(&img);
}

/* Scenes of 40 x 30 pixels in which columns i0 .. i1-1 of rows j0 .. j1-1
 * are colour c and every other pixel the background: spheres wholly behind
 * the eye never show, even with a wide field of view; with the eye inside a
 * sphere every ray meets its inside wall; a ground plane y = -1, its normal
 * up or down, is every pixel below the horizon (centre y < 0, the image
 * having an even number of rows); a triangle in the plane z = -1 whose
 * right edge is the line x = 0 and whose other edges lie outside the view
 * covers exactly the left half. */
static void test_one_colour_rectangles(void)
{
    Sphere behind[2] = { { { 0, 0, 5 }, 1, RED }, { { 0.5, -0.5, 20 }, 15, GREEN } };  /* z = 5 .. 35 */
    Sphere inside[2] = { { { 0, 0, 0 }, 10, RED }, { { 1, -2, 0.5 }, 50, GREEN } };  /* around the first */
    Plane up = { { 0, -1, 0 }, { 0, 1, 0 }, GREEN }, down = { { 0, -1, 0 }, { 0, -2, 0 }, GREEN };
    Triangle left = { { -100, -50, -1 }, { 0, -50, -1 }, { 0, 150, -1 }, RED };
    const struct {
        const char *what;
        double fov;
        int threads, nspheres;
        Sphere *spheres;
        Plane *plane;
        Triangle *tri;
        int i0, i1, j0, j1;
        Vec3 c;
    } cases[] = {
        { "spheres behind the eye", 170, 2, 2, behind, NULL, NULL, 0, 0, 0, 0, RED },
        { "the eye inside two spheres", 120, 4, 2, inside, NULL, NULL, 0, 40, 0, 30, RED },
        { "the eye inside a sphere", 120, 1, 1, inside + 1, NULL, NULL, 0, 40, 0, 30, GREEN },
        { "the ground, its normal up", 60, 2, 0, NULL, &up, NULL, 0, 40, 15, 30, GREEN },
        { "the ground, its normal down", 60, 2, 0, NULL, &down, NULL, 0, 40, 15, 30, GREEN },
        { "a triangle over the left half", 60, 2, 0, NULL, NULL, &left, 0, 20, 0, 30, RED },
    };
    for (int k = 0; k < CHECK_COUNT(cases); k++) {
        Scene scene = make_scene(40, 30, cases[k].fov, BACKGROUND, cases[k].spheres, cases[k].nspheres);
        scene.planes = cases[k].plane;
        scene.nplanes = cases[k].plane != NULL;
        scene.triangles = cases[k].tri;
        scene.ntriangles = cases[k].tri != NULL;
        Image img;
        if (render_as(&scene, RENDER_HIERARCHY_AUTO, cases[k].threads, &img, NULL) < 0)
            return;
        int area = (cases[k].i1 - cases[k].i0) * (cases[k].j1 - cases[k].j0);
        int in = count_color(&img, cases[k].i0, cases[k].i1, cases[k].j0, cases[k].j1, cases[k].c);
        int out = 40 * 30 - count_color(&img, 0, 40, 0, 30, BACKGROUND);
        CHECK_MSG(in == area && out == area, "%s: %d of the %d pixels in the rectangle are its colour, "
                  "%d pixels are not the background", cases[k].what, in, area, out);
        image_free(&img);
    }
}

/* A 1x1 image looks straight ahead; a one-row and a one-column image work. */
static void test_tiny_images(void)
{
    /* the size, the threads, and a pixel at an end that is the background
     * (none in a 1x1 image); the middle pixel is the sphere */
    static const struct { int nx, ny, threads, end_i, end_j; } sizes[] = {
        { 1, 1, 8, -1, -1 },
        { 101, 1, 2, 0, 0 },
        { 1, 101, 2, 0, 100 },
    };
    Sphere sphere = { { 0, 0, -5 }, 1, RED };
    for (int k = 0; k < CHECK_COUNT(sizes); k++) {
        Scene scene = make_scene(sizes[k].nx, sizes[k].ny, 60, BACKGROUND, &sphere, 1);
        Image img;
        if (render_as(&scene, RENDER_HIERARCHY_AUTO, sizes[k].threads, &img, NULL) < 0)
            return;
        CHECK_PIXEL(&img, sizes[k].nx / 2, sizes[k].ny / 2, RED, "the sphere");
        if (sizes[k].end_i >= 0)
            CHECK_PIXEL(&img, sizes[k].end_i, sizes[k].end_j, BACKGROUND, "the background");
        image_free(&img);
    }
}

/* Renders a shipped scene at nx x ny with 1 and with nthreads threads and
 * checks the two images are byte for byte the same. */
static void check_threads_agree(const char *path, int nx, int ny, int nthreads)
{
    Scene scene;
    if (load_scene(&scene, path, nx, ny) < 0)
        return;
    Image one, many;
    RenderStats stats;
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 1, &one, &stats) == 0) {
        CHECK_EQ_INT(stats.threads, 1);
        if (render_as(&scene, RENDER_HIERARCHY_AUTO, nthreads, &many, &stats) == 0) {
            CHECK_MSG(memcmp(one.rgb, many.rgb, (size_t)3 * nx * ny) == 0,
                      "%s at %dx%d: 1 and %d threads give different images", path, nx, ny, nthreads);
            CHECK(stats.threads >= 1 && (nthreads == 0 || stats.threads <= nthreads));
            image_free(&many);
        }
        image_free(&one);
    }
    scene_free(&scene);
}

/* The image does not depend on the number of threads. */
static void test_threads_byte_identical(void)
{
    check_threads_agree("labs/scenes/default.scene", 640, 480, 4);
    check_threads_agree("labs/scenes/default.scene", 97, 61, 4);
    check_threads_agree("labs/scenes/inside.scene", 480, 360, 4);
    check_threads_agree("labs/scenes/wide.scene", 960, 300, 3);
    check_threads_agree("labs/scenes/flip.scene", 320, 320, 0);
    check_threads_agree("labs/scenes/ground.scene", 320, 240, 3);
}

/* The colour a ray should get, written here apart from the kit: Part 3b's
 * ray_color for spheres alone; otherwise the closest hit over spheres,
 * planes and triangles, the first of equal t winning. */
static Vec3 expected_color(const Scene *scene, const Ray *ray)
{
    if (scene->nplanes == 0 && scene->ntriangles == 0)
        return ray_color(scene, ray);
    double best = INFINITY, t;
    Vec3 color = scene->background;
    for (int k = 0; k < scene->nspheres; k++)
        if (sphere_intersect(&scene->spheres[k], ray, &t) && t < best)
            best = t, color = scene->spheres[k].color;
    for (int k = 0; k < scene->nplanes; k++)
        if (plane_intersect(&scene->planes[k], ray, &t) && t < best)
            best = t, color = scene->planes[k].color;
    for (int k = 0; k < scene->ntriangles; k++)
        if (triangle_intersect(&scene->triangles[k], ray, &t) && t < best)
            best = t, color = scene->triangles[k].color;
    return color;
}

/* Renders a shipped scene at nx x ny and checks every pixel against the
 * stage functions applied to it one at a time, the plainest loop there is:
 * the renderer makes rays a run of pixels ahead and reuses the bytes of a
 * repeated colour, and neither may change a byte. */
static void check_plain_loop(const char *path, int nx, int ny)
{
    Scene scene;
    if (load_scene(&scene, path, nx, ny) < 0)
        return;
    Image img;
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 2, &img, NULL) == 0) {
        double w, h;
        image_plane_size(scene.fov_degrees, (double)nx / ny, scene.d, &w, &h);
        int wrong = 0, first_i = -1, first_j = -1;
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                Ray ray = camera_ray(scene.eye, pixel_coordinates(i, j, nx, ny, w, h, scene.d));
                if (!pixel_is(&img, i, j, expected_color(&scene, &ray)) && wrong++ == 0) {
                    first_i = i;
                    first_j = j;
                }
            }
        }
        CHECK_MSG(wrong == 0, "%s at %dx%d: %d pixels differ from the plain loop, the first (%d, %d)",
                  path, nx, ny, wrong, first_i, first_j);
        image_free(&img);
    }
    scene_free(&scene);
}

/* The renderer's image is the stage functions' answer at every pixel, for
 * widths on either side of the renderer's runs of 16 pixels.  cracks.scene
 * is checked at its own size, where the rays run along the triangles'
 * edges and ties decide pixels: 2 x 40 million triangle tests, which take
 * the sanitized build 2.5 s; that build (CHECK_SANITIZED), whose sums are
 * the same, checks it at a sixteenth of the size. */
static void test_same_as_plain_loop(void)
{
    static const int widths[] = { 1, 2, 15, 16, 17, 31, 32, 33, 97, 640 };
    for (int k = 0; k < CHECK_COUNT(widths); k++)
        check_plain_loop("labs/scenes/default.scene", widths[k], 48);
    check_plain_loop("labs/scenes/inside.scene", 161, 120);
    check_plain_loop("labs/scenes/behind.scene", 161, 120);
    check_plain_loop("labs/scenes/flip.scene", 47, 53);
    check_plain_loop("labs/scenes/ground.scene", 161, 120);
    if (CHECK_SANITIZED)
        check_plain_loop("labs/scenes/cracks.scene", 80, 60);
    else
        check_plain_loop("labs/scenes/cracks.scene", 320, 240);
}

static const Vec3 BLUE = { 0.1, 0.3, 0.9 };

/* The closest hit across kinds: a wall z = -5, a triangle at z = -4 over
 * the right half, a sphere of radius 1 at z = -3 in the middle.  The centre
 * pixel sees the sphere, a pixel left of it the wall, right of it the
 * triangle; moving the sphere behind the wall hides it. */
static void test_closest_across_kinds(void)
{
    Sphere sphere = { { 0, 0, -3 }, 1, GREEN };
    Plane wall = { { 0, 0, -5 }, { 0, 0, 1 }, RED };
    Triangle tri = { { 0.5, -100, -4 }, { 100, -100, -4 }, { 0.5, 100, -4 }, BLUE };
    Scene scene = make_scene(41, 31, 90, BACKGROUND, &sphere, 1);
    scene.planes = &wall;
    scene.nplanes = 1;
    scene.triangles = &tri;
    scene.ntriangles = 1;
    Image img;
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 2, &img, NULL) < 0)
        return;
    CHECK_PIXEL(&img, 20, 15, GREEN, "the sphere, in front of the triangle and the wall");
    CHECK_PIXEL(&img, 2, 15, RED, "the wall, left of the sphere");
    CHECK_PIXEL(&img, 38, 15, BLUE, "the triangle, right of the sphere, in front of the wall");
    CHECK_EQ_INT(count_color(&img, 0, 41, 0, 31, BACKGROUND), 0);
    image_free(&img);
    sphere.center.z = -30;                        /* behind the wall now */
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 1, &img, NULL) < 0)
        return;
    CHECK_EQ_INT(count_color(&img, 0, 41, 0, 31, GREEN), 0);
    CHECK_PIXEL(&img, 20, 15, RED, "the wall, where the sphere was");
    image_free(&img);
}

/* make compare's side-by-side picture: a band of labels (white letters on
 * grey) above each of the three panels, then the two images and the heat
 * map, pixel for pixel; a label wider than its panel is left out. */
static void test_side_by_side_labels(void)
{
    for (int width = 120; width >= 20; width -= 100) {
        Image a, b, out;
        char err[128];
        if (image_alloc(&a, width, 9, err, sizeof err) < 0 || image_alloc(&b, width, 9, err, sizeof err) < 0)
            return;
        memset(a.rgb, 10, (size_t)3 * width * 9);
        memset(b.rgb, 10, (size_t)3 * width * 9);
        b.rgb[0] = 200;                                /* one pixel differs */
        CHECK(compare_side_by_side(&a, &b, &out, err, sizeof err) == 0);
        int band = compare_label_band(width);
        CHECK_EQ_INT(band, 11);
        CHECK_EQ_INT(out.width, 3 * width + 2 * COMPARE_GAP);
        CHECK_EQ_INT(out.height, 9 + band);
        for (int k = 0; k < 3; k++) {
            int x0 = k * (width + COMPARE_GAP), white = 0;
            for (int j = 0; j < band; j++)
                for (int i = x0; i < x0 + width; i++)
                    white += out.rgb[3 * (j * out.width + i)] == 255;
            CHECK_MSG(width < 70 ? white == 0 : white > 20, "panel %d, %d wide: %d white pixels in its label", k,
                      width, white);
            const unsigned char *first = out.rgb + 3 * (band * out.width + x0);
            if (k < 2)                                 /* the images, under the band */
                CHECK_EQ_INT(first[0], k == 0 ? 10 : 200);
            else                                       /* the heat map: a difference */
                CHECK(first[0] != 0 || first[1] != 0 || first[2] != 0);
        }
        image_free(&a);
        image_free(&b);
        image_free(&out);
    }
}

/* The statistics are positive and consistent. */
static void test_stats(void)
{
    Sphere sphere = { { 0, 0, -5 }, 1, RED };
    Scene scene = make_scene(200, 150, 60, BACKGROUND, &sphere, 1);
    Image img;
    RenderStats stats = { -1, -1, -1, -1, -1, -1, true };
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 4, &img, &stats) < 0)
        return;
    CHECK(stats.seconds > 0);
    CHECK(stats.rays_per_second > 0);
    CHECK_NEAR(stats.rays_per_second * stats.seconds, 200.0 * 150.0, 1e-6 * 200 * 150);
    CHECK_EQ_INT(stats.threads, 4);
    image_free(&img);

    stats.threads = -1;               /* 0 threads: one per core */
    if (render_as(&scene, RENDER_HIERARCHY_AUTO, 0, &img, &stats) < 0)
        return;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    CHECK(stats.threads >= 1);
    CHECK(cores < 1 || stats.threads <= cores);
    image_free(&img);
}

/* An image of the wrong size is refused with a message. */
static void test_wrong_image_size(void)
{
    Sphere sphere = { { 0, 0, -5 }, 1, RED };
    Scene scene = make_scene(20, 10, 60, BACKGROUND, &sphere, 1);
    Image img;
    char err[256] = "";
    CHECK_EQ_INT(image_alloc(&img, 10, 20, err, sizeof err), 0);
    RenderOptions opt = { 1, false, RENDER_HIERARCHY_AUTO, { 0, 0 } };
    RenderStats stats;
    CHECK_EQ_INT(render_scene(&scene, &img, &opt, &stats, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "10x20");
    CHECK_STR_CONTAINS(err, "20x10");
    image_free(&img);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_sphere_straight_ahead),
    CHECK_TEST(test_asymmetric_quadrant),
    CHECK_TEST(test_one_colour_rectangles),
    CHECK_TEST(test_tiny_images),
    CHECK_TEST(test_threads_byte_identical),
    CHECK_TEST(test_same_as_plain_loop),
    CHECK_TEST(test_closest_across_kinds),
    CHECK_TEST(test_side_by_side_labels),
    CHECK_TEST(test_stats),
    CHECK_TEST(test_wrong_image_size),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
