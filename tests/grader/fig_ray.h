/*
 * fig_ray.h - the side view of a ray, shared by the figures of Parts 3a,
 * 3b (colours) and 4.
 *
 * The view is a plane that holds the ray: the ray runs from e (left) to the
 * right along the axis, a = the distance along the ray (a = t |r|), and b
 * is the distance from the ray's line.  A sphere is drawn in the plane
 * through the ray and its centre, where it is a circle of its own radius
 * (its great circle): the ray meets the sphere exactly where it meets that
 * circle.  With several spheres each is turned about the ray into the one
 * drawing plane, so all of them are drawn above the axis.  A plane is drawn
 * edge on, in the plane of the ray and the plane's normal.
 */
#ifndef FIG_RAY_H
#define FIG_RAY_H

#include <stdbool.h>
#include "markup.h"

#define RAYFIG_MAX_CIRCLES 64

typedef struct {
    double a, b, R;            /* centre (a along the ray, b >= 0 off it), radius */
    char fill[8];              /* its colour, "#rrggbb"                           */
    char label[24];            /* drawn beside it ("" for none)                   */
} RayCircle;

typedef struct {
    const char *title;         /* above the drawing                               */
    double rlen;               /* |r|: a hit at t is drawn at a = t |r|           */
    int ncircles;
    RayCircle circles[RAYFIG_MAX_CIRCLES];
    int target;                /* the circle the hits are about, or -1            */
    bool has_line;             /* a plane, edge on: the points with               */
    double line_A, line_B, line_C;   /* A a + B b = C; (A, B) is its normal       */
    bool want_hit;             /* the expected answer: a hit at want_t, or a miss */
    double want_t;
    bool got_known;            /* the submission answered                         */
    bool got_hit;              /* its answer: a hit at got_t, or a miss           */
    double got_t;
    const char *want_text;     /* the legend's words (NULL: "expected hit ...")   */
    const char *got_text;
    const char *note;          /* a line under the legend, or NULL                */
    char want_buf[120];        /* want_text's words, where ray_answers makes them */
} RayFig;

/* Fills the frame of a sphere (centre c, radius R) seen from the ray
 * e + t r: its circle's a, b.  Returns |r| (0 when r is zero or not
 * finite).  *dist gets |c - e| (scaled, so that tiny and huge lengths do
 * not underflow or overflow). */
double ray_frame_sphere(const double e[3], const double r[3], const double c[3], double *a,
                        double *b, double *dist);

/* The length of v, without overflow or underflow; the dot product a . b. */
double ray_norm(const double v[3]);
double ray_dot(const double a[3], const double b[3]);

/* The smaller root t > 0 of the ray and the sphere, computed in double
 * (for display); false when the ray misses it or it lies behind. */
bool ray_sphere_t(const double e[3], const double r[3], const double c[3], double R, double *t);

/* Fills f's answers from a case's: want[0] nonzero for a hit at want[1];
 * got NULL for no answer, else got[0] 1 for a hit at got[1], 0 for a miss,
 * and any other value "neither true nor false" (f->got_text).  either:
 * NULL, or why a miss is right too (the legend then says "expected: a hit
 * (WHY: a miss is right too)", or a miss). */
void ray_answers(RayFig *f, const double want[2], const double *got, const char *either);

/* Draws the figure (an inline <svg>). */
void ray_figure(Markup *m, const RayFig *f);

#endif
