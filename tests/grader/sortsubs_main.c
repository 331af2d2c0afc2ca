/*
 * sortsubs_main.c - the `sortsubs` command (make sort-submissions): a whole
 * class's download from Canvas, Moodle or Blackboard, sorted into one
 * folder per submission, as grade --all takes them.
 *
 *     sortsubs [--max-mb N] [--max-ratio N] FROM TO
 *
 * What it keeps, leaves out and writes: handouts/instructor-guide.md
 * ("Grading a class"); the names it reads: lmsname.h.  A zip that would
 * unpack to more than --max-mb MiB in all (256 by default), or any file of
 * which unpacks to more than --max-ratio times its packed size (100; 1 MiB
 * is always allowed), is refused before it is unpacked: a small download
 * cannot fill the memory or the disk.  Exit status: 0 when sorted, 1 on an
 * error (nothing written), 2 on a usage error.
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
#include "jail.h"
#include "lmsname.h"
#include "terminal.h"
#include "../tools/archive.h"
#include "../../labs/kit/textfile.h"

#define ERR_MAX 1024

typedef struct {
    const ArchiveEntry *entry;      /* the file in the download */
    LmsName n;
    bool kept;                      /* false: an earlier upload of the same file,
                                       or a file of an earlier attempt */
    bool earlier_attempt;           /* left out as of an earlier attempt */
} Item;

/* name in buf (size bytes), each newline and tab in it shown as ^J and
 * ^I, cut with "..." where it does not fit: the students chose the names
 * of their files (and Moodle's folders carry their own names), and a line
 * of the run's output or of sorted.txt says one file's. */
static const char *one_line(const char *name, char *buf, size_t size)
{
    size_t used = 0;
    const char *s = name;
    for (; *s && used + 6 < size; s++) {
        if (*s == '\n' || *s == '\t') {
            buf[used++] = '^';
            buf[used++] = *s == '\n' ? 'J' : 'I';
        } else {
            buf[used++] = *s;
        }
    }
    if (*s) {
        memcpy(buf + used, "...", 3);
        used += 3;
    }
    buf[used] = '\0';
    return buf;
}

/* A name from the download, on standard output, on one line (one_line)
 * and with no escape sequence the terminal would obey (terminal.h). */
