/*
 * edges.c - see edges.h.
 */
#include "edges.h"

#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "savefile.h"
#include "textfile.h"

void edges_free(Edges *edges)
{
    free(edges->pixels);
    edges->pixels = NULL;
    edges->count = 0;
}

/* Appends pixel to edges, growing its array; false when memory ran out. */
static bool edges_push(Edges *edges, size_t *capacity, const EdgePixel *pixel)
{
    if (edges->count == *capacity) {
        size_t more = *capacity ? 2 * *capacity : 64;
        EdgePixel *grown = realloc(edges->pixels, more * sizeof *grown);
        if (!grown)
            return false;
        edges->pixels = grown;
        *capacity = more;
    }
    edges->pixels[edges->count++] = *pixel;
    return true;
}

/* Adds rgb to pixel's other colours unless it is its own colour (own) or
 * one of them already. */
static void edges_add_other(EdgePixel *pixel, const unsigned char *own, const unsigned char *rgb)
{
    if (memcmp(rgb, own, 3) == 0)
        return;
    for (int k = 0; k < pixel->nother; k++)
        if (memcmp(pixel->other[k], rgb, 3) == 0)
            return;
    memcpy(pixel->other[pixel->nother++], rgb, 3);
}

int edges_find(Edges *edges, const Image *img, const Image nudged[4], char *err, size_t errlen)
{
    size_t capacity = 0;
    edges->width = img->width;
    edges->height = img->height;
    edges->count = 0;
    edges->pixels = NULL;
    for (int j = 0; j < img->height; j++)
        for (int i = 0; i < img->width; i++) {
            size_t at = 3 * ((size_t)j * (size_t)img->width + (size_t)i);
            EdgePixel pixel = { i, j, 0, { { 0 } } };
            for (int k = 0; k < 4; k++)
                edges_add_other(&pixel, img->rgb + at, nudged[k].rgb + at);
            if (pixel.nother > 0 && !edges_push(edges, &capacity, &pixel)) {
                edges_free(edges);
                return kit_fail(err, errlen, "out of memory for the pixels on an edge");
            }
        }
    return 0;
}

int edges_write(const Edges *edges, const char *path, char *err, size_t errlen)
{
    /* "i j" and four colours: at most 11 + 4 * 13 + 1 characters a line */
    size_t size = 256 + 80 * edges->count, len = 0;
    char *text = malloc(size);
    if (!text)
        return kit_fail(err, errlen, "%s: out of memory", path);
    len += (size_t)snprintf(text, size,
                            "# The pixels on an edge (labs/kit/edges.h): drawn with their centre\n"
                            "# moved by 2^-30 of the image plane, they take another colour.\n"
                            "# i j, then each other colour as r g b (0..255).\n"
                            "size %d %d\n", edges->width, edges->height);
    for (size_t n = 0; n < edges->count; n++) {
        const EdgePixel *p = &edges->pixels[n];
        len += (size_t)snprintf(text + len, size - len, "%d %d", p->i, p->j);
        for (int k = 0; k < p->nother; k++)
            len += (size_t)snprintf(text + len, size - len, "  %d %d %d", p->other[k][0],
                                    p->other[k][1], p->other[k][2]);
        len += (size_t)snprintf(text + len, size - len, "\n");
    }
    int status = kit_save_file(path, text, len, err, errlen);
    free(text);
    return status;
}

/* Reads word k of ln as a whole number in lo .. hi into *value.  Returns
 * 0, or -1 with a message naming the file, the line and what was wanted. */
static int edges_int(const TextLine *ln, int k, long lo, long hi, const char *what, int *value,
                     char *err, size_t errlen)
{
    char *end, quoted[TEXT_QUOTE_SIZE];
    errno = 0;
    long n = strtol(ln->words[k], &end, 10);
    if (*end != '\0' || end == ln->words[k] || errno != 0 || n < lo || n > hi)
        return text_error(err, errlen, ln->name, ln->line,
                          "%s: '%s' is not a whole number from %ld to %ld",
                          what, text_quote(ln->words[k], quoted), lo, hi);
    *value = (int)n;
    return 0;
}

