/*
 * archive.c - ZIP archives: building, encoding, decoding and
 * extracting them.  See archive.h.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */

#include "archive.h"
#include "../../labs/kit/savefile.h"
#include "../../labs/kit/textfile.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* ZIP record signatures and fields (APPNOTE 4.3, 4.4). */
#define ZIP_LOCAL_SIG    0x04034b50u
#define ZIP_CENTRAL_SIG  0x02014b50u
#define ZIP_END_SIG      0x06054b50u
#define ZIP_LOCAL_SIZE   30
#define ZIP_CENTRAL_SIZE 46
#define ZIP_END_SIZE     22
#define ZIP_MADE_BY      ((3u << 8) | 20u)      /* Unix, specification 2.0 */
#define ZIP_FLAG_UTF8    0x0800u
#define ZIP_DOS_TIME     0u                       /* 00:00:00            */
#define ZIP_DOS_DATE     ((40u << 9) | (1u << 5) | 1u)   /* 2020-01-01   */
#define ZIP_MAX32        0xFFFFFFFFu

/* Unix file types as stored in ZIP external attributes. */
#define UNIX_TYPE_MASK   0170000u
#define UNIX_TYPE_FILE   0100000u
#define UNIX_TYPE_DIR    0040000u
#define UNIX_TYPE_LINK   0120000u

/* ---- small helpers ------------------------------------------------------------ */

/* Little-endian numbers, as ZIP stores them. */
static void arc_put16(unsigned char *p, unsigned v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
}

static void arc_put32(unsigned char *p, uint32_t v)
{
    arc_put16(p, v & 0xFFFFu);
    arc_put16(p + 2, v >> 16);
}

static unsigned arc_get16(const unsigned char *p)
{
    return p[0] | (unsigned)p[1] << 8;
}

static uint32_t arc_get32(const unsigned char *p)
{
    return arc_get16(p) | (uint32_t)arc_get16(p + 2) << 16;
}

/* "a/b" (or just b when a is empty), malloc'd; NULL if memory runs out. */
static char *arc_join(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    char *s = malloc(la + lb + 2);
    if (!s)
        return NULL;
    if (la) {
        memcpy(s, a, la);
        s[la++] = '/';
    }
    memcpy(s + la, b, lb + 1);
    return s;
}

/* kit_read_file, at most ARCHIVE_MAX_SIZE bytes. */
static int arc_read_file(const char *path, KitBuf *out, char *err, size_t errlen)
{
    char too_large[64];
    snprintf(too_large, sizeof too_large, "larger than %zu bytes", ARCHIVE_MAX_SIZE);
    return kit_read_file(path, ARCHIVE_MAX_SIZE, too_large, out, err, errlen);
}

/* ---- entries -------------------------------------------------------------------- */

/* Starts an empty archive. */
void archive_init(Archive *a)
{
    a->entries = NULL;
    a->count = 0;
    a->cap = 0;
}

/* Frees every entry and the list. */
void archive_free(Archive *a)
{
    for (size_t k = 0; k < a->count; k++) {
        free(a->entries[k].path);
        free(a->entries[k].data);
    }
    free(a->entries);
    archive_init(a);
}

/* Relative, no empty, "." or ".." component, no backslash. */
bool archive_path_ok(const char *path)
{
    if (!path || path[0] == '\0' || path[0] == '/')
        return false;
    const char *p = path;
    for (;;) {
        const char *end = strchr(p, '/');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len == 0 || (len == 1 && p[0] == '.') || (len == 2 && p[0] == '.' && p[1] == '.') ||
            memchr(p, '\\', len))
            return false;
        if (!end)
            return true;
        p = end + 1;
    }
}

