#include "figures.h"
static void stub(Markup *m, const char *what)
{
    fig_begin(m, 720, 80, what);
    svg_text(m, 20, 40, "start", 14, COL_TEXT, false, "%s: figure to come", what);
    fig_end(m);
}
void fig_triangle(Markup *m, const Test *t, const Case *c, const double *got) { (void)t; (void)c; (void)got; stub(m, "triangle"); }
void fig_planehit(Markup *m, const Test *t, const Case *c, const double *got) { (void)t; (void)c; (void)got; stub(m, "planehit"); }
