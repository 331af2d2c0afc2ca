/*
 * outfile.h - the bench's output files, each written whole: to a temporary
 * file beside it, renamed into place once closed, so that none is ever
 * left half-written.
 */
#ifndef BENCH_OUTFILE_H
#define BENCH_OUTFILE_H

#include <stddef.h>
#include <stdio.h>

/* Opens dir/name's temporary file (".tmp" after the name) for writing.
 * Returns it, or NULL with "dir/name: cannot write" in err. */
FILE *out_open(const char *dir, const char *name, char *err, size_t errlen);

/* Closes f, opened by out_open(dir, name), and renames it over dir/name.
 * Returns 0, or -1 with "dir/name: write failed" in err and the temporary
 * file gone. */
int out_close(FILE *f, const char *dir, const char *name, char *err, size_t errlen);

/* Writes dir/name whole with body(f, data).  Returns 0, or -1 with err. */
int out_write(const char *dir, const char *name, void (*body)(FILE *f, const void *data),
              const void *data, char *err, size_t errlen);

#endif