/* Adds an entry, copying path and data.  Returns 0, or -1 with a reason. */
static int arc_add(Archive *a, const char *path, bool is_dir, const void *data, size_t size,
                   unsigned mode, char *err, size_t errlen)
{
    if (!archive_path_ok(path))
        return kit_fail(err, errlen, "unsafe or invalid path in an archive: \"%s\" (paths must be "
                        "relative, without empty, . or .. parts)", path ? path : "(null)");
    if (size > ARCHIVE_MAX_SIZE)
        return kit_fail(err, errlen, "%s: larger than %zu bytes", path, ARCHIVE_MAX_SIZE);
    for (size_t k = 0; k < a->count; k++)
        if (strcmp(a->entries[k].path, path) == 0)
            return kit_fail(err, errlen, "%s: appears twice in the archive", path);
    if (a->count == a->cap) {
        size_t cap = a->cap ? 2 * a->cap : 16;
        ArchiveEntry *e = realloc(a->entries, cap * sizeof *e);
        if (!e)
            return kit_fail(err, errlen, "out of memory");
        a->entries = e;
        a->cap = cap;
    }
    ArchiveEntry e = {strdup(path), is_dir, mode & 0777u, NULL, size};
    if (size > 0)
        e.data = malloc(size);
    if (!e.path || (size > 0 && !e.data)) {
        free(e.path);
        free(e.data);
        return kit_fail(err, errlen, "out of memory");
    }
    if (size > 0)
        memcpy(e.data, data, size);
    a->entries[a->count++] = e;
    return 0;
}

/* Adds a file.  Returns 0, or -1 with a reason. */
int archive_add_file(Archive *a, const char *path, const void *data, size_t size,
                     unsigned mode, char *err, size_t errlen)
{
    return arc_add(a, path, false, data, size, mode, err, errlen);
}

/* Adds a directory.  Returns 0, or -1 with a reason. */
int archive_add_dir(Archive *a, const char *path, unsigned mode, char *err, size_t errlen)
{
    return arc_add(a, path, true, NULL, 0, mode, err, errlen);
}

/* Orders names by their bytes (for qsort). */
static int arc_cmp_names(const void *x, const void *y)
{
    return strcmp(*(char *const *)x, *(char *const *)y);
}

/* The names in directory disk other than . and .., sorted, in a malloc'd
 * array of malloc'd strings.  Returns 0, or -1 with a reason. */
static int arc_list_dir(const char *disk, char ***names, size_t *count, char *err, size_t errlen)
{
    DIR *d = opendir(disk);
    *names = NULL;
    *count = 0;
    if (!d)
        return kit_fail(err, errlen, "%s: cannot open directory: %s", disk, strerror(errno));
    size_t cap = 0;
    int rc = 0;
    struct dirent *e;
    errno = 0;
    while (rc == 0 && (e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (*count == cap) {
            cap = cap ? 2 * cap : 16;
            char **grown = realloc(*names, cap * sizeof *grown);
            if (!grown) {
                rc = kit_fail(err, errlen, "out of memory");
                break;
            }
            *names = grown;
        }
        if (((*names)[*count] = strdup(e->d_name)) == NULL)
            rc = kit_fail(err, errlen, "out of memory");
        else
            (*count)++;
        errno = 0;
    }
    if (rc == 0 && errno != 0)
        rc = kit_fail(err, errlen, "%s: cannot read directory: %s", disk, strerror(errno));
    closedir(d);
    if (*count > 1)
        qsort(*names, *count, sizeof **names, arc_cmp_names);
    return rc;
}

/* Adds the contents of directory disk, whose path in the archive is inside
 * ("" for the root), recursively.  Returns 0, or -1 with a reason. */
static int arc_walk(Archive *a, const char *disk, const char *inside, char *err, size_t errlen)
{
    char **names;
    size_t count;
    int rc = arc_list_dir(disk, &names, &count, err, errlen);
    for (size_t k = 0; k < count && rc == 0; k++) {
        char *full = arc_join(disk, names[k]), *path = arc_join(inside, names[k]);
        struct stat st;
        KitBuf data = {0};
        if (!full || !path)
            rc = kit_fail(err, errlen, "out of memory");
        else if (lstat(full, &st) != 0)
            rc = kit_fail(err, errlen, "%s: %s", full, strerror(errno));
        else if (S_ISDIR(st.st_mode))
            rc = archive_add_dir(a, path, (unsigned)st.st_mode, err, errlen) == 0 &&
                 arc_walk(a, full, path, err, errlen) == 0 ? 0 : -1;
        else if (S_ISREG(st.st_mode))
            rc = arc_read_file(full, &data, err, errlen) == 0 &&
                 archive_add_file(a, path, data.data, data.len, (unsigned)st.st_mode,
                                  err, errlen) == 0 ? 0 : -1;
        else
            rc = kit_fail(err, errlen, "%s: not a regular file or directory (links and special "
                          "files are not archived)", full);
        kit_buf_free(&data);
        free(full);
        free(path);
    }
    for (size_t k = 0; k < count; k++)
        free(names[k]);
    free(names);
    return rc;
}

/* Adds dir's contents.  Returns 0, or -1 with a reason. */
int archive_add_tree(Archive *a, const char *dir, char *err, size_t errlen)
{
    struct stat st;
    if (stat(dir, &st) != 0)
        return kit_fail(err, errlen, "%s: %s", dir, strerror(errno));
    if (!S_ISDIR(st.st_mode))
        return kit_fail(err, errlen, "%s: not a directory", dir);
    return arc_walk(a, dir, "", err, errlen);
}

/* ---- ZIP ------------------------------------------------------------------------------ */

/* The name an entry has in a ZIP: directories end in '/'.  malloc'd. */
static char *zip_name(const ArchiveEntry *e)
{
    size_t len = strlen(e->path);
    char *name = malloc(len + 2);
    if (name) {
        memcpy(name, e->path, len);
        name[len] = '/';
        name[e->is_dir ? len + 1 : len] = '\0';
    }
    return name;
}

/* Whether s has a byte outside ASCII (then the name is flagged UTF-8). */
static bool zip_non_ascii(const char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s >= 0x80)
            return true;
    return false;
}

