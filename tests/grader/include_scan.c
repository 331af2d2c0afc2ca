/*
 * include_scan.c - see include_scan.h.
 */
#define _XOPEN_SOURCE 700        /* realpath */
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "include_scan.h"
#include "kit/textfile.h"

#include <ctype.h>
#include <limits.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct {
    const char *s;             /* the text after trigraphs and line splices */
    size_t n, i;
    const char *dir;
    const char *real_dir;      /* dir with its links followed ("" if unknown) */
    char *why;
    size_t whylen;
    int refused;
    IncludeJudge judge;        /* one more judgement of each name, or NULL */
    void *ctx;
    char joined[16];           /* the end of the string literals just read,
                                  decoded and joined as the compiler joins
                                  adjacent ones ("" after any other token) */
} Scan;

/* True for /dev, /proc, /sys and anything under them. */
static bool system_tree(const char *path)
{
    static const char *const trees[] = { "/dev", "/proc", "/sys" };
    for (int k = 0; k < 3; k++) {
        size_t m = strlen(trees[k]);
        if (strncmp(path, trees[k], m) == 0 && (path[m] == '/' || path[m] == '\0'))
            return true;
    }
    return false;
}

bool path_below(const char *path, const char *dir)
{
    size_t m = strlen(dir);
    while (m > 0 && dir[m - 1] == '/')
        m--;                            /* "/" itself: every absolute path */
    return dir[0] && strncmp(path, dir, m) == 0 && (path[m] == '/' || path[m] == '\0');
}

/* path with "//" and "/./" collapsed, into out (at most len bytes). */
static void tidy(const char *path, char *out, size_t len)
{
    size_t o = 0;
    for (size_t k = 0; path[k] && o + 1 < len; k++) {
        if (path[k] == '/' && o > 0 && out[o - 1] == '/')
            continue;
        if (path[k] == '.' && (k == 0 || path[k - 1] == '/') && (path[k + 1] == '/' || path[k + 1] == '\0')) {
            if (path[k + 1] == '/')
                k++;
            continue;
        }
        out[o++] = path[k];
    }
    out[o] = '\0';
}

/* Refuses name (n bytes) with a reason; 1. */
static int refuse(Scan *sc, const char *name, size_t n, const char *reason)
{
    if (!sc->refused)
        snprintf(sc->why, sc->whylen, "the file names \"%.*s\" to the preprocessor, %s", (int)(n > 200 ? 200 : n),
                 name, reason);
    sc->refused = 1;
    return 1;
}

/* Judges one name from a directive; 1 if refused. */
static int check_name(Scan *sc, const char *name, size_t n)
{
    if (n == 0 || n >= PATH_MAX)
        return n ? refuse(sc, name, n, "which is far too long") : 0;
    char raw[PATH_MAX], path[PATH_MAX + PATH_MAX], clean[PATH_MAX + PATH_MAX], real[PATH_MAX];
    memcpy(raw, name, n);
    raw[n] = '\0';
    for (const char *c = raw; *c; c++)
        if (c[0] == '.' && c[1] == '.' && (c == raw || c[-1] == '/') && (c[2] == '/' || c[2] == '\0')) {
            /* A kit header by a path from the student's own folders: name it
             * as the skeleton does (the kit's copy is beside the file). */
            const char *base = strrchr(raw, '/') ? strrchr(raw, '/') + 1 : raw;
            if (!strcmp(base, "raytracer.h") || !strcmp(base, "vec3.h")) {
                char why[160];
                snprintf(why, sizeof why, "which climbs out of the submission's folder with ..: write "
                         "#include \"%s\", as the skeleton does",
                         !strcmp(base, "vec3.h") ? "vec3.h" : "raytracer.h");
                return refuse(sc, name, n, why);
            }
            return refuse(sc, name, n, "which climbs out of the submission's folder with ..");
        }
    if (raw[0] == '/')
        snprintf(path, sizeof path, "%s", raw);
    else
        snprintf(path, sizeof path, "%s/%s", sc->dir, raw);
    tidy(path, clean, sizeof clean);
    /* A relative name (with no ".." in it) stays in the compile directory,
     * and what leads back into it is the grader's own copy: neither is a
     * system file because of where the directory is (TMPDIR=/dev/shm puts
     * it under /dev). */
    if (raw[0] == '/' && system_tree(clean))
        return refuse(sc, name, n, "which is a device or a system file, not a header");
    if (realpath(clean, real) && system_tree(real) && !(sc->real_dir[0] && path_below(real, sc->real_dir)))
        return refuse(sc, name, n, "which leads to a device or a system file, not a header");
    struct stat st;
    if (stat(clean, &st) == 0 && !S_ISREG(st.st_mode))
        return refuse(sc, name, n, S_ISFIFO(st.st_mode) ? "which is a pipe, not a header"
                                   : S_ISDIR(st.st_mode) ? "which is a folder, not a header"
                                                         : "which is a device, not a header");
    const char *reason = sc->judge ? sc->judge(raw, sc->ctx) : NULL;
    return reason ? refuse(sc, name, n, reason) : 0;
}

