/*
 * The pixels on an edge (labs/kit/edges.c): found where a nudged render
 * differs, each other colour once and never the pixel's own; written and
 * read back exactly; and taken by compare only in a colour listed for the
 * pixel.  (render --edges on a real scene, and compare's messages for bad
 * files: tests/suites/render_cli.sh.)
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "kit/edges.h"

/* A w x h image of one colour c. */
static Image flat(int w, int h, unsigned char c)
{
    Image img = { 0, 0, NULL };
    char err[100];
    CHECK_EQ_INT(image_alloc(&img, w, h, err, sizeof err), 0);
    if (img.rgb)
        memset(img.rgb, c, (size_t)3 * (size_t)w * (size_t)h);
    return img;
}

static void set_pixel(Image *img, int i, int j, unsigned char r, unsigned char g, unsigned char b)
{
    unsigned char *p = img->rgb + 3 * ((size_t)j * (size_t)img->width + (size_t)i);
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

/* Pixel (1, 0) changes in two of the four nudged renders, to two colours;
 * pixel (2, 3) in three, to one colour and back to its own; the rest in
 * none.  Found: those two, in row order, each other colour once. */
static void test_find(void)
{
    Image img = flat(4, 5, 10), nudged[4];
    for (int k = 0; k < 4; k++)
        nudged[k] = flat(4, 5, 10);
    if (!img.rgb)
        return;
    set_pixel(&nudged[0], 2, 3, 7, 8, 9);
    set_pixel(&nudged[1], 2, 3, 7, 8, 9);
    set_pixel(&nudged[1], 1, 0, 1, 2, 3);
    set_pixel(&nudged[3], 1, 0, 4, 5, 6);
    set_pixel(&img, 3, 4, 200, 200, 200);             /* the image's own colour in no nudge */
    for (int k = 0; k < 4; k++)
        set_pixel(&nudged[k], 3, 4, 200, 200, 200);
    Edges edges;
    char err[100];
    CHECK_EQ_INT(edges_find(&edges, &img, nudged, err, sizeof err), 0);
    CHECK_EQ_INT(edges.width, 4);
    CHECK_EQ_INT(edges.height, 5);
    CHECK_EQ_INT(edges.count, 2);
    if (edges.count == 2) {
        const EdgePixel *a = &edges.pixels[0], *b = &edges.pixels[1];
        CHECK(a->i == 1 && a->j == 0 && a->nother == 2);
        CHECK(memcmp(a->other[0], "\1\2\3", 3) == 0 && memcmp(a->other[1], "\4\5\6", 3) == 0);
        CHECK(b->i == 2 && b->j == 3 && b->nother == 1);
        CHECK(memcmp(b->other[0], "\7\10\11", 3) == 0);
    }
    edges_free(&edges);
    image_free(&img);
    for (int k = 0; k < 4; k++)
        image_free(&nudged[k]);
}

/* What edges_write writes, edges_read reads back exactly, and compare
 * takes a differing pixel on an edge only in one of its other colours. */
static void test_write_read_accept(void)
{
    char dir[64], path[128], err[300];
    if (check_temp_dir(dir, sizeof dir, "edges") < 0)
        return;
    snprintf(path, sizeof path, "%s/x.edges", dir);
    EdgePixel pixels[2] = { { 0, 1, 1, { { 255, 0, 1 } } },
                            { 2, 1, 4, { { 1, 1, 1 }, { 2, 2, 2 }, { 3, 3, 3 }, { 4, 4, 4 } } } };
    Edges out = { 3, 2, 2, pixels }, in;
    CHECK_EQ_INT(edges_write(&out, path, err, sizeof err), 0);
    CHECK_EQ_INT(edges_read(&in, path, err, sizeof err), 0);
    CHECK(in.width == 3 && in.height == 2 && in.count == 2);
    if (in.count == 2)
        CHECK(memcmp(in.pixels, pixels, sizeof pixels) == 0);

    Image ref = flat(3, 2, 50), sub = flat(3, 2, 50);
    if (ref.rgb && sub.rgb && in.count == 2) {
        set_pixel(&sub, 0, 1, 255, 0, 1);             /* listed: taken */
        set_pixel(&sub, 2, 1, 3, 3, 4);               /* not listed: still differs */
        set_pixel(&sub, 1, 0, 1, 1, 1);               /* not on an edge */
        CHECK_EQ_INT(edges_accept(&in, &sub, &ref), 1);
        CHECK(memcmp(ref.rgb + 9, "\377\0\1", 3) == 0);
        CHECK(memcmp(ref.rgb + 15, "\62\62\62", 3) == 0);
        CHECK(memcmp(ref.rgb + 3, "\62\62\62", 3) == 0);
    }
    edges_free(&in);
    image_free(&ref);
    image_free(&sub);
    check_remove_tree(dir);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_find),
    CHECK_TEST(test_write_read_accept),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
