/*
 * ccmemo_direct.c - the compile memo's direct entries (ccmemo_direct.h).
 *
 * An entry is the directory MEMO/direct-HASH, HASH that of its key:
 *   key        the direct key, compared whole
 *   manifest   lines "probe 0 PATH" (no file at PATH) and "probe 1 PATH" (a
 *              file), and "file SIZE PATH" each followed by the file's
 *              SIZE bytes and a newline
 *   object     the object
 *   messages   what the compiler said
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include "ccmemo_direct.h"

#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ccmemo_util.h"
#include "kit/savefile.h"

#define FILE_MAX (256u << 20)     /* as the preprocessed key's KEY_MAX */
#define PATH_LEN 4096

/* The environment the compiler reads: where it looks for headers and
 * programs, and the language and colours of its messages. */
static const char *const env_read[] = {
    "CPATH", "C_INCLUDE_PATH", "GCC_EXEC_PREFIX", "COMPILER_PATH", "SOURCE_DATE_EPOCH",
    "LANG", "LANGUAGE", "LC_ALL", "LC_CTYPE", "LC_MESSAGES", "GCC_COLORS", "GCC_URLS",
};

/* ---- growing buffers and lists ---------------------------------------------------- */

typedef struct {
    char *data;
    size_t len, cap;
    bool bad;
} Buf;

static void buf_add(Buf *b, const void *p, size_t n)
{
    if (b->bad)
        return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = 2 * (b->len + n + 1) + 4096;
        char *grown = realloc(b->data, cap);
        if (!grown) {
            b->bad = true;
            return;
        }
        b->data = grown;
        b->cap = cap;
    }
    memcpy(b->data + b->len, p, n);
    b->len += n;
    b->data[b->len] = '\0';
}

static void buf_str(Buf *b, const char *s)
{
    buf_add(b, s, strlen(s));
}

typedef struct {
    char **items;
    int n, cap;
    bool bad;
} List;

/* The index of s in the list, adding a copy if it is not there; -1 when
 * memory runs out. */
static int list_find_add(List *l, const char *s, size_t n)
{
    for (int k = 0; k < l->n; k++)
        if (strlen(l->items[k]) == n && memcmp(l->items[k], s, n) == 0)
            return k;
    if (l->n == l->cap) {
        int cap = 2 * l->cap + 16;
        char **grown = realloc(l->items, (size_t)cap * sizeof *grown);
        if (!grown) {
            l->bad = true;
            return -1;
        }
        l->items = grown;
        l->cap = cap;
    }
    char *copy = malloc(n + 1);
    if (!copy) {
        l->bad = true;
        return -1;
    }
    memcpy(copy, s, n);
    copy[n] = '\0';
    l->items[l->n] = copy;
    return l->n++;
}

static void list_free(List *l)
{
    for (int k = 0; k < l->n; k++)
        free(l->items[k]);
    free(l->items);
}

/* ---- the key and the entry's name ------------------------------------------------- */

char *direct_key(char *const *args, int nargs, const char *src, size_t *len)
{
    if (getenv("DEPENDENCIES_OUTPUT") || getenv("SUNPRO_DEPENDENCIES"))
        return NULL;
    size_t n;
    char *text = kit_load_file(src, FILE_MAX, &n);
    if (!text)
        return NULL;
    Buf b = { 0 };
    buf_str(&b, "ccmemo direct 1\n");
    for (int k = 0; k < nargs; k++)
        buf_add(&b, args[k], strlen(args[k]) + 1);
    buf_str(&b, "\nenvironment\n");
    for (size_t k = 0; k < sizeof env_read / sizeof env_read[0]; k++) {
        const char *v = getenv(env_read[k]);
        buf_str(&b, env_read[k]);
        if (v) {
            buf_str(&b, "=");
            buf_str(&b, v);
        }
        buf_add(&b, "", 1);
    }
    buf_str(&b, "\nsource\n");
    buf_add(&b, text, n);
    free(text);
    if (b.bad) {
        free(b.data);
        return NULL;
    }
    *len = b.len;
    return b.data;
}

static void entry_name(const char *memo, const char *key, size_t keylen, char *entry, size_t size)
{
    snprintf(entry, size, "%s/direct-%016llx", memo,
             (unsigned long long)ccmemo_fnv1a(key, keylen, 14695981039346656037u));
}

/* ---- serving ---------------------------------------------------------------------- */