/* Appends one entry's local header and data to body and its central
 * directory record to central.  Returns 0, or -1 with a reason. */
static int zip_put_entry(const ArchiveEntry *e, KitBuf *body, KitBuf *central,
                         char *err, size_t errlen)
{
    char *name = zip_name(e);
    KitBuf packed = {0};
    if (!name)
        return kit_fail(err, errlen, "out of memory");
    size_t nlen = strlen(name);
    const unsigned char *payload = e->data;
    size_t psize = e->size;
    unsigned method = 0;
    int rc = 0;
    if (e->size > 0 && e->size < ZIP_MAX32) {     /* a larger one is refused below */
        if (kit_deflate(e->data, e->size, &packed) != 0)
            rc = kit_fail(err, errlen, "out of memory");
        else if (packed.len < e->size) {
            payload = packed.data;
            psize = packed.len;
            method = 8;
        }
    }
    if (rc == 0 && (nlen > 0xFFFFu || psize >= ZIP_MAX32 || e->size >= ZIP_MAX32 ||
                    body->len >= ZIP_MAX32))
        rc = kit_fail(err, errlen, "%s: too large for a ZIP archive without ZIP64", e->path);
    if (rc == 0) {
        unsigned char lh[ZIP_LOCAL_SIZE], ch[ZIP_CENTRAL_SIZE];
        unsigned version = method == 8 || e->is_dir ? 20 : 10;
        unsigned flags = zip_non_ascii(name) ? ZIP_FLAG_UTF8 : 0;
        uint32_t crc = kit_crc32(0, e->data, e->size);
        uint32_t type = e->is_dir ? UNIX_TYPE_DIR : UNIX_TYPE_FILE;
        arc_put32(lh, ZIP_LOCAL_SIG);
        arc_put16(lh + 4, version);
        arc_put16(lh + 6, flags);
        arc_put16(lh + 8, method);
        arc_put16(lh + 10, ZIP_DOS_TIME);
        arc_put16(lh + 12, ZIP_DOS_DATE);
        arc_put32(lh + 14, crc);
        arc_put32(lh + 18, (uint32_t)psize);
        arc_put32(lh + 22, (uint32_t)e->size);
        arc_put16(lh + 26, (unsigned)nlen);
        arc_put16(lh + 28, 0);                       /* no extra field */
        arc_put32(ch, ZIP_CENTRAL_SIG);
        arc_put16(ch + 4, ZIP_MADE_BY);
        memcpy(ch + 6, lh + 4, 26);                  /* version needed .. name length */
        arc_put16(ch + 30, 0);                       /* extra field length */
        arc_put16(ch + 32, 0);                       /* comment length */
        arc_put16(ch + 34, 0);                       /* disk number */
        arc_put16(ch + 36, 0);                       /* internal attributes */
        arc_put32(ch + 38, ((type | e->mode) << 16) | (e->is_dir ? 0x10u : 0u));
        arc_put32(ch + 42, (uint32_t)body->len);     /* local header offset */
        if (kit_buf_append(body, lh, sizeof lh) != 0 || kit_buf_append(body, name, nlen) != 0 ||
            kit_buf_append(body, payload, psize) != 0 ||
            kit_buf_append(central, ch, sizeof ch) != 0 || kit_buf_append(central, name, nlen) != 0)
            rc = kit_fail(err, errlen, "out of memory");
    }
    kit_buf_free(&packed);
    free(name);
    return rc;
}