/* Reads one pixel's line into pixel, checking it against edges' size and
 * the pixel before it (prev, or NULL). */
static int edges_read_pixel(const Edges *edges, const TextLine *ln, const EdgePixel *prev,
                            EdgePixel *pixel, char *err, size_t errlen)
{
    int n = ln->nwords;
    if (n < 5 || n > 2 + 3 * EDGES_MAX_OTHER || (n - 2) % 3 != 0)
        return text_error(err, errlen, ln->name, ln->line,
                          "a pixel on an edge is 'i j' and 1 to %d colours 'r g b' (%d words here)",
                          EDGES_MAX_OTHER, n);
    if (edges_int(ln, 0, 0, edges->width - 1, "the column i", &pixel->i, err, errlen) < 0
        || edges_int(ln, 1, 0, edges->height - 1, "the row j", &pixel->j, err, errlen) < 0)
        return -1;
    if (prev && (pixel->j < prev->j || (pixel->j == prev->j && pixel->i <= prev->i)))
        return text_error(err, errlen, ln->name, ln->line,
                          "pixel (%d, %d) comes after (%d, %d): pixels go in row order, each once",
                          pixel->i, pixel->j, prev->i, prev->j);
    pixel->nother = (n - 2) / 3;
    for (int k = 0; k < 3 * pixel->nother; k++) {
        int byte;
        if (edges_int(ln, 2 + k, 0, 255, "a colour", &byte, err, errlen) < 0)
            return -1;
        pixel->other[k / 3][k % 3] = (unsigned char)byte;
    }
    return 0;
}

/* Reads the lines of text (from path) into edges. */
static int edges_parse(Edges *edges, const char *path, const char *text, char *err, size_t errlen)
{
    char buf[TEXT_MAX_LINE + 1];
    const char *pos = text;
    TextLine ln = { path, 0, { NULL }, 0 };
    size_t capacity = 0;
    bool sized = false;
    int status;
    while ((status = text_next_line(&pos, buf, &ln, err, errlen)) > 0) {
        if (ln.nwords == 0)
            continue;
        if (!sized) {
            if (ln.nwords != 3 || strcmp(ln.words[0], "size") != 0)
                return text_error(err, errlen, path, ln.line,
                                  "the first line must be 'size WIDTH HEIGHT'");
            if (edges_int(&ln, 1, 1, IMAGE_MAX_SIDE, "size", &edges->width, err, errlen) < 0
                || edges_int(&ln, 2, 1, IMAGE_MAX_SIDE, "size", &edges->height, err, errlen) < 0)
                return -1;
            sized = true;
            continue;
        }
        EdgePixel pixel = { 0, 0, 0, { { 0 } } };
        const EdgePixel *prev = edges->count ? &edges->pixels[edges->count - 1] : NULL;
        if (edges_read_pixel(edges, &ln, prev, &pixel, err, errlen) < 0)
            return -1;
        if (!edges_push(edges, &capacity, &pixel))
            return text_error(err, errlen, path, ln.line, "out of memory");
    }
    if (status == 0 && !sized)
        return text_error(err, errlen, path, 0, "no 'size WIDTH HEIGHT' line: not a file of edges");
    return status;
}

int edges_read(Edges *edges, const char *path, char *err, size_t errlen)
{
    char *text;
    memset(edges, 0, sizeof *edges);
    if (text_read_file(path, &text, err, errlen) < 0)
        return -1;
    int status = edges_parse(edges, path, text, err, errlen);
    free(text);
    if (status < 0)
        edges_free(edges);
    return status;
}

long long edges_accept(const Edges *edges, const Image *sub, Image *ref)
{
    long long taken = 0;
    for (size_t n = 0; n < edges->count; n++) {
        const EdgePixel *p = &edges->pixels[n];
        size_t at = 3 * ((size_t)p->j * (size_t)ref->width + (size_t)p->i);
        if (memcmp(sub->rgb + at, ref->rgb + at, 3) == 0)
            continue;
        for (int k = 0; k < p->nother; k++)
            if (memcmp(sub->rgb + at, p->other[k], 3) == 0) {
                memcpy(ref->rgb + at, p->other[k], 3);
                taken++;
                break;
            }
    }
    return taken;
}
