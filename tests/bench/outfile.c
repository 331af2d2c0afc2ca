/*
 * outfile.c - see outfile.h.
 */
#include "outfile.h"

/* path's temporary file's name into tmp (len bytes); false when too long. */
static int out_tmp(const char *path, char *tmp, size_t len)
{
    int n = snprintf(tmp, len, "%s.tmp", path);
    return n > 0 && (size_t)n < len;
}

FILE *out_open(const char *path, char *err, size_t errlen)
{
    char tmp[1200];
    FILE *f = out_tmp(path, tmp, sizeof tmp) ? fopen(tmp, "w") : NULL;
    if (!f)
        snprintf(err, errlen, "%s: cannot write", path);
    return f;
}

int out_close(FILE *f, const char *path, char *err, size_t errlen)
{
    char tmp[1200];
    out_tmp(path, tmp, sizeof tmp);
    if (fclose(f) != 0 || rename(tmp, path) != 0) {
        remove(tmp);
        snprintf(err, errlen, "%s: write failed", path);
        return -1;
    }
    return 0;
}