/* Local headers with data, then the central directory and its end record,
 * all appended at once.  Returns 0, or -1 with a reason (out as it was). */
int archive_encode(const Archive *a, KitBuf *out, char *err, size_t errlen)
{
    KitBuf central = {0};
    size_t start = out->len;
    int rc = 0;
    if (a->count >= 0xFFFFu)
        return kit_fail(err, errlen, "too many entries for a ZIP archive without ZIP64");
    /* offsets count from the start of the archive: build it in its own buffer */
    KitBuf body = {0};
    for (size_t k = 0; k < a->count && rc == 0; k++)
        rc = zip_put_entry(&a->entries[k], &body, &central, err, errlen);
    if (rc == 0 && (body.len >= ZIP_MAX32 || central.len >= ZIP_MAX32))
        rc = kit_fail(err, errlen, "too large for a ZIP archive without ZIP64");
    if (rc == 0) {
        unsigned char end[ZIP_END_SIZE];
        arc_put32(end, ZIP_END_SIG);
        arc_put16(end + 4, 0);                       /* this disk */
        arc_put16(end + 6, 0);                       /* disk with the directory */
        arc_put16(end + 8, (unsigned)a->count);
        arc_put16(end + 10, (unsigned)a->count);
        arc_put32(end + 12, (uint32_t)central.len);
        arc_put32(end + 16, (uint32_t)body.len);
        arc_put16(end + 20, 0);                      /* no comment */
        if (kit_buf_append(out, body.data, body.len) != 0 ||
            kit_buf_append(out, central.data, central.len) != 0 ||
            kit_buf_append(out, end, sizeof end) != 0) {
            out->len = start;
            rc = kit_fail(err, errlen, "out of memory");
        }
    }
    kit_buf_free(&body);
    kit_buf_free(&central);
    return rc;
}

/* Finds the end of central directory record (the last one whose comment
 * reaches exactly to the end).  Returns its offset, or -1. */
static long long zip_find_end(const unsigned char *p, size_t n)
{
    if (n < ZIP_END_SIZE)
        return -1;
    for (size_t at = n - ZIP_END_SIZE;; at--) {
        if (arc_get32(p + at) == ZIP_END_SIG && at + ZIP_END_SIZE + arc_get16(p + at + 20) == n)
            return (long long)at;
        if (at == 0 || n - at >= ZIP_END_SIZE + 0xFFFFu)
            return -1;
    }
}

/* The entry's type and mode from a central directory record's "version
 * made by" and external attributes; is_dir may already be set by a name
 * ending in '/'.  Returns 0, or -1 for links and special files. */
static int zip_entry_mode(unsigned made_by, uint32_t external, bool *is_dir, unsigned *mode)
{
    uint32_t unix_mode = external >> 16;
    *mode = *is_dir ? 0755u : 0644u;
    if ((made_by >> 8) != 3 || unix_mode == 0)
        return 0;
    uint32_t type = unix_mode & UNIX_TYPE_MASK;
    if (type == UNIX_TYPE_DIR)
        *is_dir = true;
    else if (type != UNIX_TYPE_FILE && type != 0)
        return -1;
    *mode = unix_mode & 0777u;
    return 0;
}

/* Reads one entry whose central directory record is at cd (with room for
 * its fixed part), its data before data_end; adds it to a and counts its
 * size into *total.  Returns the record's length, or -1 with a reason. */
