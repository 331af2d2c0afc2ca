/*
 * sortsubs_main.c - the `sortsubs` command (make sort-submissions): a whole
 * class's download from Canvas, Moodle or Blackboard, sorted into one
 * folder per submission, as grade --all takes them.
 *
 *     sortsubs [--max-mb N] [--max-ratio N] FROM TO
 *
 * FROM is the download: the .zip the platform gave, or the folder it was
 * unpacked into.  Each file is read by its name (lmsname.h): whose
 * submission it is, and the name its student gave it, which it gets back.
 * Where a student's submission has the same file twice (Canvas's
 * "part1_image_plane-1.c", uploaded again, beside "part1_image_plane.c"),
 * the later upload is kept and the run says so; where a download holds a
 * student's earlier attempts too (Blackboard's, with every attempt
 * downloaded), the latest attempt's files are kept, and the run says so.
 * TO must be new (missing,
 * or an empty folder): the sorted folders are written into a temporary
 * folder beside it, renamed to TO when all is written, so a run that fails
 * leaves nothing.  FROM is only read.  TO/sorted.txt lists where each file
 * came from.  A zip that would unpack to more than --max-mb MiB in all
 * (256 by default), or any file of which unpacks to more than
 * --max-ratio times its packed size (100; 1 MiB is always allowed), is
 * refused before it is unpacked: a small download cannot fill the memory
 * or the disk.
 *
 * Files of the system's own (names starting with ".", macOS's __MACOSX)
 * are left out; any other file not named as the platforms name a
 * submission's files is named, and not sorted.  Exit status: 0 when
 * sorted, 1 on an error (nothing written), 2 on a usage error.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "build.h"
#include "lmsname.h"
#include "terminal.h"
#include "../tools/archive.h"

#define ERR_MAX 1024

typedef struct {
    const ArchiveEntry *entry;      /* the file in the download */
    LmsName n;
    bool kept;                      /* false: an earlier upload of the same file,
                                       or a file of an earlier attempt */
    bool earlier_attempt;           /* left out as of an earlier attempt */
} Item;

/* A name from the download, on standard output: the students chose the
 * names of their files (and Moodle's folders carry their own names). */
static void put_name(const char *name)
{
    term_put(stdout, name, strlen(name));
}

static int usage(void)
{
    fprintf(stderr, "usage: sortsubs [--max-mb N] [--max-ratio N] FROM TO\n"
                    "  FROM  a class's download from Canvas, Moodle or Blackboard: the .zip, or the "
                    "folder it was "
                    "unpacked into\n"
                    "  TO    a new folder (missing or empty), to hold one folder per submission\n"
                    "  --max-mb N     refuse a download that unpacks to more than N MiB (256)\n"
                    "  --max-ratio N  refuse a file that unpacks to more than N times its size (100)\n");
    return 2;
}

static int fail(const char *what, const char *why)
{
    fprintf(stderr, "sortsubs: %s%s%s; nothing written\n", what, why ? ": " : "", why ? why : "");
    return 1;
}

/* Whether a component of path is the system's own: ".DS_Store", "._x",
 * ".git", macOS's "__MACOSX". */
static bool system_file(const char *path)
{
    for (const char *c = path; c; c = strchr(c, '/')) {
        if (*c == '/')
            c++;
        if (*c == '.' || strncmp(c, "__MACOSX/", 9) == 0 || strcmp(c, "__MACOSX") == 0)
            return true;
    }
    return false;
}

/* 1 when TO can be made (missing, or an empty folder), 0 when not (why in err). */
static int new_destination(const char *to, bool *exists, char *err, size_t errlen)
{
    struct stat st;
    *exists = false;
    if (lstat(to, &st) != 0)
        return errno == ENOENT ? 1 : (snprintf(err, errlen, "%s", strerror(errno)), 0);
    if (!S_ISDIR(st.st_mode)) {
        snprintf(err, errlen, "it exists and is not a folder");
        return 0;
    }
    DIR *d = opendir(to);
    struct dirent *e;
    int entries = 0;
    while (d && (e = readdir(d)))
        entries += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    if (!d || entries > 0) {
        snprintf(err, errlen, "%s", d ? "it is not empty: give a new folder, so that nothing in it is mixed "
                                        "with the sorted submissions or overwritten"
                                      : strerror(errno));
        return 0;
    }
    *exists = true;
    return 1;
}

