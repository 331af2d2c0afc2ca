/*
 * savefile.h - writing a whole file so that it is never left half-written,
 * and reading a whole file back.
 */
#ifndef KIT_SAVEFILE_H
#define KIT_SAVEFILE_H

#include <stddef.h>
#include <stdio.h>

#include "zlib.h"

/* Writes n bytes of data to a temporary file beside path, gives it the mode
 * a new file would get (0666 less the umask), closes it and renames it over
 * path.  Returns 0, or -1 with "path: reason" in err and no temporary file
 * left behind. */
int kit_save_file(const char *path, const void *data, size_t n, char *err, size_t errlen);
/* The same with mode, less the umask, instead of 0666 (0600: the owner's
 * alone). */
int kit_save_file_mode(const char *path, const void *data, size_t n, unsigned mode, char *err,
                       size_t errlen);

/* Writes all n bytes of data to fd, retrying after interruptions and short
 * writes.  Returns 0, or -1 with errno set. */
int kit_write_all(int fd, const void *data, size_t n);

/* Appends the whole file at path to out, at most max bytes.  Returns 0, or
 * -1 with "path: reason" in err; a file larger than max has the reason
 * too_large. */
int kit_read_file(const char *path, size_t max, const char *too_large, KitBuf *out,
                  char *err, size_t errlen);

/* Reads the whole regular file at path, any bytes, into a fresh buffer with
 * a NUL after them, and sets *len to their number.  NULL when it cannot be
 * opened, is not a regular file, holds more than max bytes, changed while
 * it was read, or memory runs out.  (Text to parse: text_read_file.) */
char *kit_load_file(const char *path, size_t max, size_t *len);

/* The same from a stream already open (one opened with care, say: no
 * links), which it closes. */
char *kit_load_stream(FILE *f, size_t max, size_t *len);

#endif