static long long zip_read_entry(Archive *a, const unsigned char *p, size_t cd, size_t cd_end,
                                size_t data_end, size_t *total, const ArchiveLimits *lim,
                                char *err, size_t errlen)
{
    const unsigned char *c = p + cd;
    if (arc_get32(c) != ZIP_CENTRAL_SIG)
        return kit_fail(err, errlen, "ZIP central directory is corrupt");
    unsigned made_by = arc_get16(c + 4), flags = arc_get16(c + 8), method = arc_get16(c + 10);
    uint32_t crc = arc_get32(c + 16), csize = arc_get32(c + 20), usize = arc_get32(c + 24);
    size_t nlen = arc_get16(c + 28), rest = nlen + arc_get16(c + 30) + arc_get16(c + 32);
    uint32_t external = arc_get32(c + 38), local = arc_get32(c + 42);
    if (rest > cd_end - cd - ZIP_CENTRAL_SIZE)
        return kit_fail(err, errlen, "ZIP central directory is truncated");
    if (nlen == 0 || memchr(c + ZIP_CENTRAL_SIZE, 0, nlen))
        return kit_fail(err, errlen, "ZIP entry with an empty or invalid name");
    char *name = malloc(nlen + 1);
    if (!name)
        return kit_fail(err, errlen, "out of memory");
    memcpy(name, c + ZIP_CENTRAL_SIZE, nlen);
    name[nlen] = '\0';
    bool is_dir = name[nlen - 1] == '/';
    if (is_dir)
        name[nlen - 1] = '\0';
    unsigned mode;
    KitBuf data = {0};
    size_t at = 0;
    int rc = 0;
    if (zip_entry_mode(made_by, external, &is_dir, &mode) != 0)
        rc = kit_fail(err, errlen, "%s: a link or special file (not supported)", name);
    else if (flags & 1u)
        rc = kit_fail(err, errlen, "%s: encrypted (not supported)", name);
    else if (csize == ZIP_MAX32 || usize == ZIP_MAX32 || local == ZIP_MAX32)
        rc = kit_fail(err, errlen, "%s: ZIP64 entries are not supported", name);
    else if (usize > lim->max_unpacked - *total)
        rc = kit_fail(err, errlen, "%s: the archive unpacks to more than %zu MiB", name,
                      lim->max_unpacked >> 20);
    else if (usize > ARCHIVE_RATIO_FREE && usize / lim->max_ratio > csize)
        rc = kit_fail(err, errlen, "%s: unpacks to %lu bytes from %lu, more than %u times as many "
                      "(a zip bomb?)", name, (unsigned long)usize, (unsigned long)csize, lim->max_ratio);
    else if (local > data_end || data_end - local < ZIP_LOCAL_SIZE ||
             arc_get32(p + local) != ZIP_LOCAL_SIG)
        rc = kit_fail(err, errlen, "%s: ZIP local header missing or corrupt", name);
    else {
        at = local + ZIP_LOCAL_SIZE + arc_get16(p + local + 26) + arc_get16(p + local + 28);
        if (at > data_end || csize > data_end - at)
            rc = kit_fail(err, errlen, "%s: ZIP data is truncated", name);
    }
    if (rc == 0 && is_dir && usize != 0)
        rc = kit_fail(err, errlen, "%s: a directory entry with data", name);
    if (rc == 0 && method == 0) {
        if (csize != usize || kit_buf_append(&data, p + at, csize) != 0)
            rc = kit_fail(err, errlen, "%s: stored entry is corrupt", name);
    } else if (rc == 0 && method == 8) {
        char why[200];
        if (kit_inflate(p + at, csize, usize, &data, NULL, why, sizeof why) != 0)
            rc = kit_fail(err, errlen, "%s: %s", name, why);
        else if (data.len != usize)
            rc = kit_fail(err, errlen, "%s: unpacks to %zu bytes, not %lu", name, data.len,
                          (unsigned long)usize);
    } else if (rc == 0) {
        rc = kit_fail(err, errlen, "%s: compression method %u is not supported", name, method);
    }
    if (rc == 0 && kit_crc32(0, data.data, data.len) != crc)
        rc = kit_fail(err, errlen, "%s: CRC-32 mismatch (the archive is corrupt)", name);
    if (rc == 0)
        rc = arc_add(a, name, is_dir, data.data, data.len, mode, err, errlen);
    if (rc == 0)
        *total += data.len;
    kit_buf_free(&data);
    free(name);
    return rc == 0 ? (long long)(ZIP_CENTRAL_SIZE + rest) : -1;
}

/* Reads the end record, then every entry of the central directory.
 * Returns 0, or -1 with a reason. */
