/*
 * compare_main.c - the `compare` program: how far a render is from the
 * reference render.
 *
 *     compare SUBMISSION_IMAGE REFERENCE_IMAGE [-o SIDE_BY_SIDE.png] [--edges FILE]
 *
 * Prints how many pixels differ, the largest and the mean channel error and
 * the PSNR, and can write the two images side by side with a heat map of
 * their difference.  With the reference's pixels on an edge (render
 * --edges, edges.h), a pixel there in one of the reference's other colours
 * is equal.  Exit status: 0 identical, 1 different, 2 error.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compare.h"
#include "edges.h"
#include "image.h"
#include "textfile.h"

/* Prints the usage to f. */
static void compare_usage(FILE *f)
{
    fprintf(f,
            "usage: compare SUBMISSION_IMAGE REFERENCE_IMAGE [-o SIDE_BY_SIDE.png] [--edges FILE]\n"
            "  compares two images of the same size (PNG or binary PPM)\n"
            "  -o FILE   also write submission | reference | difference side by side;\n"
            "            in the difference black is equal, then dark blue, red, yellow\n"
            "            and white for ever larger differences\n"
            "  --edges FILE  the reference's pixels on an edge (render --edges): there a\n"
            "            colour the reference draws when its ray moves by a rounding is equal\n"
            "exit status: 0 identical, 1 the images differ, 2 error or bad usage\n");
}

/* Writes submission | reference | heat map, with grey gaps, to path.
 * Returns 0, or -1 with a message in err (too wide, out of memory, write). */
static int compare_write_side_by_side(const Image *sub, const Image *ref, const char *path,
                                      char *err, size_t errlen)
{
    Image out;
    char why[400];
    if (compare_side_by_side(sub, ref, &out, why, sizeof why) < 0)
        return kit_fail(err, errlen, "%s: %s", path, why);
    int status = image_write(&out, path, err, errlen);
    image_free(&out);
    return status;
}

/* Prints the measures of st for the two files. */
static void compare_report(const CompareStats *st, const char *sub, const char *ref,
                           int width, int height)
{
    printf("compared %s with %s (%dx%d)\n", sub, ref, width, height);
    printf("  pixels that differ:    %.3f%% (%lld of %lld)\n",
           100.0 * (double)st->differing / (double)st->pixels, st->differing, st->pixels);
    printf("  largest channel error: %d (of 255)\n", st->max_error);
    printf("  mean channel error:    %.4f (of 255)\n", st->mean_error);
    if (st->differing == 0)
        printf("  PSNR:                  infinite\nidentical\n");
    else
        printf("  PSNR:                  %.2f dB\nthe images differ\n", st->psnr);
}

/* Reads the reference's pixels on an edge from path and takes into ref
 * each of sub's pixels there in one of their other colours, saying how
 * many.  Returns 0, or -1 with a reason in err. */
static int compare_edges(const char *path, const Image *sub, Image *ref, char *err, size_t errlen)
{
    Edges edges;
    if (edges_read(&edges, path, err, errlen) < 0)
        return -1;
    if (edges.width != ref->width || edges.height != ref->height) {
        snprintf(err, errlen, "%s is for an image of %dx%d, the reference is %dx%d", path,
                 edges.width, edges.height, ref->width, ref->height);
        edges_free(&edges);
        return -1;
    }
    long long taken = edges_accept(&edges, sub, ref);
    if (taken > 0)
        printf("%lld pixel%s on an edge (%s) %s the colour the reference draws when its ray moves "
               "by a rounding: equal\n", taken, taken == 1 ? "" : "s", path,
               taken == 1 ? "has" : "have");
    edges_free(&edges);
    return 0;
}

/* Compares as the command line says.  Returns the exit status: 0 identical,
 * 1 different (or of different sizes), 2 error or bad usage. */
int main(int argc, char **argv)
{
    const char *paths[2] = { NULL, NULL }, *out_path = NULL, *edges_path = NULL;
    int npaths = 0;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            compare_usage(stdout);
            return 0;
        } else if (strcmp(a, "-o") == 0 || strcmp(a, "--edges") == 0) {
            if (k + 1 == argc || argv[k + 1][0] == '\0') {
                fprintf(stderr, "compare: %s needs a file name\n", a);
                compare_usage(stderr);
                return 2;
            }
            *(a[1] == 'o' ? &out_path : &edges_path) = argv[++k];
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "compare: unknown option '%.40s'\n", a);
            compare_usage(stderr);
            return 2;
        } else if (npaths == 2) {
            fprintf(stderr, "compare: more than two images given\n");
            compare_usage(stderr);
            return 2;
        } else {
            paths[npaths++] = a;
        }
    }
    if (npaths != 2) {
        fprintf(stderr, "compare: give two images, the submission's and the reference\n");
        compare_usage(stderr);
        return 2;
    }

    char err[512];
    Image sub, ref;
    if (image_read(&sub, paths[0], err, sizeof err) < 0) {
        fprintf(stderr, "compare: %s\n", err);
        return 2;
    }
    if (image_read(&ref, paths[1], err, sizeof err) < 0) {
        fprintf(stderr, "compare: %s\n", err);
        image_free(&sub);
        return 2;
    }
    int status;
    if (sub.width != ref.width || sub.height != ref.height) {
        fprintf(stderr, "compare: the images differ in size: %s is %dx%d, %s is %dx%d\n",
                paths[0], sub.width, sub.height, paths[1], ref.width, ref.height);
        status = 1;
    } else if (edges_path && compare_edges(edges_path, &sub, &ref, err, sizeof err) < 0) {
        fprintf(stderr, "compare: %s\n", err);
        status = 2;
    } else {
        CompareStats st = compare_measure(&sub, &ref);
        compare_report(&st, paths[0], paths[1], sub.width, sub.height);
        status = st.differing ? 1 : 0;
        if (out_path) {
            if (compare_write_side_by_side(&sub, &ref, out_path, err, sizeof err) < 0) {
                fprintf(stderr, "compare: %s\n", err);
                status = 2;
            } else {
                printf("wrote %s\n", out_path);
            }
        }
    }
    image_free(&sub);
    image_free(&ref);
    return status;
}
