/*
 * outfile.h - the bench's output files, each written whole: to a temporary
 * file beside it, renamed into place once closed, so that none is ever
 * left half-written.
 */
#ifndef BENCH_OUTFILE_H
#define BENCH_OUTFILE_H

#include <stddef.h>
#include <stdio.h>

/* Opens path's temporary file (path with ".tmp" after it) for writing.
 * Returns it, or NULL with "path: cannot write" in err. */
FILE *out_open(const char *path, char *err, size_t errlen);

/* Closes f, opened by out_open(path), and renames it over path.  Returns
 * 0, or -1 with "path: write failed" in err and the temporary file gone. */
int out_close(FILE *f, const char *path, char *err, size_t errlen);

#endif
