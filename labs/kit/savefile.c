/*
 * savefile.c - see savefile.h.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "savefile.h"
#include "textfile.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

int kit_write_all(int fd, const void *data, size_t n)
{
    const unsigned char *p = data;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

int kit_save_file(const char *path, const void *data, size_t n, char *err, size_t errlen)
{
    return kit_save_file_mode(path, data, n, 0666, err, errlen);
}

/* Saves data to path: a temporary file beside it (same directory, so the
 * rename cannot cross file systems), given its permissions, written,
 * closed, then renamed over path.  Returns 0, or -1 with "path: reason" in
 * err and no temporary file left behind. */
int kit_save_file_mode(const char *path, const void *data, size_t n, unsigned mode, char *err,
                       size_t errlen)
{
    const char *slash = strrchr(path, '/');
    size_t dirlen = slash ? (size_t)(slash - path) + 1 : 0;
    static const char pattern[] = ".save-XXXXXX";
    char *tmp = malloc(dirlen + sizeof pattern);
    if (!tmp)
        return kit_fail(err, errlen, "%s: out of memory", path);
    memcpy(tmp, path, dirlen);
    memcpy(tmp + dirlen, pattern, sizeof pattern);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot create a temporary file in its directory: %s",
                 path, strerror(errno));
        free(tmp);
        return -1;
    }
    /* mkstemp makes the file private (0600); give it the mode a newly
     * created file would have (mode less the umask). */
    mode_t mask = umask(022);
    umask(mask);
    const char *what = "cannot write";
    int failed = fchmod(fd, (mode_t)mode & ~mask) != 0 || kit_write_all(fd, data, n) != 0;
    int saved = errno;
    if (close(fd) != 0 && !failed) {
        failed = 1;
        saved = errno;
    }
    if (!failed && rename(tmp, path) != 0) {
        failed = 1;
        saved = errno;
        what = "cannot rename the temporary file to it";
    }
    if (failed) {
        unlink(tmp);
        snprintf(err, errlen, "%s: %s: %s", path, what, strerror(saved));
    }
    free(tmp);
    return failed ? -1 : 0;
}

int kit_read_file(const char *path, size_t max, const char *too_large, KitBuf *out,
                  char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return kit_fail(err, errlen, "%s: cannot open: %s", path, strerror(errno));
    for (;;) {
        if (kit_buf_reserve(out, (size_t)1 << 16) != 0) {
            fclose(f);
            return kit_fail(err, errlen, "%s: out of memory", path);
        }
        size_t got = fread(out->data + out->len, 1, out->cap - out->len, f);
        out->len += got;
        if (out->len > max) {
            fclose(f);
            return kit_fail(err, errlen, "%s: %s", path, too_large);
        }
        if (got == 0)
            break;
    }
    int bad = ferror(f);
    int saved = errno;
    fclose(f);
    if (bad)
        return kit_fail(err, errlen, "%s: cannot read: %s", path, strerror(saved));
    return 0;
}

char *kit_load_file(const char *path, size_t max, size_t *len)
{
    FILE *f = fopen(path, "rb");
    return f ? kit_load_stream(f, max, len) : NULL;
}

char *kit_load_stream(FILE *f, size_t max, size_t *len)
{
    struct stat st;
    char *buf = NULL;
    size_t n = 0;
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && (size_t)st.st_size <= max &&
        (buf = malloc((size_t)st.st_size + 1)) != NULL) {
        n = fread(buf, 1, (size_t)st.st_size, f);
        if (n != (size_t)st.st_size || ferror(f) || getc(f) != EOF) {
            free(buf);                  /* changed while read */
            buf = NULL;
        }
    }
    fclose(f);
    if (!buf)
        return NULL;
    buf[n] = '\0';
    *len = n;
    return buf;
}
