/*
 * markup.c - see markup.h.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "markup.h"
#include "kit/png.h"
#include "../tools/base64.h"
#include "../tools/utf8.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void mk_init(Markup *m)
{
    kit_buf_init(&m->b);
    m->failed = false;
}

void mk_free(Markup *m)
{
    kit_buf_free(&m->b);
    m->failed = false;
}

bool mk_ok(const Markup *m)
{
    return !m->failed;
}

void mk_raw(Markup *m, const char *s, size_t n)
{
    if (kit_buf_append(&m->b, s, n) != 0)
        m->failed = true;
}

/* mk_printf with a va_list: written into the buffer's room, made larger
 * first when the text does not fit (failure sets m->failed). */
static void mk_vprintf(Markup *m, const char *fmt, va_list ap)
{
    va_list again;
    va_copy(again, ap);
    size_t room = m->b.cap - m->b.len;
    int n = vsnprintf(room ? (char *)m->b.data + m->b.len : NULL, room, fmt, ap);
    if (n >= 0 && (size_t)n >= room && kit_buf_reserve(&m->b, (size_t)n + 1) != 0) {
        m->failed = true;
        n = -1;
    } else if (n >= 0 && (size_t)n >= room) {
        vsnprintf((char *)m->b.data + m->b.len, (size_t)n + 1, fmt, again);
    }
    m->b.len += n > 0 ? (size_t)n : 0;
    va_end(again);
}

void mk_printf(Markup *m, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    mk_vprintf(m, fmt, ap);
    va_end(ap);
}

/* What mk_text writes for each of the characters it escapes. */
static const char *const entity[128] = {
    ['&'] = "&amp;", ['<'] = "&lt;", ['>'] = "&gt;", ['"'] = "&quot;", ['\''] = "&#39;",
};

void mk_text(Markup *m, const char *text)
{
    if (!text)
        return;
    const unsigned char *s = (const unsigned char *)text;
    size_t n = strlen(text);
    for (size_t k = 0; k < n;) {
        unsigned char c = s[k];
        int len = c >= 0x80 ? utf8_sequence(s + k, n - k) : 1;
        if (c < 0x80 && entity[c])
            mk_raw(m, entity[c], strlen(entity[c]));
        else if (len > 1 || (c < 0x7F && (c >= 0x20 || c == '\n' || c == '\t')))
            mk_raw(m, text + k, (size_t)len);
        else
            mk_raw(m, "\xEF\xBF\xBD", 3);              /* U+FFFD */
        k += (size_t)(len > 0 ? len : -len);
    }
}

void mk_textf(Markup *m, const char *fmt, ...)
{
    char buf[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    mk_text(m, buf);
}

void mk_png_bytes_uri(Markup *m, const void *png, size_t n)
{
    mk_raw(m, "data:image/png;base64,", 22);
    size_t len = base64_encoded_length(n);
    if (m->failed || kit_buf_reserve(&m->b, len + 1) != 0) {
        m->failed = true;
        return;
    }
    m->b.len += base64_encode(png, n, (char *)m->b.data + m->b.len);
}

int mk_png_uri(Markup *m, const Image *img)
{
    KitBuf png;
    char err[256];
    kit_buf_init(&png);
    if (png_encode(img->width, img->height, img->rgb, &png, err, sizeof err) != 0) {
        kit_buf_free(&png);
        return -1;
    }
    mk_png_bytes_uri(m, png.data, png.len);
    kit_buf_free(&png);
    return 0;
}

double mk_clamp(double v)
{
    if (!(v == v))
        return 0;
    return v > 1e6 ? 1e6 : v < -1e6 ? -1e6 : v;
}

/* ---- SVG --------------------------------------------------------------------- */

void svg_line(Markup *m, double x1, double y1, double x2, double y2, const char *color,
              double width, const char *dash)
{
    mk_printf(m, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
                 "stroke-width=\"%.2g\"", mk_clamp(x1), mk_clamp(y1), mk_clamp(x2), mk_clamp(y2),
              color, width);
    if (dash)
        mk_printf(m, " stroke-dasharray=\"%s\"", dash);
    mk_printf(m, "/>\n");
}

void svg_arrow(Markup *m, double x1, double y1, double x2, double y2, const char *color,
               double width, const char *dash)
{
    x1 = mk_clamp(x1), y1 = mk_clamp(y1), x2 = mk_clamp(x2), y2 = mk_clamp(y2);
    double dx = x2 - x1, dy = y2 - y1, len = hypot(dx, dy);
    if (!(len > 0.5)) {
        svg_circle(m, x2, y2, 2, color, "none", 0);
        return;
    }
    double ux = dx / len, uy = dy / len, head = fmin(9 + 2 * width, 0.6 * len + 3);
    /* the shaft stops where the head begins, so a thick line keeps a sharp point */
    svg_line(m, x1, y1, x2 - ux * head * 0.7, y2 - uy * head * 0.7, color, width, dash);
    mk_printf(m, "<path d=\"M%.2f %.2f L%.2f %.2f L%.2f %.2f Z\" fill=\"%s\"/>\n", x2, y2,
              x2 - ux * head - uy * head * 0.4, y2 - uy * head + ux * head * 0.4,
              x2 - ux * head + uy * head * 0.4, y2 - uy * head - ux * head * 0.4, color);
}

/* A shape's stroke, unless it is "none", and its end. */
static void stroke_end(Markup *m, const char *stroke, double width)
{
    if (strcmp(stroke, "none") != 0)
        mk_printf(m, " stroke=\"%s\" stroke-width=\"%.2g\"", stroke, width);
    mk_printf(m, "/>\n");
}

void svg_circle(Markup *m, double cx, double cy, double r, const char *fill, const char *stroke,
                double width)
{
    mk_printf(m, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\"", mk_clamp(cx),
              mk_clamp(cy), mk_clamp(r), fill);
    stroke_end(m, stroke, width);
}

void svg_rect(Markup *m, double x, double y, double w, double h, const char *fill,
              const char *stroke, double width)
{
    mk_printf(m, "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"",
              mk_clamp(x), mk_clamp(y), mk_clamp(fmax(w, 0)), mk_clamp(fmax(h, 0)), fill);
    stroke_end(m, stroke, width);
}

void svg_text(Markup *m, double x, double y, const char *anchor, double size, const char *color,
              bool bold, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    char attr[48] = "";
    if (strcmp(anchor, "start") != 0)
        snprintf(attr, sizeof attr, " text-anchor=\"%.12s\"", anchor);
    mk_printf(m, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"%.3g\" fill=\"%s\"%s%s>",
              mk_clamp(x), mk_clamp(y), size, color, bold ? " font-weight=\"bold\"" : "", attr);
    mk_text(m, buf);
    mk_printf(m, "</text>\n");
}

void svg_mark_want(Markup *m, double x, double y)
{
    svg_circle(m, x, y, 5.5, COL_WANT, "white", 1.5);
}

void svg_mark_got(Markup *m, double x, double y)
{
    svg_circle(m, x, y, 7.5, "none", COL_GOT, 2.2);
    svg_line(m, x - 4.2, y - 4.2, x + 4.2, y + 4.2, COL_GOT, 2, NULL);      /* and an x across it */
    svg_line(m, x - 4.2, y + 4.2, x + 4.2, y - 4.2, COL_GOT, 2, NULL);
}