static void put_name(const char *name)
{
    char shown[ERR_MAX];
    one_line(name, shown, sizeof shown);
    term_put(stdout, shown, strlen(shown));
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

/* The download and its files, sorted: what main's steps share. */
typedef struct {
    Archive in;                       /* the download's files                       */
    Item *items;                      /* those named as the platforms name them     */
    size_t nitems;
    const ArchiveEntry **unsorted;    /* the others, but for the system's own       */
    size_t nunsorted, nsystem;
    size_t nby[LMS_BLACKBOARD + 1];   /* the items of each platform                 */
    size_t nfolders, nlater, nlate;   /* submissions, items left out, late ones     */
} Sorting;

/* Reads the options (--max-mb N, --max-ratio N) into lim.  Returns the
 * index of the first argument after them, or -1 when one is wrong. */
static int read_options(int argc, char **argv, ArchiveLimits *lim)
{
    int arg = 1;
    for (; arg + 1 < argc && strncmp(argv[arg], "--max-", 6) == 0; arg += 2) {
        bool mb = strcmp(argv[arg], "--max-mb") == 0;
        unsigned long v = bound(argv[arg + 1], mb ? ARCHIVE_MAX_SIZE >> 20 : 1000000);
        if (mb && v)
            lim->max_unpacked = (size_t)v << 20;
        else if (strcmp(argv[arg], "--max-ratio") == 0 && v)
            lim->max_ratio = (unsigned)v;
        else
            return -1;
    }
    return arg;
}

/* The download, as a list of files (s->in): a zip's entries, or a
 * folder's tree.  Returns 0, or 1 having said why. */
static int read_download(Sorting *s, const char *from, const ArchiveLimits *lim)
{
    char err[ERR_MAX], why[ERR_MAX];
    struct stat st;
    if (stat(from, &st) != 0) {
        snprintf(err, sizeof err, "%s", from);
        return fail(err, strerror(errno));
    }
    int status = S_ISDIR(st.st_mode) ? archive_add_tree(&s->in, from, why, sizeof why)
                                     : archive_load_within(&s->in, from, lim, why, sizeof why);
    if (status != 0)
        return fail(S_ISDIR(st.st_mode) ? "the download's folder could not be read" : "the download could not be read",
                    why);
    return 0;
}

/* Each file by its name: those named as a platform names a submission's
 * files become items, the others are not sorted, and the system's own are
 * counted and left out.  Returns 0, or 1 having said why (none is named
 * so). */
static int name_files(Sorting *s, const char *from)
{
    s->items = calloc(s->in.count + 1, sizeof *s->items);
    s->unsorted = calloc(s->in.count + 1, sizeof *s->unsorted);
    if (!s->items || !s->unsorted)
        return fail("out of memory", NULL);
    for (size_t k = 0; k < s->in.count; k++) {
        const ArchiveEntry *e = &s->in.entries[k];
        if (e->is_dir)
            continue;
        if (system_file(e->path)) {
            s->nsystem++;
            continue;
        }
        Item *it = &s->items[s->nitems];
        if (!lms_name(e->path, stage_names, NPARTS, &it->n) || !archive_path_ok(it->n.who) ||
            !archive_path_ok(it->n.name) || strchr(it->n.who, '/') || strcmp(it->n.who, "sorted.txt") == 0) {
            s->unsorted[s->nunsorted++] = e;
            continue;
        }
        it->entry = e;
        it->kept = true;
        s->nby[it->n.lms]++;
        s->nitems++;
    }
    if (s->nitems > 0)
        return 0;
    char err[ERR_MAX];
    snprintf(err, sizeof err, "%s holds no file named as Canvas, Moodle or Blackboard name a class's "
             "files (NAME_USERID_FILEID_FILE, \"FULL NAME_ID_assignsubmission_file_\" and the file, or "
             "ASSIGNMENT_USERNAME_attempt_DATE_FILE)", from);
    return fail(err, NULL);
}

/* The last component of path. */
static const char *last_part(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* Blackboard's username is read as the last "_"-separated part before
 * "_attempt_" (lmsname.h), but a username may hold "_" too: "j_smith"'s
 * and "k_smith"'s files were both "smith"'s, one student's attempts taken
 * for the other's earlier ones.  A download is of one assignment, whose
 * name, up to a "_", all its Blackboard files' names start with: each
 * username is all that follows it up to "_attempt_". */
static void blackboard_users(Sorting *s)
{
    const char *first = NULL;          /* the first such name's last component */
    size_t common = 0;                 /* the bytes all of them share          */
    for (size_t k = 0; k < s->nitems; k++) {
        const LmsName *n = &s->items[k].n;
        if (n->lms != LMS_BLACKBOARD)
            continue;
        const char *base = last_part(s->items[k].entry->path);
        size_t len = n->user_at + strlen(n->who), c = 0;
        if (!first) {
            first = base;
            common = len;
        }
        while (c < common && c < len && base[c] == first[c])
            c++;
        common = c;
    }
    size_t at = common;                /* where the usernames begin */
    while (at > 0 && first[at - 1] != '_')
        at--;
    for (size_t k = 0; k < s->nitems && at > 1; k++) {
        LmsName *n = &s->items[k].n;
        size_t len = n->user_at + strlen(n->who);
        if (n->lms == LMS_BLACKBOARD && len - at < sizeof n->who) {
            memmove(n->who, last_part(s->items[k].entry->path) + at, len - at);
            n->who[len - at] = '\0';
        }
    }
}

/* By submission, then name.  Of a submission's attempts, the latest is
 * kept (Blackboard's dates, written so that their order is that of their
 * text); of one file uploaded more than once, the last (Canvas's highest
 * "-N").  Counts the submissions, the items left out and the late ones. */
static void keep_latest(Sorting *s)
{
    Item *items = s->items;
    size_t nitems = s->nitems;
    qsort(items, nitems, sizeof *items, by_who_then_name);
    for (size_t k = 0, end; k < nitems; k = end) {
        const char *latest = items[k].n.attempt;
        for (end = k; end < nitems && strcmp(items[end].n.who, items[k].n.who) == 0; end++)
            if (strcmp(items[end].n.attempt, latest) > 0)
                latest = items[end].n.attempt;
        s->nfolders++;
        s->nlate += items[k].n.late;
        for (size_t j = k; j < end; j++)
            if (strcmp(items[j].n.attempt, latest) != 0) {
                items[j].kept = false;
                items[j].earlier_attempt = true;
                s->nlater++;
            }
    }
    for (size_t k = 0; k + 1 < nitems; k++) {
        size_t next = k + 1;                /* the next file of the same attempt */
        while (next < nitems && items[next].earlier_attempt)
            next++;
        if (items[k].kept && next < nitems && strcmp(items[k].n.who, items[next].n.who) == 0 &&
            strcmp(items[k].n.name, items[next].n.name) == 0) {
            items[k].kept = false;
            s->nlater++;
        }
    }
}

/* The sorted folders, and sorted.txt, into out, to be written at once.
 * Returns 0, or -1 with why. */
static int pack_sorted(const Sorting *s, const char *from, Archive *out, char *why, size_t whylen)
{
    KitBuf list = { 0 };
    char line[3 * ERR_MAX];
    snprintf(line, sizeof line, "# sorted by sortsubs from %s: each file, and where it came from\n", from);
    int status = kit_buf_append(&list, line, strlen(line));
    for (size_t k = 0; k < s->nitems && status == 0; k++) {
        const Item *it = &s->items[k];
        char path[2 * LMS_NAME_MAX + 2], to[ERR_MAX], was[ERR_MAX];
        snprintf(path, sizeof path, "%s/%s", it->n.who, it->n.name);
        if (it->kept)
            status = archive_add_file(out, path, it->entry->data, it->entry->size, 0644, why, whylen);
        snprintf(line, sizeof line, "%s\t%s%s%s\n", it->kept ? one_line(path, to, sizeof to) : "(left out)",
                 one_line(it->entry->path, was, sizeof was),
                 it->n.late ? "\t(late)" : "",
                 it->kept ? "" : it->earlier_attempt ? "\t(of an earlier attempt)"
                                                     : "\t(an earlier upload of the same file)");
        if (status == 0)
            status = kit_buf_append(&list, line, strlen(line));
    }
    for (size_t k = 0; k < s->nunsorted && status == 0; k++) {
        char was[ERR_MAX];
        snprintf(line, sizeof line, "(not sorted)\t%s\n", one_line(s->unsorted[k]->path, was, sizeof was));
        status = kit_buf_append(&list, line, strlen(line));
    }
    if (status == 0)
        status = archive_add_file(out, "sorted.txt", list.data, list.len, 0644, why, whylen);
    free(list.data);
    return status;
}

/* Writes out into a new folder beside TO, then renames it to TO (an empty
 * folder there, which exists says, removed first).  Returns 0, or -1 with
 * why; nothing is left written then. */
static int write_beside(const Archive *out, const char *to, bool exists, char *why, size_t whylen)
{
    char tmp[4096];
    if ((size_t)snprintf(tmp, sizeof tmp, "%s.sorting.XXXXXX", to) >= sizeof tmp)
        return kit_fail(why, whylen, "the folder's name is too long");
    if (!mkdtemp(tmp))
        return kit_fail(why, whylen, "%.900s: %s", tmp, strerror(errno));
    chmod(tmp, 0755);
    int status = archive_extract(out, tmp, why, whylen);
    if (status == 0 && exists && rmdir(to) != 0) {
        snprintf(why, whylen, "%.900s: %s", to, strerror(errno));
        status = -1;
    }
    if (status == 0 && rename(tmp, to) != 0) {
        snprintf(why, whylen, "%.900s: %s", to, strerror(errno));
        status = -1;
    }
    if (status != 0)
        jail_remove_tree(tmp);
    return status;
}

/* The sorted folders and sorted.txt, written to TO.  Returns 0, or 1
 * having said why. */
static int write_sorted(const Sorting *s, const char *from, const char *to, bool exists)
{
    char why[ERR_MAX];
    Archive out;
    archive_init(&out);
    int status = pack_sorted(s, from, &out, why, sizeof why);
    if (status == 0)
        status = write_beside(&out, to, exists, why, sizeof why);
    archive_free(&out);
    return status == 0 ? 0 : fail("the sorted folders could not be written", why);
}

/* The first line: how many files of which platforms went into how many
 * folders, and the first submissions' names. */
static void say_sorted(const Sorting *s, const char *to)
{
    /* "Canvas", "Canvas and Moodle", "Canvas, Moodle and Blackboard" */
    static const char *const platform[] = { "", "Canvas", "Moodle", "Blackboard" };
    char platforms[64] = "";
    int nplatforms = 0, named = 0;
    for (int l = LMS_CANVAS; l <= LMS_BLACKBOARD; l++)
        nplatforms += s->nby[l] > 0;
    for (int l = LMS_CANVAS; l <= LMS_BLACKBOARD; l++)
        if (s->nby[l]) {
            named++;
            snprintf(platforms + strlen(platforms), sizeof platforms - strlen(platforms), "%s%s",
                     named == 1 ? "" : named == nplatforms ? " and " : ", ", platform[l]);
        }
    size_t nsorted = s->nitems - s->nlater;
    printf("sorted %zu file%s of a %s download into %zu submission folder%s in %s", nsorted,
           nsorted == 1 ? "" : "s", platforms, s->nfolders, s->nfolders == 1 ? "" : "s", to);
    if (s->nlate)
        printf(" (%zu of them late, as Canvas marked them)", s->nlate);
    printf(":");
    size_t shown = 0;
    for (size_t k = 0; k < s->nitems; k++)
        if (k == 0 || strcmp(s->items[k].n.who, s->items[k - 1].n.who) != 0) {
            if (shown < 8) {
                fputs(shown ? ", " : " ", stdout);
                put_name(s->items[k].n.who);
            }
            else if (shown == 8)
                printf(", ...");
            shown++;
        }
    printf("\n");
}

/* Each submission with files of earlier attempts left out, once. */
static void say_earlier_attempts(const Sorting *s)
{
    const Item *items = s->items;
    for (size_t k = 0, end; k < s->nitems; k = end) {
        size_t left = 0, kept = k;
        for (end = k; end < s->nitems && strcmp(items[end].n.who, items[k].n.who) == 0; end++) {
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
}

/* Each file uploaded again: the upload kept, and the one left out. */
static void say_earlier_uploads(const Sorting *s)
{
    const Item *items = s->items;
    for (size_t k = 0; k < s->nitems; k++) {
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
}

/* The files not sorted, those of the system's own left out, where
 * sorted.txt is, and the next step. */
static void say_left_out(const Sorting *s, const char *to)
{
    if (s->nunsorted) {
        printf("not sorted (not named as Canvas, Moodle or Blackboard name a submission's files): ");
        for (size_t k = 0; k < s->nunsorted && k < 8; k++) {
            fputs(k ? ", " : "", stdout);
            put_name(s->unsorted[k]->path);
        }
        printf("%s\n", s->nunsorted > 8 ? ", ..." : "");
    }
    if (s->nsystem)
        printf("left out %zu file%s of the system's own (names starting with \".\", __MACOSX)\n", s->nsystem,
               s->nsystem == 1 ? "" : "s");
    printf("where each file came from: %s/sorted.txt\n", to);
    printf("to grade them: make grade-all SUBMISSIONS=%s\n", to);
}

int main(int argc, char **argv)
{
    ArchiveLimits lim = { (size_t)256 << 20, 100 };
    int arg = read_options(argc, argv, &lim);
    if (arg < 0 || argc - arg != 2 || !*argv[arg] || !*argv[arg + 1])
        return usage();
    const char *from = argv[arg], *to = argv[arg + 1];
    /* "sorted/", as a shell completes a folder's name, is "sorted": its
     * temporary folder goes beside it, not inside. */
    for (size_t n = strlen(to); n > 1 && to[n - 1] == '/'; n--)
        argv[arg + 1][n - 1] = '\0';
    char err[ERR_MAX], why[ERR_MAX];
    bool exists;
    if (!new_destination(to, &exists, why, sizeof why)) {
        snprintf(err, sizeof err, "%s", to);
        return fail(err, why);
    }
    Sorting s = { 0 };
    archive_init(&s.in);
    int status = read_download(&s, from, &lim);
    if (status == 0)
        status = name_files(&s, from);
    if (status == 0) {
        blackboard_users(&s);
        keep_latest(&s);
        status = write_sorted(&s, from, to, exists);
    }
    if (status == 0) {
        say_sorted(&s, to);
        say_earlier_attempts(&s);
        say_earlier_uploads(&s);
        say_left_out(&s, to);
    }
    free(s.items);
    free(s.unsorted);
    archive_free(&s.in);
    return status;
}
