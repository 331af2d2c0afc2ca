/*
 * htmlcheck - checks that an HTML page is well formed and self-contained,
 * for the tests of the grader's report page (tests/suites/report.sh).
 *
 *     htmlcheck PAGE.html
 *
 * Checks, and says where each failure is (file:line: what):
 *   - the page starts with <!DOCTYPE html>;
 *   - every element is closed, in order (the void elements of HTML --
 *     img, meta, br ... -- need no end tag; inside <svg> an element may
 *     close itself with "/>", outside it only a void element may);
 *   - every attribute value is quoted, no attribute appears twice in a tag,
 *     every id is unique;
 *   - "&" in text starts a character reference, "<" starts a tag;
 *   - no <script>, no on... event attribute, no javascript: address;
 *   - every src and href is a data: URI (base64 that decodes; a PNG one
 *     must start with the PNG signature), a #fragment naming an id of the
 *     page, or a relative path to a file that exists beside the page (its
 *     %XX read as the byte XX, as a browser reads them) --
 *     never an address on the network (a scheme such as http: or https:,
 *     or one starting with //); the style sheet loads nothing (no url(),
 *     no @import).
 * Prints "figures N" (the <figure> elements of class "case"), "images N"
 * and "elements N", then "ok" or the number of problems.  Exit status: 0
 * when the page passes, 1 when it does not, 2 on bad usage.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <ctype.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>
#include "base64.h"

#define MAX_DEPTH 256
#define MAX_IDS   20000

static const char *path;
static const char *text;
static size_t len;
static int problems;
static char dir[4096];

/* The line of text[at]. */
static int line_of(size_t at)
{
    int line = 1;
    for (size_t k = 0; k < at && k < len; k++)
        line += text[k] == '\n';
    return line;
}

/* Reports a problem at text[at] (the first 50 are printed), and counts it. */
static void problem(size_t at, const char *what, const char *detail)
{
    if (problems < 50)
        fprintf(stderr, "%s:%d: %s%s%s\n", path, line_of(at), what, detail ? ": " : "",
                detail ? detail : "");
    problems++;
}

/* The first place of needle in hay, ignoring case (strcasestr is not
 * POSIX); NULL when there is none. */
static const char *find_ci(const char *hay, const char *needle)
{
    size_t n = strlen(needle);
    for (; *hay; hay++)
        if (strncasecmp(hay, needle, n) == 0)
            return hay;
    return NULL;
}

/* Whether HTML's element name has no end tag. */
static bool is_void(const char *name)
{
    static const char *const v[] = { "area", "base", "br", "col", "embed", "hr", "img", "input",
                                     "link", "meta", "source", "track", "wbr", NULL };
    for (int k = 0; v[k]; k++)
        if (strcmp(name, v[k]) == 0)
            return true;
    return false;
}

static char *ids[MAX_IDS];
static size_t id_at[MAX_IDS];
static int nids;
/* Fragment links, checked once every id is known. */
static char *frags[MAX_IDS];
static size_t frag_at[MAX_IDS];
static int nfrags;

/* The path v[0 .. n) with each %XX turned into its byte, as a browser
 * reads an address, into out (n + 1 bytes); false when a % is not
 * followed by two hexadecimal digits, or stands for a NUL. */
static bool percent_decoded(const char *v, size_t n, char *out)
{
    for (size_t k = 0; k < n; k++) {
        if (v[k] != '%') {
            *out++ = v[k];
            continue;
        }
        if (k + 2 >= n)
            return false;
        if (!isxdigit((unsigned char)v[k + 1]) || !isxdigit((unsigned char)v[k + 2]))
            return false;
        char hex[3] = { v[k + 1], v[k + 2], '\0' };
        long byte = strtol(hex, NULL, 16);
        if (byte == 0)
            return false;
        *out++ = (char)byte;
        k += 2;
    }
    *out = '\0';
    return true;
}

/* Checks the address v of a src or href attribute: a data: URI that
 * decodes, a #fragment (checked at the end), or a file beside the page. */