/* Whether every probe and every file of the manifest reads as it did. */
static bool manifest_holds(const char *p, const char *end)
{
    char path[PATH_LEN];
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        if (!nl)
            return false;
        if ((strncmp(p, "probe 0 ", 8) == 0 || strncmp(p, "probe 1 ", 8) == 0) &&
            (size_t)(nl - p - 8) < sizeof path) {
            memcpy(path, p + 8, (size_t)(nl - p - 8));
            path[nl - p - 8] = '\0';
            struct stat st;
            if ((stat(path, &st) == 0) != (p[6] == '1'))
                return false;
            p = nl + 1;
            continue;
        }
        if (strncmp(p, "file ", 5) != 0)
            return false;
        char *q;
        unsigned long long size = strtoull(p + 5, &q, 10);
        if (*q != ' ' || (size_t)(nl - q - 1) >= sizeof path)
            return false;
        memcpy(path, q + 1, (size_t)(nl - q - 1));
        path[nl - q - 1] = '\0';
        p = nl + 1;
        if ((unsigned long long)(end - p) < size + 1 || p[size] != '\n')
            return false;
        size_t n;
        char *now = kit_load_file(path, FILE_MAX, &n);
        bool same = now && n == size && memcmp(now, p, n) == 0;
        free(now);
        if (!same)
            return false;
        p += size + 1;
    }
    return true;
}

int direct_use(const char *memo, const char *key, size_t keylen, const char *obj)
{
    char entry[PATH_LEN], path[PATH_LEN + 32];
    entry_name(memo, key, keylen, entry, sizeof entry);
    if (!ccmemo_same_key(entry, key, keylen, FILE_MAX))
        return -1;
    size_t n;
    snprintf(path, sizeof path, "%s/manifest", entry);
    char *manifest = kit_load_file(path, FILE_MAX, &n);
    bool holds = manifest && manifest_holds(manifest, manifest + n);
    free(manifest);
    if (!holds || ccmemo_serve(entry, obj, FILE_MAX, NULL, NULL) != 0)
        return -1;
    utimensat(AT_FDCWD, entry, NULL, 0);   /* used now: tests/run.sh keeps it */
    return 0;
}

/* ---- keeping ---------------------------------------------------------------------- */

/* The files the preprocessor read, from the line markers of its text
 * ('# LINE "PATH" FLAGS'); false for a name the marker escapes. */
static bool read_markers(const char *text, size_t textlen, List *files)
{
    const char *p = text, *end = text + textlen;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        if (!nl)
            nl = end;
        if (nl - p > 4 && p[0] == '#' && p[1] == ' ' && p[2] >= '0' && p[2] <= '9') {
            const char *q = p + 2;
            while (q < nl && *q >= '0' && *q <= '9')
                q++;
            if (q + 2 > nl || q[0] != ' ' || q[1] != '"')
                return false;
            const char *name = q + 2, *close = name;
            while (close < nl && *close != '"' && *close != '\\')
                close++;
            if (close >= nl || *close != '"' || list_find_add(files, name, (size_t)(close - name)) < 0)
                return false;
        }
        p = nl + 1;
    }
    return files->n > 0;
}

/* The compiler's search list (cc ARGS -E -v): the directories it prints,
 * and those it ignores for not existing, which a new directory would add. */
static bool search_list(const char *memo, char *const *args, int nargs, const char *src, List *dirs)
{
    char **argv = calloc((size_t)nargs + 5, sizeof *argv);
    if (!argv)
        return false;
    int n = 0;
    for (int k = 0; k < nargs; k++)
        if (args[k] != src)
            argv[n++] = args[k];
    argv[n++] = "-E";
    argv[n++] = "-v";
    argv[n++] = "-xc";
    argv[n++] = "/dev/null";
    char tmp[PATH_LEN];
    snprintf(tmp, sizeof tmp, "%s/messages.%ld.v", memo, (long)getpid());
    int fd = open(tmp, O_RDWR | O_CREAT | O_TRUNC, 0644), null = open("/dev/null", O_WRONLY);
    int status = fd < 0 || null < 0 ? -1 : ccmemo_run(argv, null, fd);
    free(argv);
    size_t len = 0;
    char *out = status == 0 && lseek(fd, 0, SEEK_SET) == 0 ? ccmemo_slurp_fd(fd, 1 << 20, &len) : NULL;
    if (fd >= 0)
        close(fd);
    if (null >= 0)
        close(null);
    unlink(tmp);
    if (!out)
        return false;
    bool listing = false, ok = false;
    for (char *line = out, *nl; *line; line = nl + 1) {
        nl = strchr(line, '\n');
        if (!nl)
            break;
        *nl = '\0';
        const char *ignored = "ignoring nonexistent directory \"";
        if (strncmp(line, ignored, strlen(ignored)) == 0) {
            char *name = line + strlen(ignored), *close = strchr(name, '"');
            if (close)
                list_find_add(dirs, name, (size_t)(close - name));
        } else if (strstr(line, "search starts here:")) {
            listing = true;
        } else if (strncmp(line, "End of search list.", 19) == 0) {
            ok = listing;
            listing = false;
        } else if (listing && line[0] == ' ') {
            char *name = line + 1, *extra = strstr(name, " (framework directory)");
            size_t n2 = extra ? (size_t)(extra - name) : strlen(name);
            while (n2 > 1 && name[n2 - 1] == '/')
                n2--;
            list_find_add(dirs, name, n2);
        }
    }
    free(out);
    return ok && !dirs->bad;
}