static int zip_decode(Archive *a, const unsigned char *p, size_t n, const ArchiveLimits *lim,
                      char *err, size_t errlen)
{
    long long end = zip_find_end(p, n);
    if (end < 0)
        return kit_fail(err, errlen, "not a ZIP archive (no end of central directory record)");
    const unsigned char *e = p + end;
    unsigned count = arc_get16(e + 10);
    uint32_t cd_size = arc_get32(e + 12), cd_off = arc_get32(e + 16);
    if (arc_get16(e + 4) != 0 || arc_get16(e + 6) != 0 || arc_get16(e + 8) != count)
        return kit_fail(err, errlen, "multi-disk ZIP archives are not supported");
    if (count == 0xFFFFu || cd_size == ZIP_MAX32 || cd_off == ZIP_MAX32)
        return kit_fail(err, errlen, "ZIP64 archives are not supported");
    if (cd_off > (size_t)end || cd_size > (size_t)end - cd_off)
        return kit_fail(err, errlen, "ZIP central directory is out of bounds");
    size_t at = cd_off, cd_end = (size_t)cd_off + cd_size, total = 0;
    for (unsigned k = 0; k < count; k++) {
        if (cd_end - at < ZIP_CENTRAL_SIZE)
            return kit_fail(err, errlen, "ZIP central directory is truncated");
        long long len = zip_read_entry(a, p, at, cd_end, cd_off, &total, lim, err, errlen);
        if (len < 0)
            return -1;
        at += (size_t)len;
    }
    return 0;
}

/* ---- whole archives -------------------------------------------------------------------- */

/* Encodes, then writes a temporary file beside path (given the mode a new
 * file would get) and renames it over path.  Returns 0, or -1 with
 * "path: reason". */
int archive_save(const Archive *a, const char *path, char *err, size_t errlen)
{
    KitBuf bytes = {0};
    char why[512];
    if (archive_encode(a, &bytes, why, sizeof why) != 0) {
        kit_buf_free(&bytes);
        return kit_fail(err, errlen, "%s: %s", path, why);
    }
    int status = kit_save_file(path, bytes.data, bytes.len, err, errlen);
    kit_buf_free(&bytes);
    return status;
}

/* ARCHIVE_MAX_SIZE, and any ratio. */
static const ArchiveLimits archive_no_limits = { ARCHIVE_MAX_SIZE, ARCHIVE_MAX_SIZE };

/* Decodes a ZIP, told by its first bytes.  Returns 0, or -1 with
 * a reason (a left empty). */
int archive_decode_within(Archive *a, const void *data, size_t n, const ArchiveLimits *lim,
                          char *err, size_t errlen)
{
    const unsigned char *p = data;
    ArchiveLimits within = *lim;
    if (within.max_unpacked > ARCHIVE_MAX_SIZE || within.max_unpacked < ARCHIVE_RATIO_FREE)
        within.max_unpacked = ARCHIVE_MAX_SIZE;
    if (within.max_ratio < 1)
        within.max_ratio = 1;
    archive_init(a);
    int rc;
    if (n >= 4 && p[0] == 'P' && p[1] == 'K' && ((p[2] == 3 && p[3] == 4) || (p[2] == 5 && p[3] == 6)))
        rc = zip_decode(a, p, n, &within, err, errlen);
    else
        rc = kit_fail(err, errlen, "not a ZIP archive");
    if (rc != 0)
        archive_free(a);
    return rc;
}

int archive_decode(Archive *a, const void *data, size_t n, char *err, size_t errlen)
{
    return archive_decode_within(a, data, n, &archive_no_limits, err, errlen);
}

int archive_load(Archive *a, const char *path, char *err, size_t errlen)
{
    return archive_load_within(a, path, &archive_no_limits, err, errlen);
}

/* Reads the file, then decodes it.  Returns 0, or -1 with "path: reason". */
int archive_load_within(Archive *a, const char *path, const ArchiveLimits *lim, char *err, size_t errlen)
{
    KitBuf bytes = {0};
    char why[512];
    archive_init(a);
    if (arc_read_file(path, &bytes, err, errlen) != 0) {
        kit_buf_free(&bytes);
        return -1;
    }
    int rc = archive_decode_within(a, bytes.data, bytes.len, lim, why, sizeof why);
    if (rc != 0)
        kit_fail(err, errlen, "%s: %s", path, why);
    kit_buf_free(&bytes);
    return rc;
}

/* ---- extraction ----------------------------------------------------------------------- */

/* Makes sure directory path exists, creating it (mode 0755) if missing;
 * a symbolic link or a non-directory in its place is refused.  Returns 0,
 * or -1 with a reason. */
static int arc_ensure_dir(const char *path, char *err, size_t errlen)
{
    struct stat st;
    if (lstat(path, &st) == 0) {
        if (S_ISLNK(st.st_mode))
            return kit_fail(err, errlen, "%s: refusing to extract through a symbolic link", path);
        if (!S_ISDIR(st.st_mode))
            return kit_fail(err, errlen, "%s: exists and is not a directory", path);
        return 0;
    }
    if (errno != ENOENT || mkdir(path, 0755) != 0)
        return kit_fail(err, errlen, "%s: cannot create directory: %s", path, strerror(errno));
    return 0;
}