static void check_address(const char *attr, const char *v, size_t at)
{
    if (strncasecmp(v, "data:", 5) == 0) {
        const char *comma = strchr(v, ',');
        if (!comma) {
            problem(at, "a data: URI without a comma", attr);
            return;
        }
        size_t meta = (size_t)(comma - v), n = 0;
        if (meta < 7 || strncmp(comma - 7, ";base64", 7) != 0)
            return;
        char err[100];
        unsigned char *data = base64_decode(comma + 1, strlen(comma + 1), &n, err, sizeof err);
        if (!data)
            problem(at, "a data: URI whose base64 is not valid", attr);
        else if (strncmp(v, "data:image/png", 14) == 0 && (n < 8 || memcmp(data, "\x89PNG\r\n\x1a\n", 8) != 0))
            problem(at, "a data: URI that says PNG but is not one", attr);
        free(data);
        return;
    }
    if (v[0] == '#') {
        if (nfrags < MAX_IDS) {
            frags[nfrags] = strdup(v + 1);
            frag_at[nfrags++] = at;
        }
        return;
    }
    if (strncmp(v, "//", 2) == 0) {
        problem(at, "an address on the network", v);
        return;
    }
    for (const char *p = v; *p && *p != '/' && *p != '?' && *p != '#'; p++)
        if (*p == ':') {
            problem(at, "an address with a scheme (only data: and relative paths are allowed)", v);
            return;
        }
    if (!*v) {
        problem(at, "an empty address", attr);
        return;
    }
    char file[8192];
    size_t n = strcspn(v, "?#");
    int at_name = snprintf(file, sizeof file, "%s/", dir);
    if (at_name < 0 || (size_t)at_name + n >= sizeof file || !percent_decoded(v, n, file + at_name))
        problem(at, "an address with a % not followed by two hexadecimal digits", v);
    else if (access(file, R_OK) != 0)
        problem(at, "a file the page refers to is missing", v);
}

/* Checks that every & in text[from .. to-1] starts a character reference. */
static void check_text_refs(size_t from, size_t to)
{
    for (size_t k = from; k < to; k++) {
        if (text[k] != '&')
            continue;
        size_t j = k + 1;
        if (j < to && text[j] == '#') {
            j++;
            bool hex = j < to && (text[j] == 'x' || text[j] == 'X');
            j += hex;
            size_t d = j;
            while (j < to && (hex ? isxdigit((unsigned char)text[j]) : isdigit((unsigned char)text[j])))
                j++;
            if (j == d || j >= to || text[j] != ';')
                problem(k, "a & that does not start a character reference", NULL);
        } else {
            size_t d = j;
            while (j < to && isalnum((unsigned char)text[j]))
                j++;
            if (j == d || j >= to || text[j] != ';')
                problem(k, "a & that does not start a character reference (write &amp;)", NULL);
        }
    }
}


/* The elements open, innermost last, and what the page holds. */
static char stack[MAX_DEPTH][32];
static size_t stack_at[MAX_DEPTH];
static int depth, svg_depth, figures, images, elements;

/* A tag as read: <name ...>, </name>, or <name .../>. */
typedef struct {
    char name[32];
    size_t at;                  /* where its < is */
    bool closing, self_close, is_case;
} Tag;

/* Checks the attribute an="v" of tag (v may be changed). */
static void check_attribute(Tag *tag, const char *an, char *v)
{
    if (tag->closing)
        problem(tag->at, "an end tag with attributes", tag->name);
    if (strncmp(an, "on", 2) == 0)
        problem(tag->at, "an event attribute (JavaScript)", an);
    if (find_ci(v, "javascript:"))
        problem(tag->at, "a javascript: address", an);
    if (strcmp(an, "id") == 0) {
        for (int q = 0; q < nids; q++)
            if (strcmp(ids[q], v) == 0) {
                char msg[200];
                snprintf(msg, sizeof msg, "%.60s (first at line %d)", v, line_of(id_at[q]));
                problem(tag->at, "an id used twice", msg);
            }
        if (nids < MAX_IDS) {
            ids[nids] = strdup(v);
            id_at[nids++] = tag->at;
        }
    }
    if (strcmp(an, "src") == 0 || strcmp(an, "href") == 0 || strcmp(an, "xlink:href") == 0) {
        check_address(an, v, tag->at);
        images += strcmp(tag->name, "img") == 0 || strcmp(tag->name, "image") == 0;
    }
    if (strcmp(an, "class") == 0 && strcmp(tag->name, "figure") == 0)
        for (char *w = strtok(v, " \t\n"); w; w = strtok(NULL, " \t\n"))
            tag->is_case = tag->is_case || strcmp(w, "case") == 0;
}

