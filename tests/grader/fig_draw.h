/*
 * fig_draw.h - what every figure of the report page draws with: a window
 * of world coordinates on the page, lines, circles and polygons clipped to
 * it, the figure's frame, short numbers, and the legend.  The lowest of the
 * figure files: fig_ray.c and the figures of each part (figures.h) draw
 * with these, and figures.c picks the part's figure.
 */
#ifndef FIG_DRAW_H
#define FIG_DRAW_H

#include <stdbool.h>
#include <stddef.h>
#include "markup.h"

/* A window of a figure: world coordinates (x right, y up) shown in a
 * rectangle of pixels (y down), at one scale on both axes. */
typedef struct {
    double cx, cy;            /* the world point at the window's centre   */
    double s;                 /* pixels per world unit                    */
    double px0, py0, pw, ph;  /* the window's pixels: corner and size     */
} FigView;

/* Fits the world box [x0, x1] x [y0, y1] (padded by pad of its size on
 * each side) into the pixel box, centred; a box of no size gets unit size. */
void fig_fit(FigView *v, double x0, double y0, double x1, double y1, double pad,
             double px0, double py0, double pw, double ph);
double fig_px(const FigView *v, double x);
double fig_py(const FigView *v, double y);
/* Whether the world point shows inside the window. */
bool fig_inside(const FigView *v, double x, double y);

/* A world line segment, clipped to the window (nothing when outside). */
void fig_segment(Markup *m, const FigView *v, double x1, double y1, double x2, double y2,
                 const char *color, double width, const char *dash);
/* A world circle, clipped to the window; a circle far larger than the
 * window is drawn as the arc that crosses it, computed near the window so
 * that its position stays exact to the pixel.  opacity is the fill's. */
void fig_circle(Markup *m, const FigView *v, double cx, double cy, double R, const char *fill,
                double opacity, const char *stroke, double width);

/* A world polygon of n <= 8 vertices, clipped to the window in double
 * (so that a far vertex of a window zoomed in a million times still puts
 * its edges where they belong). */
void fig_polygon(Markup *m, const FigView *v, const double *wx, const double *wy, int n,
                 const char *fill, double opacity, const char *stroke, double width);

/* Opens the figure's <svg> of width x height pixels (scaled to the page's
 * width), with its title for screen readers; fig_end closes it. */
void fig_begin(Markup *m, double width, double height, const char *title);
void fig_end(Markup *m);
/* Opens a window whose drawing is clipped to it (a nested <svg>), with a
 * frame; fig_window_end closes it and outlines it, in purple if it is a
 * zoomed-in window. */
void fig_window(Markup *m, const FigView *v, const char *frame);
void fig_window_end(Markup *m, const FigView *v, bool zoom);

/* A colour (r, g, b in [0, 1]) as "#rrggbb" in buf (at least 8 bytes). */
const char *fig_hex(char *buf, const double *rgb);
/* A short decimal form of x: %.*g with the digits given, "NaN", "inf". */
const char *fig_num(char *buf, size_t len, double x, int digits);
/* A magnification for people: "230", "4500", "3.8e+12". */
const char *fig_times(char *buf, size_t len, double x);
/* A "nice" step (1, 2 or 5 times a power of ten) near span / n. */
double fig_step(double span, int n);

/* The legend line at the bottom of a figure: the expected marker and
 * text, then the returned marker and text (either may be NULL). */
void fig_legend(Markup *m, double x, double y, const char *want, const char *got);

#endif
