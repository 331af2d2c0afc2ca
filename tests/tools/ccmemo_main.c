/*
 * ccmemo - a stand-in for cc that compiles each distinct file once for the
 * kit's own tests.
 *
 * Four suites build a packaged kit from the same sources (the student kit,
 * the Gradescope bundle, the PrairieLearn course and the Classroom
 * repository), each from scratch as a new user would.  Put the directory
 * holding this program (built as "cc") first on PATH and name a directory
 * in CC_MEMO: a compile "cc ARGS -c FILE.c -o OBJ" then
 *   0. is served the direct way if it can be: without preprocessing, when
 *      every file its last compile read, and every place it looked in,
 *      are as they were (ccmemo_direct.h); else it
 *   1. preprocesses FILE.c with the same ARGS (cc -E),
 *   2. looks for an entry whose key -- the real compiler's path, ARGS and
 *      the whole preprocessed text, compared whole, not only by its hash --
 *      is the same, and if there is one copies its object to OBJ and writes
 *      its messages to stderr;
 *   3. else compiles, and keeps the object and the messages as a new entry;
 *   4. after 2 or 3, keeps a direct entry for step 0 the next time.
 * The preprocessed text holds every header's text and the file names as
 * written (the kits build with the same relative paths), so an entry is
 * used only where compiling would give the same object.  Two builds asking
 * for the same entry at once: one compiles, the other waits for it, or
 * takes the compile over if the first has died (its pid is in the lock).
 *
 * A link "cc FLAGS FILES.o/.a -o PROG -lLIB..." is kept the same way: its
 * key is the real compiler's path, the arguments but -o PROG, and the
 * name, size and bytes of every object and archive it links, compared
 * whole; the program is copied out with the mode a new program gets.
 * Only links whose arguments are all of a few known kinds (-std=, -O, -W
 * but not -Wl, -f, -g, -pthread, -rdynamic, -no-pie, -lNAME, and files
 * ending in .o or .a) are kept, and the values of LIBRARY_PATH,
 * GCC_EXEC_PREFIX, COMPILER_PATH and LD_RUN_PATH are part of the key:
 * nothing else they read can change without the compiler changing too,
 * and then tests/tools/ccmemo_keep.sh empties the memo (it keys on the
 * linker and the C library's start file too).
 * Anything else (another link, -E, no CC_MEMO, as in the grader's sandbox,
 * which passes the compiler only PATH) runs the real compiler, which is
 * the next cc on PATH after the directories holding this program's marker
 * file "ccmemo.marker".  The memo's file "log" has a line for each compile
 * or link it saw: "compiled", "used", "used-direct", "linked",
 * "used-link" or "not-kept", the file and the directory.  An
 * entry's time is set when it is used, so that tests/run.sh, which keeps
 * the memo from run to run for the same compiler, can drop those a whole
 * run did not use.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "ccmemo_direct.h"
#include "ccmemo_util.h"
#include "kit/savefile.h"

#define KEY_MAX (256u << 20)     /* preprocessed text larger than this: compile */
#define WAIT_SECONDS 120         /* for another build's compile of the same key  */

static char real_cc[4096];

/* The next cc on PATH that is not in a directory marked as ours. */
static int find_real_cc(void)
{
    const char *path = getenv("PATH");
    if (!path)
        return -1;
    const char *p = path;
    while (*p) {
        const char *end = strchr(p, ':');
        size_t n = end ? (size_t)(end - p) : strlen(p);
        char dir[3000], marker[3100];
        if (n > 0 && n < sizeof dir) {
            memcpy(dir, p, n);
            dir[n] = '\0';
            snprintf(marker, sizeof marker, "%s/ccmemo.marker", dir);
            snprintf(real_cc, sizeof real_cc, "%s/cc", dir);
            if (access(marker, F_OK) != 0 && access(real_cc, X_OK) == 0)
                return 0;
        }
        p = end ? end + 1 : p + n;
    }
    return -1;
}

static void run_real(char **argv)
{
    argv[0] = real_cc;
    execv(real_cc, argv);
    fprintf(stderr, "ccmemo: cannot run %s: %s\n", real_cc, strerror(errno));
    exit(127);
}

/* Writes (buf, len) as path, all or nothing (kit_save_file). */
static int put(const char *path, const char *buf, size_t len)
{
    char err[64];
    return kit_save_file(path, buf, len, err, sizeof err);
}

/* The entry's object copied to obj and its messages to stderr (and to
 * *messages, malloc'd, *mlen set): 0, or -1 when there is no entry for this
 * key. */