/* Reads tag's attributes from text[p] to its > (or />); returns the place
 * after it, or 0 when the tag is broken and the page cannot be read on. */
static size_t read_attributes(Tag *tag, size_t p)
{
    char seen[64][40];
    int nseen = 0;
    while (p < len) {
        while (p < len && isspace((unsigned char)text[p]))
            p++;
        if (text[p] == '>')
            return p + 1;
        if (text[p] == '/' && text[p + 1] == '>') {
            tag->self_close = true;
            return p + 2;
        }
        char an[40];
        size_t al = 0;
        while (p < len && !isspace((unsigned char)text[p]) && text[p] != '=' && text[p] != '>'
               && text[p] != '/' && al < 39)
            an[al++] = (char)tolower((unsigned char)text[p++]);
        an[al] = '\0';
        if (al == 0) {
            problem(p, "a broken tag", tag->name);
            return 0;
        }
        for (int q = 0; q < nseen; q++)
            if (strcmp(seen[q], an) == 0)
                problem(p, "an attribute given twice", an);
        if (nseen < 64)
            strcpy(seen[nseen++], an);
        if (text[p] != '=') {
            problem(p, "an attribute without a quoted value", an);
            continue;
        }
        char quote = text[++p];
        if (quote != '"' && quote != '\'') {
            problem(p, "an attribute value that is not quoted", an);
            while (p < len && !isspace((unsigned char)text[p]) && text[p] != '>')
                p++;
            continue;
        }
        const char *end = memchr(text + p + 1, quote, len - p - 1);
        if (!end) {
            problem(p, "an attribute value that never ends", an);
            return 0;
        }
        size_t vfrom = p + 1, vto = (size_t)(end - text);
        check_text_refs(vfrom, vto);
        char *v = strndup(text + vfrom, vto - vfrom);
        if (v)
            check_attribute(tag, an, v);
        free(v);
        p = vto + 1;
    }
    return p;
}

/* An end tag: closes the element open innermost, or says it is out of
 * order and closes up to the element it names, if one is open. */
static void close_element(const Tag *tag)
{
    if (depth == 0 || strcmp(stack[depth - 1], tag->name) != 0) {
        char msg[120];
        snprintf(msg, sizeof msg, "</%s> where %s%s%s is open", tag->name, depth ? "<" : "nothing",
                 depth ? stack[depth - 1] : "", depth ? ">" : "");
        problem(tag->at, "an end tag out of order", msg);
        for (int q = depth - 1; q >= 0; q--)
            if (strcmp(stack[q], tag->name) == 0) {
                depth = q;
                break;
            }
    } else {
        depth--;
    }
    if (strcmp(tag->name, "svg") == 0 && svg_depth > 0)
        svg_depth--;
}

/* An element of raw text (style, script, textarea; title outside SVG):
 * returns the place after its end tag, or 0 when it never ends.  A style
 * sheet must load nothing. */
static size_t skip_raw_text(const Tag *tag, size_t k)
{
    char endtag[40];
    snprintf(endtag, sizeof endtag, "</%s>", tag->name);
    const char *end = find_ci(text + k, endtag);
    if (!end) {
        problem(tag->at, "an element that never ends", tag->name);
        return 0;
    }
    if (strcmp(tag->name, "style") == 0) {
        char *css = strndup(text + k, (size_t)(end - text) - k);
        if (css && (find_ci(css, "url(") || find_ci(css, "@import") || strstr(css, "//")))
            problem(tag->at, "the style sheet loads something (url(), @import or //)", NULL);
        free(css);
    }
    return (size_t)(end - text) + strlen(endtag);
}

/* The tag at text[k], which is '<': reads and checks it; returns the place
 * after it (after its raw text, for style and the like), or 0 when the
 * page cannot be read on. */