/* Skips blanks and comments, not newlines. */
static void skip_blank(Scan *sc)
{
    while (sc->i < sc->n) {
        char c = sc->s[sc->i];
        if (c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r') {
            sc->i++;
        } else if (c == '/' && sc->i + 1 < sc->n && sc->s[sc->i + 1] == '*') {
            const char *end = NULL;
            for (size_t k = sc->i + 2; k + 1 < sc->n; k++)
                if (sc->s[k] == '*' && sc->s[k + 1] == '/') {
                    end = sc->s + k;
                    break;
                }
            sc->i = end ? (size_t)(end - sc->s) + 2 : sc->n;
        } else if (c == '/' && sc->i + 1 < sc->n && sc->s[sc->i + 1] == '/') {
            while (sc->i < sc->n && sc->s[sc->i] != '\n')
                sc->i++;
        } else {
            break;
        }
    }
}

static bool ident_start(char c)
{
    return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

static bool ident_char(char c)
{
    return ident_start(c) || (c >= '0' && c <= '9');
}

/* Reads an identifier at sc->i into word (empty if none). */
static void read_ident(Scan *sc, char *word, size_t len)
{
    size_t k = 0;
    while (sc->i < sc->n && ident_char(sc->s[sc->i])) {
        if (k + 1 < len)
            word[k++] = sc->s[sc->i];
        sc->i++;
    }
    word[k] = '\0';
}

/* A header name, "name" or <name>, read verbatim at sc->i and judged. */
static void header_name(Scan *sc)
{
    if (sc->i >= sc->n || (sc->s[sc->i] != '"' && sc->s[sc->i] != '<'))
        return;                         /* a macro: left to the compiler's limits */
    char close = sc->s[sc->i] == '"' ? '"' : '>';
    size_t start = ++sc->i;
    while (sc->i < sc->n && sc->s[sc->i] != close && sc->s[sc->i] != '\n')
        sc->i++;
    if (sc->i < sc->n && sc->s[sc->i] == close) {
        check_name(sc, sc->s + start, sc->i - start);
        sc->i++;
    }
}

/* The byte an escape sequence at s[*k] (just after its backslash) stands
 * for, as the compiler reads it; *k moves past the sequence. */
static char escaped(const char *s, size_t n, size_t *k)
{
    unsigned value = 0;
    int digits = 0;
    if (s[*k] >= '0' && s[*k] <= '7') {
        while (*k < n && digits < 3 && s[*k] >= '0' && s[*k] <= '7')
            value = value * 8 + (unsigned)(s[(*k)++] - '0'), digits++;
        return (char)value;
    }
    if (s[*k] == 'x') {
        for ((*k)++; *k < n && isxdigit((unsigned char)s[*k]); (*k)++)
            value = value * 16 + (unsigned)(isdigit((unsigned char)s[*k]) ? s[*k] - '0'
                                            : tolower((unsigned char)s[*k]) - 'a' + 10);
        return (char)value;
    }
    return s[(*k)++];           /* \n and the like spell no letter of a directive */
}

/* Skips a string or character literal at sc->i.  A string's text, escapes
 * decoded and joined to the strings just before it (".inc" "bin" is one
 * string to the compiler), is refused when it holds an assembler directive
 * that reads a file: .incbin, .include. */
static void literal(Scan *sc)
{
    char q = sc->s[sc->i++];
    size_t keep = strlen(sc->joined);
    char text[16 + 256];
    memcpy(text, sc->joined, keep);
    size_t m = keep;
    while (sc->i < sc->n && sc->s[sc->i] != q && sc->s[sc->i] != '\n') {
        char c = sc->s[sc->i++];
        if (c == '\\' && sc->i < sc->n)
            c = escaped(sc->s, sc->n, &sc->i);
        if (q != '"')
            continue;
        text[m++] = c;
        if (m == sizeof text - 1 || sc->i >= sc->n || sc->s[sc->i] == q || sc->s[sc->i] == '\n') {
            text[m] = '\0';
            for (size_t k = 0; k < m && !sc->refused; k++)
                if ((m - k >= 7 && memcmp(text + k, ".incbin", 7) == 0) ||
                    (m - k >= 8 && memcmp(text + k, ".include", 8) == 0)) {
                    snprintf(sc->why, sc->whylen, "the file uses the assembler's %s, which reads a "
                             "file into the program", text[k + 4] == 'b' ? ".incbin" : ".include");
                    sc->refused = 1;
                }
            keep = m < 15 ? m : 15;     /* the end, for the next piece */
            memmove(text, text + m - keep, keep);
            m = keep;
        }
    }
    if (q == '"') {
        memcpy(sc->joined, text, m);
        sc->joined[m] = '\0';
    } else {
        sc->joined[0] = '\0';
    }
    if (sc->i < sc->n && sc->s[sc->i] == q)
        sc->i++;
}

/* "GCC dependency name" after #pragma or in _Pragma's string. */
static void pragma(Scan *sc)
{
    char w1[16], w2[16];
    skip_blank(sc);
    read_ident(sc, w1, sizeof w1);
    skip_blank(sc);
    read_ident(sc, w2, sizeof w2);
    skip_blank(sc);
    if (strcmp(w1, "GCC") == 0 && strcmp(w2, "dependency") == 0)
        header_name(sc);
}

/* _Pragma ( "string" ): the string, unescaped, is a #pragma line. */
static void destringize_pragma(Scan *sc)
{
    skip_blank(sc);
    if (sc->i >= sc->n || sc->s[sc->i] != '(')
        return;
    sc->i++;
    skip_blank(sc);
    if (sc->i >= sc->n || sc->s[sc->i] != '"')
        return;
    size_t start = sc->i;
    literal(sc);
    size_t end = sc->i;
    char *text = malloc(end - start + 1);
    if (!text)
        return;
    size_t m = 0;
    for (size_t k = start + 1; k + 1 < end; k++) {
        if (sc->s[k] == '\\' && k + 2 < end && (sc->s[k + 1] == '"' || sc->s[k + 1] == '\\'))
            k++;
        text[m++] = sc->s[k];
    }
    Scan inner = { text, m, 0, sc->dir, sc->real_dir, sc->why, sc->whylen, sc->refused, sc->judge, sc->ctx, "" };
    pragma(&inner);
    sc->refused = inner.refused;
    free(text);
}

/* __has_include ( name ) and its kin. */
static void has_include(Scan *sc)
{
    skip_blank(sc);
    if (sc->i < sc->n && sc->s[sc->i] == '(') {
        sc->i++;
        skip_blank(sc);
        header_name(sc);
    }
}

/* The text with trigraphs replaced and backslash-newlines removed (the
 * compiler's first two phases, -std=c11 having trigraphs); n is its length. */
static char *phases_1_2(const char *text, size_t len, size_t *n)
{
    char *out = malloc(len + 1);
    if (!out)
        return NULL;
    static const char from[] = "=/()'<!>-", to[] = "#\\[]^{|}~";
    size_t o = 0;
    for (size_t k = 0; k < len; k++) {
        char c = text[k];
        if (c == '?' && k + 2 < len && text[k + 1] == '?' && text[k + 2] && strchr(from, text[k + 2])) {
            c = to[strchr(from, text[k + 2]) - from];
            k += 2;
        }
        out[o++] = c;
    }
    size_t w = 0;
    for (size_t k = 0; k < o; k++) {
        if (out[k] == '\\') {           /* backslash, blanks, newline: a splice */
            size_t j = k + 1;
            while (j < o && (out[j] == ' ' || out[j] == '\t' || out[j] == '\r'))
                j++;
            if (j < o && out[j] == '\n') {
                k = j;
                continue;
            }
        }
        out[w++] = out[k];
    }
    out[w] = '\0';
    *n = w;
    return out;
}

int include_scan(const char *text, size_t len, const char *dir, char *why, size_t whylen)
{
    return include_scan_judged(text, len, dir, NULL, NULL, why, whylen);
}

int include_scan_judged(const char *text, size_t len, const char *dir, IncludeJudge judge, void *ctx,
                        char *why, size_t whylen)
{
    size_t n = 0;
    char *s = phases_1_2(text, len, &n);
    if (!s) {
        snprintf(why, whylen, "the grader ran out of memory reading the file");
        return 1;
    }
    char real_dir[PATH_MAX];
    if (!realpath(dir, real_dir))
        real_dir[0] = '\0';
    Scan sc = { s, n, 0, dir, real_dir, why, whylen, 0, judge, ctx, "" };
    /* A byte-order mark is skipped, as gcc and clang skip it: what
     * follows starts the line. */
    sc.i = text_bom_length(s, n);
    bool line_start = true;
    while (sc.i < sc.n && !sc.refused) {
        char c = s[sc.i];
        if (c == '\n') {
            line_start = true;
            sc.i++;
        } else if (c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r' ||
                   (c == '/' && sc.i + 1 < n && (s[sc.i + 1] == '*' || s[sc.i + 1] == '/'))) {
            skip_blank(&sc);
        } else if (line_start && (c == '#' || (c == '%' && sc.i + 1 < n && s[sc.i + 1] == ':'))) {
            sc.joined[0] = '\0';
            sc.i += c == '#' ? 1 : 2;
            line_start = false;
            char word[32];
            skip_blank(&sc);
            read_ident(&sc, word, sizeof word);
            skip_blank(&sc);
            if (!strcmp(word, "include") || !strcmp(word, "include_next") || !strcmp(word, "import") ||
                !strcmp(word, "embed"))
                header_name(&sc);
            else if (!strcmp(word, "pragma"))
                pragma(&sc);
        } else if (c == '"' || c == '\'') {
            line_start = false;
            literal(&sc);
        } else if (ident_start(c)) {
            line_start = false;
            char word[32];
            read_ident(&sc, word, sizeof word);
            /* A string's prefix (L"", u8"") keeps it joined to the last. */
            bool prefix = sc.i < n && s[sc.i] == '"' && (!strcmp(word, "L") || !strcmp(word, "u") ||
                                                         !strcmp(word, "U") || !strcmp(word, "u8"));
            if (!prefix)
                sc.joined[0] = '\0';
            if (!strcmp(word, "_Pragma"))
                destringize_pragma(&sc);
            else if (!strcmp(word, "__has_include") || !strcmp(word, "__has_include_next") ||
                     !strcmp(word, "__has_embed"))
                has_include(&sc);
        } else {
            line_start = false;
            sc.joined[0] = '\0';
            sc.i++;
        }
    }
    free(s);
    return sc.refused;
}