static int use_entry(const char *entry, const char *key, size_t keylen, const char *obj,
                     char **messages, size_t *mlen)
{
    if (!ccmemo_same_key(entry, key, keylen, KEY_MAX))
        return -1;
    return ccmemo_serve(entry, obj, KEY_MAX, messages, mlen);
}

static void log_use(const char *memo, const char *what, const char *src)
{
    char path[4200], line[4200], cwd[2048];
    if (!getcwd(cwd, sizeof cwd))
        strcpy(cwd, "?");
    snprintf(line, sizeof line, "%s %s %s\n", what, src, cwd);
    snprintf(path, sizeof path, "%s/log", memo);
    int fd = open(path, O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
        ccmemo_write_all(fd, line, strlen(line));
        close(fd);
    }
}

/* Whether argument a of a link is of a kind the memo keeps: see the top. */
static int link_flag_known(const char *a)
{
    static const char *const exact[] = { "-pthread", "-rdynamic", "-no-pie" };
    for (size_t k = 0; k < sizeof exact / sizeof exact[0]; k++)
        if (strcmp(a, exact[k]) == 0)
            return 1;
    if (strncmp(a, "-Wl", 3) == 0)
        return 0;
    if (strncmp(a, "-std=", 5) == 0 || strncmp(a, "-O", 2) == 0 || strncmp(a, "-W", 2) == 0 ||
        strncmp(a, "-f", 2) == 0 || strncmp(a, "-g", 2) == 0)
        return 1;
    if (strncmp(a, "-l", 2) == 0 && a[2] != '\0') {
        for (const char *p = a + 2; *p; p++)
            if (!((*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '_'))
                return 0;
        return 1;
    }
    return 0;
}

/* Appends n bytes to (*key, *len, *cap); 0, or -1 out of memory or past
 * KEY_MAX. */
static int key_add(char **key, size_t *len, size_t *cap, const void *bytes, size_t n)
{
    if (n > KEY_MAX - *len)
        return -1;
    if (*len + n > *cap) {
        size_t c = *cap ? *cap : 4096;
        while (c < *len + n)
            c *= 2;
        char *more = realloc(*key, c);
        if (!more)
            return -1;
        *key = more;
        *cap = c;
    }
    memcpy(*key + *len, bytes, n);
    *len += n;
    return 0;
}

/* The key of a link the memo keeps (see the top), malloc'd with *len set;
 * NULL when argv is not such a link. */
static char *link_key(int argc, char **argv, int oarg, size_t *len)
{
    char *key = NULL;
    size_t cap = 0;
    *len = 0;
    int files = 0, bad = key_add(&key, len, &cap, "link\n", 5) ||
                         key_add(&key, len, &cap, real_cc, strlen(real_cc) + 1);
    /* Where these are set, the linker may look for libraries and tools
     * elsewhere: their values are part of the key. */
    static const char *const moves[] = { "LIBRARY_PATH", "GCC_EXEC_PREFIX", "COMPILER_PATH",
                                         "LD_RUN_PATH" };
    for (size_t k = 0; k < sizeof moves / sizeof moves[0] && !bad; k++) {
        const char *v = getenv(moves[k]);
        bad = v && (key_add(&key, len, &cap, moves[k], strlen(moves[k])) ||
                    key_add(&key, len, &cap, "=", 1) || key_add(&key, len, &cap, v, strlen(v) + 1));
    }
    for (int k = 1; k < argc && !bad; k++) {
        const char *a = argv[k];
        size_t n = strlen(a);
        if (k == oarg || k == oarg - 1)
            continue;
        if (a[0] == '-') {
            bad = !link_flag_known(a) || key_add(&key, len, &cap, a, n + 1);
            continue;
        }
        struct stat st;
        if (n < 3 || (strcmp(a + n - 2, ".o") != 0 && strcmp(a + n - 2, ".a") != 0) ||
            stat(a, &st) != 0 || !S_ISREG(st.st_mode)) {
            bad = 1;
            break;
        }
        size_t size = 0;
        char *bytes = kit_load_file(a, KEY_MAX, &size);
        char head[64];
        int hn = snprintf(head, sizeof head, "\n%zu\n", size);
        bad = !bytes || key_add(&key, len, &cap, a, n) || key_add(&key, len, &cap, head, (size_t)hn) ||
              key_add(&key, len, &cap, bytes, size);
        free(bytes);
        files++;
    }
    if (bad || files == 0) {
        free(key);
        return NULL;
    }
    return key;
}

/* Steps 2 and 3 for a key: the entry's object (or program) to obj and its
 * messages to stderr, or, with no entry, argv run and a successful result
 * kept.  made and used are the log's words for the two; name is what the
 * log names.  Returns argv's exit status (0 when served); *served set, and
 * what the compiler said in *messages (malloc'd, *mlen) for a result that
 * is there. */
static int serve_or_make(const char *memo, const char *key, size_t keylen, const char *obj,
                         char **argv, const char *made, const char *used, const char *name,
                         int *served, char **messages, size_t *mlen)
{
    char entry[4096], lock[4200];
    snprintf(entry, sizeof entry, "%s/%016llx", memo,
             (unsigned long long)ccmemo_fnv1a(key, keylen, 14695981039346656037u));
    snprintf(lock, sizeof lock, "%s.lock", entry);
    *served = 0;
    *messages = NULL;
    *mlen = 0;

    /* 2. An entry, or the lock to make it, or wait for who holds it.  The
     * lock holds its maker's pid: a lock whose maker has died (a build
     * interrupted while it compiled) is taken over, not waited for. */
    char holder[4300];
    snprintf(holder, sizeof holder, "%s/pid", lock);
    struct timespec nap = { 0, 20 * 1000 * 1000 };
    for (long waited = 0;; waited++) {
        if (use_entry(entry, key, keylen, obj, messages, mlen) == 0) {
            utimensat(AT_FDCWD, entry, NULL, 0);   /* used now: tests/run.sh keeps it */
            log_use(memo, used, name);
            *served = 1;
            return 0;
        }
        if (mkdir(lock, 0755) == 0) {
            char mine[32];
            int n = snprintf(mine, sizeof mine, "%ld\n", (long)getpid());
            put(holder, mine, (size_t)n);
            break;
        }
        if (errno != EEXIST || waited > WAIT_SECONDS * 50)
            run_real(argv);
        struct stat est;
        if (stat(entry, &est) == 0 && waited > 0)
            run_real(argv);                     /* an entry for another key */
        size_t n;
        char *kept = kit_load_file(holder, KEY_MAX, &n);
        long who = kept ? strtol(kept, NULL, 10) : 0;
        free(kept);
        if (who > 0 && kill((pid_t)who, 0) != 0 && errno == ESRCH) {
            unlink(holder);                     /* its maker is gone */
            rmdir(lock);
            continue;
        }
        nanosleep(&nap, NULL);
    }

    /* 3. Compile (or link), with the messages kept, and keep a successful
     * result. */
    char mpath[4300];
    snprintf(mpath, sizeof mpath, "%s/messages.%ld", memo, (long)getpid());
    int mfd = open(mpath, O_RDWR | O_CREAT | O_TRUNC, 0644);
    argv[0] = real_cc;
    int status = mfd < 0 ? -1 : ccmemo_run(argv, -1, mfd);
    char *m = NULL;
    if (mfd >= 0 && lseek(mfd, 0, SEEK_SET) == 0)
        m = ccmemo_slurp_fd(mfd, KEY_MAX, mlen);
    if (mfd >= 0)
        close(mfd);
    unlink(mpath);
    if (m)
        ccmemo_write_all(2, m, *mlen);
    if (status == 0) {
        char tmpdir[4300], path[4400];
        snprintf(tmpdir, sizeof tmpdir, "%s.%ld.new", entry, (long)getpid());
        size_t on;
        char *o = kit_load_file(obj, KEY_MAX, &on);
        int ok = o && mkdir(tmpdir, 0755) == 0;
        if (ok) {
            snprintf(path, sizeof path, "%s/object", tmpdir);
            ok = put(path, o, on) == 0;
            snprintf(path, sizeof path, "%s/messages", tmpdir);
            ok = ok && put(path, m ? m : "", m ? *mlen : 0) == 0;
            snprintf(path, sizeof path, "%s/key", tmpdir);
            ok = ok && put(path, key, keylen) == 0;   /* last: an entry with a key is whole */
            if (!ok || rename(tmpdir, entry) != 0)
                log_use(memo, "not-kept", name);
        }
        free(o);
        log_use(memo, made, name);
    }
    unlink(holder);
    rmdir(lock);
    if (status < 0)
        run_real(argv);
    if (status != 0) {
        free(m);
        *messages = NULL;
        *mlen = 0;
    } else {
        *messages = m;
    }
    return status;
}

int main(int argc, char **argv)
{
    if (find_real_cc() != 0) {
        fprintf(stderr, "ccmemo: no cc on PATH besides this one\n");
        return 127;
    }
    const char *memo = getenv("CC_MEMO");
    const char *obj = NULL, *src = NULL;
    int compile = 0, oarg = -1, others = 0;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k];
        size_t n = strlen(a);
        if (strcmp(a, "-c") == 0)
            compile = 1;
        else if (strcmp(a, "-o") == 0 && k + 1 < argc)
            obj = argv[oarg = ++k];
        else if (a[0] == '-' && (a[1] == 'E' || a[1] == 'S' || a[1] == 'M' || a[1] == 'o' ||
                                 strcmp(a, "-") == 0))
            compile = -1;                       /* neither a plain compile nor a link */
        else if (a[0] != '-' && n > 2 && strcmp(a + n - 2, ".c") == 0 && !src)
            src = a;
        else if (a[0] != '-')
            others++;                           /* a link's input, or not a plain compile */
    }
    if (!memo || !*memo || !obj)
        run_real(argv);
    int served;
    char *said = NULL;
    size_t said_len = 0;
    if (compile == 0 && !src && others > 0) {
        /* A link: kept if it is of the kinds known (see the top). */
        size_t keylen = 0;
        char *key = link_key(argc, argv, oarg, &keylen);
        if (!key)
            run_real(argv);
        int status = serve_or_make(memo, key, keylen, obj, argv, "linked", "used-link", obj,
                                   &served, &said, &said_len);
        if (status == 0 && served) {
            mode_t mask = umask(022);           /* the mode a new program gets */
            umask(mask);
            chmod(obj, 0777 & ~mask);
        }
        free(said);
        free(key);
        return status;
    }
    if (compile != 1 || !src || others > 0)
        run_real(argv);

    /* 0. The direct way (ccmemo_direct.h): no preprocessing if the files
     * the compile read last time read the same. */
    char **pre = calloc((size_t)argc + 2, sizeof *pre);
    if (!pre)
        run_real(argv);
    int np = 0;
    pre[np++] = real_cc;
    for (int k = 1; k < argc; k++)
        if (k != oarg && k != oarg - 1 && strcmp(argv[k], "-c") != 0)
            pre[np++] = argv[k];
    size_t dlen = 0;
    char *dkey = direct_key(pre, np, src, &dlen);
    if (dkey && direct_use(memo, dkey, dlen, obj) == 0) {
        log_use(memo, "used-direct", src);
        free(dkey);
        free(pre);
        return 0;
    }

    /* 1. The key: the compiler, the arguments but -c and -o OBJ, the text. */
    pre[np++] = "-E";
    pre[np] = NULL;
    int fds[2];
    if (pipe(fds) != 0)
        run_real(argv);
    pid_t pid = fork();
    if (pid < 0)
        run_real(argv);
    if (pid == 0) {
        close(fds[0]);
        int null = open("/dev/null", O_WRONLY);
        if (dup2(fds[1], 1) < 0 || null < 0 || dup2(null, 2) < 0)
            _exit(127);
        execv(real_cc, pre);
        _exit(127);
    }
    close(fds[1]);
    size_t textlen = 0;
    char *text = ccmemo_slurp_fd(fds[0], KEY_MAX, &textlen);
    close(fds[0]);
    int st;
    while (waitpid(pid, &st, 0) < 0 && errno == EINTR)
        ;
    if (!text || !WIFEXITED(st) || WEXITSTATUS(st) != 0)
        run_real(argv);                         /* let the compiler say why */
    size_t head = strlen(real_cc) + 1;
    for (int k = 1; k < np - 1; k++)
        head += strlen(pre[k]) + 1;
    char *key = malloc(head + textlen + 1);
    if (!key)
        run_real(argv);
    size_t keylen = 0;
    for (int k = 0; k < np - 1; k++) {
        size_t n = strlen(pre[k]);
        memcpy(key + keylen, pre[k], n);
        key[keylen + n] = '\n';
        keylen += n + 1;
    }
    memcpy(key + keylen, text, textlen);
    keylen += textlen;

    /* 2 and 3; then 4, a direct entry for the next time. */
    int status = serve_or_make(memo, key, keylen, obj, argv, "compiled", "used", src, &served, &said,
                               &said_len);
    if (status == 0 && dkey)
        direct_keep(memo, dkey, dlen, pre, np - 1, src, text, textlen, obj, said, said_len);
    free(said);
    return status;
}
