/*
 * edges.h - the pixels of a render that lie on an edge, where rounding
 * alone decides the colour.
 *
 * Where two surfaces meet (ground.scene's wall on its ground) or an outline
 * runs exactly through pixel centres (cracks.scene's box), a ray through
 * the centre hits two objects at the same t, or grazes an edge: two correct
 * submissions, whose rays and t differ in the last bits, may draw either
 * colour.  `render --edges FILE` finds such pixels by drawing the scene
 * four more times with every pixel centre moved by EDGES_NUDGE of the
 * image plane (of w to the left and right, of h up and down): some ten
 * million times what rounding moves a centre, and a million times less
 * than a pixel.  A pixel whose colour changes is on an edge, and the
 * colours it takes are its other colours.  `make compare` reads the file of
 * the reference's render and takes a pixel in one of the reference's other
 * colours as equal: a correct submission sees "identical" there, and a
 * wrong one still differs everywhere else.
 *
 * The file, text:
 *
 *     # comments
 *     size 640 480
 *     i j  r g b  [r g b ...]     a pixel on an edge and its other colours
 *
 * pixels in row order, each once, with 1 to EDGES_MAX_OTHER colours as
 * bytes 0..255, none the pixel's own.
 */
#ifndef KIT_EDGES_H
#define KIT_EDGES_H

#include <stddef.h>
#include "image.h"

#define EDGES_NUDGE 0x1p-30        /* of w (x) and of h (y): about 1e-9 */
#define EDGES_MAX_OTHER 4          /* one for each nudged render         */

typedef struct {
    int i, j;                               /* column, row                */
    int nother;                             /* 1 .. EDGES_MAX_OTHER       */
    unsigned char other[EDGES_MAX_OTHER][3];
} EdgePixel;

typedef struct {
    int width, height;
    size_t count;
    EdgePixel *pixels;
} Edges;

/* Fills edges with the pixels of img whose colour in one of the four
 * nudged renders differs from img's.  All five images are the same size.
 * Returns 0, or -1 with a reason in err (memory ran out). */
int edges_find(Edges *edges, const Image *img, const Image nudged[4], char *err, size_t errlen);

/* Writes edges to path (whole, or not at all).  Returns 0, or -1 with a
 * reason naming path in err. */
int edges_write(const Edges *edges, const char *path, char *err, size_t errlen);

/* Reads the file at path into edges.  Returns 0, or -1 with "path:line:
 * reason" in err (edges then holds nothing to free). */
int edges_read(Edges *edges, const char *path, char *err, size_t errlen);

/* For each pixel on an edge where sub differs from ref but has one of its
 * other colours, copies sub's colour into ref: what the reference draws
 * with its ray nudged.  Returns how many pixels it copied.  ref and sub
 * are of edges' size. */
long long edges_accept(const Edges *edges, const Image *sub, Image *ref);

void edges_free(Edges *edges);

#endif
