/*
 * archive.h - ZIP archives, in memory: what sort-submissions reads from a
 * class's download and writes back, and Gradescope's autograder.zip.
 *
 * An Archive is a list of entries (files with their bytes and directories,
 * each with a relative path and Unix permission bits).  Fill one with
 * archive_add_file, archive_add_dir and archive_add_tree, then turn it
 * into bytes with archive_encode or into a file with archive_save; or fill
 * one from bytes with archive_decode or from a file with archive_load, then
 * write its entries below a directory with archive_extract.
 *
 * Written archives are reproducible: entries keep the order they were
 * added in (archive_add_tree adds a directory's contents sorted by name)
 * and every time stamp is 2020-01-01 00:00.
 *
 *   ZIP (APPNOTE 6.3): each file deflated when that makes it smaller, else
 *   stored; CRC-32; local headers, central directory, end record; "version
 *   made by" Unix, with the mode in the external attributes, so unzip keeps
 *   the executable bit.  No ZIP64: at most 65535 entries and 4 GiB.
 *
 * Paths in an archive must be relative: not empty, no leading '/', no
 * empty, "." or ".." component, no backslash.  Adding or reading any other
 * path is refused, so extraction never leaves the destination directory.
 * Only files and directories are handled: links and devices are refused.
 */
#ifndef TOOLS_ARCHIVE_H
#define TOOLS_ARCHIVE_H

#include <stdbool.h>
#include <stddef.h>
#include "../../labs/kit/zlib.h"

#define ARCHIVE_MAX_SIZE ((size_t)1 << 30)     /* the most bytes read or unpacked */
#define ARCHIVE_RATIO_FREE ((size_t)1 << 20)   /* bytes any entry may unpack to,
                                                  whatever its ratio           */

/* What reading an archive may unpack: at most max_unpacked bytes in all
 * (up to ARCHIVE_MAX_SIZE), and no entry more than
 * max_ratio times its packed size beyond ARCHIVE_RATIO_FREE: a small
 * archive that would fill the memory or the disk is refused. */
typedef struct {
    size_t max_unpacked;
    unsigned max_ratio;
} ArchiveLimits;

typedef struct {
    char *path;              /* relative, '/'-separated, no trailing '/'   */
    bool is_dir;
    unsigned mode;           /* permission bits, 0 .. 0777                 */
    unsigned char *data;     /* a file's bytes (NULL when size is 0)       */
    size_t size;
} ArchiveEntry;

typedef struct {
    ArchiveEntry *entries;
    size_t count, cap;
} Archive;

/* Starts an empty archive. */
void archive_init(Archive *a);
/* Frees all entries; a is empty afterwards. */
void archive_free(Archive *a);

/* Whether path is acceptable in an archive (see above). */
bool archive_path_ok(const char *path);

/* Adds a file holding a copy of data[0 .. size-1] with permission bits
 * mode & 0777.  Returns 0, or -1 with a reason in err (a bad or repeated
 * path, a file over ARCHIVE_MAX_SIZE, out of memory). */
int archive_add_file(Archive *a, const char *path, const void *data, size_t size,
                     unsigned mode, char *err, size_t errlen);

/* Adds a directory entry.  Returns 0, or -1 with a reason as above. */
int archive_add_dir(Archive *a, const char *path, unsigned mode, char *err, size_t errlen);

/* Adds everything below the directory dir on disk, each directory's
 * entries sorted by name (byte order), with the modes they have on disk,
 * at the archive's root.
 * Returns 0, or -1 with a reason naming the file at fault in err. */
int archive_add_tree(Archive *a, const char *dir, char *err, size_t errlen);

/* Appends the archive's bytes to out.  Returns 0, or -1
 * with a reason in err (out keeps its old length). */
int archive_encode(const Archive *a, KitBuf *out, char *err, size_t errlen);

/* Encodes the archive and writes it to path through a temporary file in
 * the same directory renamed over path.  Returns 0, or -1 with
 * "path: reason" in err (no temporary file left behind). */
int archive_save(const Archive *a, const char *path, char *err, size_t errlen);

/* Reads a ZIP archive from
 * data[0 .. n-1] into a, which is initialised here.  Every CRC and size is
 * checked.  Returns 0, or -1 with a reason in err (a is then empty). */
int archive_decode(Archive *a, const void *data, size_t n, char *err, size_t errlen);
/* The same within limits (ArchiveLimits). */
int archive_decode_within(Archive *a, const void *data, size_t n, const ArchiveLimits *lim,
                          char *err, size_t errlen);

/* archive_decode on the contents of the file at path.  Returns 0, or -1
 * with "path: reason" in err. */
int archive_load(Archive *a, const char *path, char *err, size_t errlen);
int archive_load_within(Archive *a, const char *path, const ArchiveLimits *lim, char *err,
                        size_t errlen);

/* Writes every entry below destdir (created if missing), files with
 * their modes; existing files are replaced.  Refuses to write through a
 * symbolic link found inside destdir.  Returns 0, or -1 with a reason
 * naming the file at fault in err. */
int archive_extract(const Archive *a, const char *destdir, char *err, size_t errlen);

#endif