/* The directory of path: "." for a bare name. */
static void dir_of(const char *path, char *dir, size_t size)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, size, ".");
    else if (slash == path)
        snprintf(dir, size, "/");
    else
        snprintf(dir, size, "%.*s", (int)(slash - path), path);
}

/* dir/name, or name alone for ".". */
static bool join(const char *dir, const char *name, char *out, size_t size)
{
    int n = strcmp(dir, ".") == 0 ? snprintf(out, size, "%s", name)
          : strcmp(dir, "/") == 0 ? snprintf(out, size, "/%s", name)
                                  : snprintf(out, size, "%s/%s", dir, name);
    return n > 0 && (size_t)n < size;
}

/* Adds to probes each place where the preprocessor looks for name, asked
 * for from a file in directory from: there first when the name is quoted,
 * then in each directory of the search list. */
static void probe_name(List *probes, const char *from, bool quoted, const List *search,
                       const char *name, size_t n)
{
    char path[PATH_LEN], written[PATH_LEN];
    if (n >= sizeof written) {
        probes->bad = true;
        return;
    }
    memcpy(written, name, n);
    written[n] = '\0';
    if (quoted && (!join(from, written, path, sizeof path) || list_find_add(probes, path, strlen(path)) < 0))
        probes->bad = true;
    for (int k = 0; k < search->n; k++)
        if (!join(search->items[k], written, path, sizeof path) ||
            list_find_add(probes, path, strlen(path)) < 0)
            probes->bad = true;
}

/* After an include or a __has_include at p: the name written, "x" or <x>,
 * probed; false when it is not written out (a macro). */
static bool written_name(const char *p, const char *end, const char *from, const List *search,
                         List *probes)
{
    while (p < end && (*p == ' ' || *p == '\t'))
        p++;
    if (p == end || (*p != '"' && *p != '<'))
        return false;
    char close = *p == '"' ? '"' : '>';
    const char *name = ++p;
    while (p < end && *p != close && *p != '\n')
        p++;
    if (p == end || *p != close || p == name)
        return false;
    probe_name(probes, from, close == '"', search, name, (size_t)(p - name));
    return true;
}

/* Every name the file's text (in directory from) includes or asks for
 * with __has_include, probed; false for one not written out.  Directives
 * in comments or skipped blocks are probed too, which costs only probes. */
static bool probe_includes(const char *text, size_t len, const char *from, const List *search,
                           List *probes)
{
    const char *end = text + len;
    for (const char *line = text; line < end;) {
        const char *nl = memchr(line, '\n', (size_t)(end - line)), *p = line;
        if (!nl)
            nl = end;
        while (p < nl && (*p == ' ' || *p == '\t'))
            p++;
        if (p < nl && (*p == '#' || (p + 1 < nl && p[0] == '%' && p[1] == ':'))) {
            p += *p == '#' ? 1 : 2;
            while (p < nl && (*p == ' ' || *p == '\t'))
                p++;
            if (nl - p >= 7 && strncmp(p, "include", 7) == 0) {
                p += 7;
                if (nl - p >= 5 && strncmp(p, "_next", 5) == 0)
                    p += 5;
                /* "#include's" in a comment is not a directive */
                bool directive = p < nl && (*p == ' ' || *p == '\t' || *p == '"' || *p == '<');
                if (directive && !written_name(p, nl, from, search, probes))
                    return false;
            }
        }
        line = nl + 1;
    }
    const char *word = "__has_include";
    size_t wn = strlen(word);
    for (const char *p = text; (p = memchr(p, '_', (size_t)(end - p))) != NULL;) {
        if ((size_t)(end - p) < wn || strncmp(p, word, wn) != 0) {
            p++;
            continue;
        }
        p += wn;
        if ((size_t)(end - p) >= 5 && strncmp(p, "_next", 5) == 0)
            p += 5;
        while (p < end && (*p == ' ' || *p == '\t'))
            p++;
        if (p == end || *p != '(')
            continue;                            /* "#ifdef __has_include" */
        if (!written_name(p + 1, end, from, search, probes))
            return false;
    }
    return true;
}