static size_t read_tag(size_t k)
{
    Tag tag = { .at = k, .closing = text[k + 1] == '/' };
    size_t p = k + 1 + tag.closing, nl = 0;
    while (p < len && (isalnum((unsigned char)text[p]) || text[p] == '-' || text[p] == ':') && nl < 31)
        tag.name[nl++] = (char)tolower((unsigned char)text[p++]);
    tag.name[nl] = '\0';
    if (nl == 0) {
        problem(k, "a < that does not start a tag (write &lt;)", NULL);
        return k + 1;
    }
    p = read_attributes(&tag, p);
    if (p == 0)
        return 0;
    if (strcmp(tag.name, "script") == 0)
        problem(k, "a <script> (the page must need no JavaScript)", NULL);
    if (tag.closing) {
        close_element(&tag);
        return p;
    }
    elements++;
    figures += strcmp(tag.name, "figure") == 0 && tag.is_case;
    if (tag.self_close) {
        if (!svg_depth && !is_void(tag.name))
            problem(k, "a non-void element closed with />, which HTML ignores", tag.name);
        return p;
    }
    if (!svg_depth && is_void(tag.name))
        return p;
    if (strcmp(tag.name, "svg") == 0)
        svg_depth++;
    if (strcmp(tag.name, "style") == 0 || strcmp(tag.name, "script") == 0 || strcmp(tag.name, "textarea") == 0
        || (strcmp(tag.name, "title") == 0 && !svg_depth))
        return skip_raw_text(&tag, p);
    if (depth == MAX_DEPTH) {
        problem(k, "elements nested too deep", tag.name);
        return 0;
    }
    snprintf(stack[depth], sizeof stack[depth], "%s", tag.name);
    stack_at[depth++] = k;
    return p;
}

/* The page at path, whole and NUL-terminated, in text and len. */
static char *read_page(void)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "htmlcheck: cannot open %s\n", path);
        return NULL;
    }
    size_t cap = 1 << 20, n;
    char *buf = malloc(cap + 1);
    len = 0;
    while (buf && (n = fread(buf + len, 1, cap - len, f)) > 0) {
        len += n;
        if (len == cap) {
            char *grown = realloc(buf, 2 * cap + 1);
            if (!grown)
                free(buf);
            buf = grown;
            cap *= 2;
        }
    }
    fclose(f);
    if (!buf)
        fprintf(stderr, "htmlcheck: out of memory\n");
    else
        buf[len] = '\0';
    return buf;
}

/* Checks the page named; the exit status says whether it passed. */
int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: htmlcheck PAGE.html\n");
        return 2;
    }
    path = argv[1];
    char *buf = read_page();
    if (!buf)
        return 1;
    text = buf;
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = '\0';
    else
        snprintf(dir, sizeof dir, ".");

    size_t k = 0;
    if (strncasecmp(text, "<!DOCTYPE html>", 15) == 0)
        k = 15;
    else
        problem(0, "the page does not start with <!DOCTYPE html>", NULL);
    size_t text_from = k;
    while (k < len) {
        if (text[k] != '<') {
            k++;
            continue;
        }
        check_text_refs(text_from, k);
        if (strncmp(text + k, "<!--", 4) == 0) {
            const char *end = strstr(text + k + 4, "-->");
            if (!end) {
                problem(k, "a comment that never ends", NULL);
                break;
            }
            k = (size_t)(end - text) + 3;
        } else if ((k = read_tag(k)) == 0) {
            break;
        }
        text_from = k;
    }
    check_text_refs(text_from, len);
    for (int q = depth - 1; q >= 0; q--)
        problem(stack_at[q], "an element that is never closed", stack[q]);
    for (int q = 0; q < nfrags; q++) {
        bool found = false;
        for (int r = 0; r < nids && !found; r++)
            found = strcmp(ids[r], frags[q]) == 0;
        if (!found)
            problem(frag_at[q], "a link to an id the page does not have", frags[q]);
        free(frags[q]);
    }
    for (int q = 0; q < nids; q++)
        free(ids[q]);
    printf("figures %d\nimages %d\nelements %d\n", figures, images, elements);
    if (problems)
        printf("%d problem%s\n", problems, problems == 1 ? "" : "s");
    else
        printf("ok\n");
    free(buf);
    return problems ? 1 : 0;
}
