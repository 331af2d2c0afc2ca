/*
 * markup.h - writing the report page's HTML and SVG into a growable buffer:
 * formatted text, escaped text, data: URIs of PNG images, and the SVG
 * shapes the figures are made of.
 *
 * Every function appends to a KitBuf (labs/kit/zlib.h).  Running out of
 * memory sets the buffer's mk_failed flag (see mk_ok): the caller checks
 * once at the end instead of after every call.
 */
#ifndef MARKUP_H
#define MARKUP_H

#include <stdbool.h>
#include <stddef.h>
#include "kit/image.h"
#include "kit/zlib.h"

typedef struct {
    KitBuf b;
    bool failed;               /* memory ran out somewhere */
} Markup;

void mk_init(Markup *m);
void mk_free(Markup *m);
bool mk_ok(const Markup *m);

/* Appends text formatted as by printf (written as is: no escaping). */
void mk_printf(Markup *m, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Appends raw bytes. */
void mk_raw(Markup *m, const char *s, size_t n);
/* Appends s escaped for HTML and XML text and attribute values (& < > " '),
 * as valid UTF-8: a control character other than newline and tab becomes
 * U+FFFD, and so does each stretch of bytes that is not valid UTF-8 (its
 * maximal subparts, tests/tools/utf8.h).  NULL appends nothing. */
void mk_text(Markup *m, const char *s);
/* The same, formatted as by printf first. */
void mk_textf(Markup *m, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Appends "data:image/png;base64,..." for img.  Returns 0, or -1 when the
 * image could not be encoded (nothing appended). */
int mk_png_uri(Markup *m, const Image *img);
/* Appends "data:image/png;base64,..." for the bytes of a PNG file as they
 * are (a file the caller has decoded, so known to be a PNG). */
void mk_png_bytes_uri(Markup *m, const void *png, size_t n);

/* A number for an SVG coordinate: fixed point with 2 decimals, clamped to
 * +-1e6 so that a figure never holds a value a browser cannot draw. */
double mk_clamp(double v);

/* ---- SVG shapes (coordinates in the figure's pixels, y down) ------------- */

/* A line; dash is NULL or a stroke-dasharray ("5 3"). */
void svg_line(Markup *m, double x1, double y1, double x2, double y2, const char *color,
              double width, const char *dash);
/* An arrow from (x1, y1) to (x2, y2) with its head at the end. */
void svg_arrow(Markup *m, double x1, double y1, double x2, double y2, const char *color,
               double width, const char *dash);
/* A circle; fill and stroke are colours or "none". */
void svg_circle(Markup *m, double cx, double cy, double r, const char *fill, const char *stroke,
                double width);
/* A rectangle. */
void svg_rect(Markup *m, double x, double y, double w, double h, const char *fill,
              const char *stroke, double width);
/* Text; anchor is "start", "middle" or "end"; size in pixels; bold or not.
 * The text is escaped. */
void svg_text(Markup *m, double x, double y, const char *anchor, double size, const char *color,
              bool bold, const char *fmt, ...) __attribute__((format(printf, 8, 9)));

/* The colours of the figures: expected (the reference's answer) and
 * returned (the submission's), and the greys of axes and labels. */
#define COL_WANT  "#1f5fbf"
#define COL_GOT   "#d9480f"
#define COL_AXIS  "#555555"
#define COL_GRID  "#d0d0d0"
#define COL_TEXT  "#222222"
#define COL_NOTE  "#666666"

/* The markers: expected is a filled blue disc, returned an orange ring with
 * a cross, so that the two read apart also without colour. */
void svg_mark_want(Markup *m, double x, double y);
void svg_mark_got(Markup *m, double x, double y);

#endif
