/*
 * outfile.c - every output file written whole (bench.h).
 */
#include "bench.h"

/* dir/name into path and its temporary file's name into tmp (len bytes
 * each); false when too long. */
static int out_paths(const char *dir, const char *name, char *path, char *tmp, size_t len)
{
    snprintf(path, len, "%s/%s", dir, name);
    int n = snprintf(tmp, len, "%s/%s.tmp", dir, name);
    return n > 0 && (size_t)n < len;
}

FILE *out_open(const char *dir, const char *name, char *err, size_t errlen)
{
    char path[1200], tmp[1200];
    FILE *f = out_paths(dir, name, path, tmp, sizeof tmp) ? fopen(tmp, "w") : NULL;
    if (!f)
        snprintf(err, errlen, "%s: cannot write", path);
    return f;
}

int out_close(FILE *f, const char *dir, const char *name, char *err, size_t errlen)
{
    char path[1200], tmp[1200];
    out_paths(dir, name, path, tmp, sizeof tmp);
    if (fclose(f) != 0 || rename(tmp, path) != 0) {
        remove(tmp);
        snprintf(err, errlen, "%s: write failed", path);
        return -1;
    }
    return 0;
}

int out_write(const char *dir, const char *name, void (*body)(FILE *f, const void *data),
              const void *data, char *err, size_t errlen)
{
    FILE *f = out_open(dir, name, err, errlen);
    if (!f)
        return -1;
    body(f, data);
    return out_close(f, dir, name, err, errlen);
}
