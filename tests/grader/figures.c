/*
 * figures.c - see figures.h: which figure draws a case, by its test's kind.
 */
#include "figures.h"

void figure_case(Markup *m, const Test *t, const TestResult *r, int c, const double *got)
{
    const Case *cs = &t->cases[c];
    switch (t->kind) {
    case KIND_PLANE:    fig_plane(m, t, cs, got); break;
    case KIND_PIXEL:    fig_pixel(m, t, cs, got); break;
    case KIND_SPHERE:   fig_sphere(m, t, cs, got); break;
    case KIND_CAMERA:   fig_camera(m, t, cs, got); break;
    case KIND_COLOR:    fig_color(m, t, cs, got); break;
    case KIND_IMAGE:    fig_image(m, t, r, c); break;
    case KIND_PLANEHIT: fig_planehit(m, t, cs, got); break;
    case KIND_TRIANGLE:
    case KIND_MESH:     fig_triangle(m, t, cs, got); break;
    default:            break;
    }
}
