/*
 * pack_main.c - the `pack` command: makes, lists and unpacks the kit's ZIP
 * archives (see archive.h): Gradescope's autograder.zip, and the tests'
 * downloads of a class.
 *
 *     pack zip    OUT.zip    DIR          DIR's contents at the archive's root
 *     pack unzip  FILE.zip    DESTDIR
 *     pack list   FILE                    one line per entry: mode, size, path
 *
 * Archives are written to a temporary file renamed into place.  Exit status:
 * 0 on success, 1 on an error (with a message on stderr), 2 on a usage error.
 */
#include <stdio.h>
#include <string.h>

#include "archive.h"

#define PACK_ERR 1024

/* Prints the usage and returns 2. */
static int pack_usage(void)
{
    fprintf(stderr,
            "usage: pack zip OUT.zip DIR\n"
            "       pack unzip FILE.zip DESTDIR\n"
            "       pack list FILE\n");
    return 2;
}

/* Prints "pack: message" and returns 1. */
static int pack_error(const char *message)
{
    fprintf(stderr, "pack: %s\n", message);
    return 1;
}

/* Archives the tree dir into out.  Returns the exit status. */
static int pack_make(const char *out, const char *dir)
{
    Archive a;
    char err[PACK_ERR];
    archive_init(&a);
    int rc = archive_add_tree(&a, dir, err, sizeof err) == 0 &&
             archive_save(&a, out, err, sizeof err) == 0 ? 0 : pack_error(err);
    archive_free(&a);
    return rc;
}

/* Unpacks file below dest.  Returns the exit status. */
static int pack_unpack(const char *file, const char *dest)
{
    Archive a;
    char err[PACK_ERR];
    if (archive_load(&a, file, err, sizeof err) != 0)
        return pack_error(err);
    int rc = 0;
    if (archive_extract(&a, dest, err, sizeof err) != 0) {
        rc = pack_error(err);
    }
    archive_free(&a);
    return rc;
}

/* Lists file's entries like "-rwxr-xr-x     1234 path".  Returns the exit
 * status. */
static int pack_list(const char *file)
{
    Archive a;
    char err[PACK_ERR];
    if (archive_load(&a, file, err, sizeof err) != 0)
        return pack_error(err);
    for (size_t k = 0; k < a.count; k++) {
        const ArchiveEntry *e = &a.entries[k];
        char mode[11] = "----------";
        static const char letters[] = "rwxrwxrwx";
        mode[0] = e->is_dir ? 'd' : '-';
        for (int b = 0; b < 9; b++)
            if (e->mode & (0400u >> b))
                mode[1 + b] = letters[b];
        printf("%s %10zu %s%s\n", mode, e->size, e->path, e->is_dir ? "/" : "");
    }
    archive_free(&a);
    if (fflush(stdout) != 0 || ferror(stdout))
        return pack_error("cannot write the listing to standard output");
    return 0;
}

/* Dispatches on the command word. */
int main(int argc, char **argv)
{
    if (argc < 2)
        return pack_usage();
    const char *cmd = argv[1];
    if (strcmp(cmd, "zip") == 0 && argc == 4)
        return pack_make(argv[2], argv[3]);
    if (strcmp(cmd, "unzip") == 0 && argc == 4)
        return pack_unpack(argv[2], argv[3]);
    if (strcmp(cmd, "list") == 0 && argc == 3)
        return pack_list(argv[2]);
    return pack_usage();
}