static bool has_clock_macro(const char *text, size_t len)
{
    static const char *const macros[] = { "__DATE__", "__TIME__", "__TIMESTAMP__" };
    for (size_t k = 0; k < sizeof macros / sizeof macros[0]; k++) {
        size_t m = strlen(macros[k]);
        for (const char *p = text; (p = memchr(p, '_', (size_t)(text + len - p))) != NULL; p++)
            if ((size_t)(text + len - p) >= m && memcmp(p, macros[k], m) == 0)
                return true;
    }
    return false;
}

/* The manifest: the probes, then the files read with their bytes. */
static bool write_manifest(Buf *m, const List *files, const List *search)
{
    List probes = { 0 };
    bool ok = true;
    for (int f = 0; f < files->n && ok; f++) {
        const char *path = files->items[f];
        if (path[0] == '<')
            continue;                            /* <built-in>, <command-line> */
        size_t n;
        char *text = kit_load_file(path, FILE_MAX, &n), line[64], from[PATH_LEN];
        dir_of(path, from, sizeof from);
        ok = text && !strchr(path, '\n') && !has_clock_macro(text, n) &&
             probe_includes(text, n, from, search, &probes);
        snprintf(line, sizeof line, "file %zu ", n);
        buf_str(m, line);
        buf_str(m, path);
        buf_add(m, "\n", 1);
        buf_add(m, text ? text : "", n);
        buf_add(m, "\n", 1);
        free(text);
    }
    Buf head = { 0 };
    for (int k = 0; ok && k < probes.n; k++) {
        struct stat st;
        if (strchr(probes.items[k], '\n')) {
            ok = false;
            break;
        }
        buf_str(&head, stat(probes.items[k], &st) == 0 ? "probe 1 " : "probe 0 ");
        buf_str(&head, probes.items[k]);
        buf_add(&head, "\n", 1);
    }
    ok = ok && !probes.bad && !head.bad && !m->bad;
    list_free(&probes);
    if (ok) {                                    /* the probes first */
        buf_add(&head, m->data, m->len);
        free(m->data);
        *m = head;
        ok = !m->bad;
    } else {
        free(head.data);
    }
    return ok;
}

/* Removes an entry's directory and the files an entry holds. */
static void remove_entry(const char *dir)
{
    static const char *const parts[] = { "key", "manifest", "object", "messages" };
    char path[PATH_LEN + 128];
    for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, parts[k]);
        unlink(path);
    }
    rmdir(dir);
}

void direct_keep(const char *memo, const char *key, size_t keylen, char *const *args, int nargs,
                 const char *src, const char *text, size_t textlen, const char *obj,
                 const char *messages, size_t mlen)
{
    List files = { 0 }, dirs = { 0 };
    Buf manifest = { 0 };
    size_t on = 0;
    char *o = NULL;
    if (!read_markers(text, textlen, &files) || files.bad ||
        !search_list(memo, args, nargs, src, &dirs) || !write_manifest(&manifest, &files, &dirs) ||
        !(o = kit_load_file(obj, FILE_MAX, &on)))
        goto done;
    char entry[PATH_LEN], tmp[PATH_LEN + 64], old[PATH_LEN + 64], path[PATH_LEN + 96], err[64];
    entry_name(memo, key, keylen, entry, sizeof entry);
    snprintf(tmp, sizeof tmp, "%s.%ld.new", entry, (long)getpid());
    snprintf(old, sizeof old, "%s.%ld.old", entry, (long)getpid());
    if (mkdir(tmp, 0755) != 0)
        goto done;
    bool ok = true;
    snprintf(path, sizeof path, "%s/manifest", tmp);
    ok = ok && kit_save_file(path, manifest.data, manifest.len, err, sizeof err) == 0;
    snprintf(path, sizeof path, "%s/object", tmp);
    ok = ok && kit_save_file(path, o, on, err, sizeof err) == 0;
    snprintf(path, sizeof path, "%s/messages", tmp);
    ok = ok && kit_save_file(path, messages ? messages : "", messages ? mlen : 0, err, sizeof err) == 0;
    snprintf(path, sizeof path, "%s/key", tmp);
    ok = ok && kit_save_file(path, key, keylen, err, sizeof err) == 0;
    /* In place of an entry that no longer holds (a header changed). */
    if (ok && rename(tmp, entry) != 0) {
        ok = rename(entry, old) == 0;
        if (ok) {
            remove_entry(old);
            ok = rename(tmp, entry) == 0;
        }
    }
    if (!ok)
        remove_entry(tmp);
done:
    free(o);
    free(manifest.data);
    list_free(&files);
    list_free(&dirs);
}