static int by_who_then_name(const void *a, const void *b)
{
    const Item *x = a, *y = b;
    int c = strcmp(x->n.who, y->n.who);
    c = c ? c : strcmp(x->n.name, y->n.name);
    return c ? c : (x->n.again > y->n.again) - (x->n.again < y->n.again);
}

/* A whole number from 1 to max, or 0. */
static unsigned long bound(const char *text, unsigned long max)
{
    char *end;
    errno = 0;
    unsigned long v = strtoul(text, &end, 10);
    return *text >= '0' && *text <= '9' && !*end && !errno && v >= 1 && v <= max ? v : 0;
}

int main(int argc, char **argv)
{
    ArchiveLimits lim = { (size_t)256 << 20, 100 };
    int arg = 1;
    for (; arg + 1 < argc && strncmp(argv[arg], "--max-", 6) == 0; arg += 2) {
        bool mb = strcmp(argv[arg], "--max-mb") == 0;
        unsigned long v = bound(argv[arg + 1], mb ? ARCHIVE_MAX_SIZE >> 20 : 1000000);
        if (mb && v)
            lim.max_unpacked = (size_t)v << 20;
        else if (strcmp(argv[arg], "--max-ratio") == 0 && v)
            lim.max_ratio = (unsigned)v;
        else
            return usage();
    }
    if (argc - arg != 2 || !*argv[arg] || !*argv[arg + 1])
        return usage();
    const char *from = argv[arg], *to = argv[arg + 1];
    char err[ERR_MAX], why[ERR_MAX];
    bool exists;
    if (!new_destination(to, &exists, why, sizeof why)) {
        snprintf(err, sizeof err, "%s", to);
        return fail(err, why);
    }

    /* The download, as a list of files: a zip's entries, or a folder's tree. */
    struct stat st;
    if (stat(from, &st) != 0) {
        snprintf(err, sizeof err, "%s", from);
        return fail(err, strerror(errno));
    }
    Archive in;
    archive_init(&in, ARCHIVE_ZIP);
    int status = S_ISDIR(st.st_mode) ? archive_add_tree(&in, from, NULL, why, sizeof why)
                                     : archive_load_within(&in, from, &lim, why, sizeof why);
    if (status != 0) {
        archive_free(&in);
        return fail(S_ISDIR(st.st_mode) ? "the download's folder could not be read" : "the download could not be read",
                    why);
    }

    /* Each file by its name. */
    Item *items = calloc(in.count + 1, sizeof *items);
    const ArchiveEntry **unsorted = calloc(in.count + 1, sizeof *unsorted);
    if (!items || !unsorted) {
        archive_free(&in);
        return fail("out of memory", NULL);
    }
    size_t nitems = 0, nunsorted = 0, nsystem = 0, nby[LMS_BLACKBOARD + 1] = { 0 };
    for (size_t k = 0; k < in.count; k++) {
        const ArchiveEntry *e = &in.entries[k];
        if (e->is_dir)
            continue;
        if (system_file(e->path)) {
            nsystem++;
            continue;
        }
        Item *it = &items[nitems];
        if (!lms_name(e->path, stage_names, NPARTS, &it->n) || !archive_path_ok(it->n.who) ||
            !archive_path_ok(it->n.name) || strchr(it->n.who, '/') || strcmp(it->n.who, "sorted.txt") == 0) {
            unsorted[nunsorted++] = e;
            continue;
        }
        it->entry = e;
        it->kept = true;
        nby[it->n.lms]++;
        nitems++;
    }
    if (nitems == 0) {
        snprintf(err, sizeof err, "%s holds no file named as Canvas, Moodle or Blackboard name a class's "
                 "files (NAME_USERID_FILEID_FILE, \"FULL NAME_ID_assignsubmission_file_\" and the file, or "
                 "ASSIGNMENT_USERNAME_attempt_DATE_FILE)", from);
        free(items);
        free(unsorted);
        archive_free(&in);
        return fail(err, NULL);
    }

    /* By submission, then name.  Of a submission's attempts, the latest
     * is kept (Blackboard's dates, written so that their order is that of
     * their text); of one file uploaded more than once, the last (Canvas's
     * highest "-N"). */
    qsort(items, nitems, sizeof *items, by_who_then_name);
    size_t nfolders = 0, nlater = 0, nlate = 0;
    for (size_t k = 0, end; k < nitems; k = end) {
        const char *latest = items[k].n.attempt;
        for (end = k; end < nitems && strcmp(items[end].n.who, items[k].n.who) == 0; end++)
            if (strcmp(items[end].n.attempt, latest) > 0)
                latest = items[end].n.attempt;
        nfolders++;
        nlate += items[k].n.late;
        for (size_t j = k; j < end; j++)
            if (strcmp(items[j].n.attempt, latest) != 0) {
                items[j].kept = false;
                items[j].earlier_attempt = true;
                nlater++;
            }
    }
    for (size_t k = 0; k + 1 < nitems; k++) {
        size_t next = k + 1;                /* the next file of the same attempt */
        while (next < nitems && items[next].earlier_attempt)
            next++;
        if (items[k].kept && next < nitems && strcmp(items[k].n.who, items[next].n.who) == 0 &&
            strcmp(items[k].n.name, items[next].n.name) == 0) {
            items[k].kept = false;
            nlater++;
        }
    }

    /* The sorted folders, and sorted.txt, as an archive written out at once. */
    Archive out;
    archive_init(&out, ARCHIVE_ZIP);
    KitBuf list = { 0 };
    char line[3 * ERR_MAX];
    snprintf(line, sizeof line, "# sorted by sortsubs from %s: each file, and where it came from\n", from);
    status = kit_buf_append(&list, line, strlen(line));
    for (size_t k = 0; k < nitems && status == 0; k++) {
        const Item *it = &items[k];
        char path[2 * LMS_NAME_MAX + 2];
        snprintf(path, sizeof path, "%s/%s", it->n.who, it->n.name);
        if (it->kept)
            status = archive_add_file(&out, path, it->entry->data, it->entry->size, 0644, why, sizeof why);
        snprintf(line, sizeof line, "%s\t%s%s%s\n", it->kept ? path : "(left out)", it->entry->path,
                 it->n.late ? "\t(late)" : "",
                 it->kept ? "" : it->earlier_attempt ? "\t(of an earlier attempt)"
                                                     : "\t(an earlier upload of the same file)");
        if (status == 0)
            status = kit_buf_append(&list, line, strlen(line));
    }
    for (size_t k = 0; k < nunsorted && status == 0; k++) {
        snprintf(line, sizeof line, "(not sorted)\t%s\n", unsorted[k]->path);
        status = kit_buf_append(&list, line, strlen(line));
    }
    if (status == 0)
        status = archive_add_file(&out, "sorted.txt", list.data, list.len, 0644, why, sizeof why);
    free(list.data);

    /* Written beside TO, then renamed to it. */
    char tmp[4096];
    if (status == 0 && (size_t)snprintf(tmp, sizeof tmp, "%s.sorting.XXXXXX", to) >= sizeof tmp) {
        snprintf(why, sizeof why, "the folder's name is too long");
        status = -1;
    }
    if (status == 0 && !mkdtemp(tmp)) {
        snprintf(why, sizeof why, "%.900s: %s", tmp, strerror(errno));
        status = -1;
    }
    if (status == 0) {
        chmod(tmp, 0755);
        status = archive_extract(&out, tmp, why, sizeof why);
        if (status == 0 && exists && rmdir(to) != 0) {
            snprintf(why, sizeof why, "%.900s: %s", to, strerror(errno));
            status = -1;
        }
        if (status == 0 && rename(tmp, to) != 0) {
            snprintf(why, sizeof why, "%.900s: %s", to, strerror(errno));
            status = -1;
        }
        if (status != 0)
            build_rmtree(tmp);
    }
    archive_free(&out);
    if (status != 0) {
        free(items);
        free(unsorted);
        archive_free(&in);
        return fail("the sorted folders could not be written", why);
    }

    /* "Canvas", "Canvas and Moodle", "Canvas, Moodle and Blackboard" */
    static const char *const platform[] = { "", "Canvas", "Moodle", "Blackboard" };
    char platforms[64] = "";
    int nplatforms = 0, named = 0;
    for (int l = LMS_CANVAS; l <= LMS_BLACKBOARD; l++)
        nplatforms += nby[l] > 0;
    for (int l = LMS_CANVAS; l <= LMS_BLACKBOARD; l++)
        if (nby[l]) {
            named++;
            snprintf(platforms + strlen(platforms), sizeof platforms - strlen(platforms), "%s%s",
                     named == 1 ? "" : named == nplatforms ? " and " : ", ", platform[l]);
        }
    printf("sorted %zu file%s of a %s download into %zu submission folder%s in %s", nitems - nlater,
           nitems - nlater == 1 ? "" : "s", platforms, nfolders, nfolders == 1 ? "" : "s", to);
    if (nlate)
        printf(" (%zu of them late, as Canvas marked them)", nlate);
    printf(":");
    size_t shown = 0;
    for (size_t k = 0; k < nitems; k++)
        if (k == 0 || strcmp(items[k].n.who, items[k - 1].n.who) != 0) {
            if (shown < 8) {
                fputs(shown ? ", " : " ", stdout);
                put_name(items[k].n.who);
            }
            else if (shown == 8)
                printf(", ...");
            shown++;
        }
    printf("\n");
    for (size_t k = 0, end; k < nitems; k = end) {      /* earlier attempts: once a submission */
        size_t left = 0, kept = k;
        for (end = k; end < nitems && strcmp(items[end].n.who, items[k].n.who) == 0; end++) {
            left += items[end].earlier_attempt;
            if (!items[end].earlier_attempt)
                kept = end;
        }
        if (!left)
            continue;
        fputs("  ", stdout);
        put_name(items[k].n.who);
        printf(": kept the latest attempt, ");
        put_name(items[kept].n.attempt);
        printf("; left out %zu file%s of earlier attempts\n", left, left == 1 ? "" : "s");
    }
    for (size_t k = 0; k < nitems; k++) {
        if (items[k].kept || items[k].earlier_attempt)
            continue;
        size_t last = k + 1;                /* the one kept: the last of its run */
        while (!items[last].kept)
            last++;                         /* (files of earlier attempts are not kept either) */
        fputs("  ", stdout);
        put_name(items[k].n.who);
        fputs("/", stdout);
        put_name(items[k].n.name);
        fputs(": kept the later upload, ", stdout);
        put_name(items[last].entry->path);
        fputs("; left out ", stdout);
        put_name(items[k].entry->path);
        fputs("\n", stdout);
    }
    if (nunsorted) {
        printf("not sorted (not named as Canvas, Moodle or Blackboard name a submission's files): ");
        for (size_t k = 0; k < nunsorted && k < 8; k++) {
            fputs(k ? ", " : "", stdout);
            put_name(unsorted[k]->path);
        }
        printf("%s\n", nunsorted > 8 ? ", ..." : "");
    }
    if (nsystem)
        printf("left out %zu file%s of the system's own (names starting with \".\", __MACOSX)\n", nsystem,
               nsystem == 1 ? "" : "s");
    printf("where each file came from: %s/sorted.txt\n", to);
    free(items);
    free(unsorted);
    archive_free(&in);
    return 0;
}