/* Creates destdir and its missing parents (links above destdir are
 * followed: destdir is the caller's choice).  Returns 0, or -1. */
static int arc_make_dest(const char *destdir, char *err, size_t errlen)
{
    char *copy = strdup(destdir);
    if (!copy)
        return kit_fail(err, errlen, "out of memory");
    int rc = 0;
    for (char *p = copy + 1; rc == 0; p++) {
        if (*p != '/' && *p != '\0')
            continue;
        char saved = *p;
        *p = '\0';
        struct stat st;
        if (stat(copy, &st) != 0 && (errno != ENOENT || mkdir(copy, 0755) != 0))
            rc = kit_fail(err, errlen, "%s: cannot create directory: %s", copy, strerror(errno));
        else if (stat(copy, &st) == 0 && !S_ISDIR(st.st_mode))
            rc = kit_fail(err, errlen, "%s: not a directory", copy);
        *p = saved;
        if (saved == '\0')
            break;
    }
    free(copy);
    return rc;
}

/* Writes a file entry to full: any old file there is removed first, the
 * new one is created without following links, written and given its
 * mode.  Returns 0, or -1 with a reason. */
static int arc_extract_file(const ArchiveEntry *e, const char *full, char *err, size_t errlen)
{
    struct stat st;
    if (lstat(full, &st) == 0) {
        if (S_ISDIR(st.st_mode))
            return kit_fail(err, errlen, "%s: is a directory", full);
        if (unlink(full) != 0)
            return kit_fail(err, errlen, "%s: cannot replace: %s", full, strerror(errno));
    }
    int fd = open(full, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0600);
    if (fd < 0)
        return kit_fail(err, errlen, "%s: cannot create: %s", full, strerror(errno));
    int failed = kit_write_all(fd, e->data, e->size) != 0 || fchmod(fd, e->mode) != 0;
    int saved = errno;
    if (close(fd) != 0 && !failed) {
        failed = 1;
        saved = errno;
    }
    if (failed)
        return kit_fail(err, errlen, "%s: cannot write: %s", full, strerror(saved));
    return 0;
}

/* Creates the parent directories of entry path below destdir, then the
 * entry itself.  Returns 0, or -1 with a reason. */
static int arc_extract_entry(const ArchiveEntry *e, const char *destdir, char *err, size_t errlen)
{
    char *full = arc_join(destdir, e->path);
    if (!full)
        return kit_fail(err, errlen, "out of memory");
    int rc = 0;
    size_t base = strlen(destdir) + 1;
    for (char *p = full + base; rc == 0 && (p = strchr(p, '/')) != NULL; p++) {
        *p = '\0';
        rc = arc_ensure_dir(full, err, errlen);
        *p = '/';
    }
    if (rc == 0)
        rc = e->is_dir ? arc_ensure_dir(full, err, errlen) : arc_extract_file(e, full, err, errlen);
    free(full);
    return rc;
}

/* Checks every path, creates destdir, writes the entries in order, then
 * gives directories their modes, deepest last-listed first.  Returns 0, or
 * -1 with a reason. */
int archive_extract(const Archive *a, const char *destdir, char *err, size_t errlen)
{
    for (size_t k = 0; k < a->count; k++)
        if (!archive_path_ok(a->entries[k].path))
            return kit_fail(err, errlen, "unsafe path in the archive: \"%s\"", a->entries[k].path);
    if (destdir[0] == '\0')
        destdir = ".";
    if (arc_make_dest(destdir, err, errlen) != 0)
        return -1;
    for (size_t k = 0; k < a->count; k++)
        if (arc_extract_entry(&a->entries[k], destdir, err, errlen) != 0)
            return -1;
    for (size_t k = a->count; k-- > 0;) {
        if (!a->entries[k].is_dir)
            continue;
        char *full = arc_join(destdir, a->entries[k].path);
        if (!full)
            return kit_fail(err, errlen, "out of memory");
        int bad = chmod(full, a->entries[k].mode) != 0;
        if (bad)
            kit_fail(err, errlen, "%s: cannot set its mode: %s", full, strerror(errno));
        free(full);
        if (bad)
            return -1;
    }
    return 0;
}
