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
 * Anything else (linking, -E, no CC_MEMO, as in the grader's sandbox, which
 * passes the compiler only PATH) runs the real compiler, which is the next
 * cc on PATH after the directories holding this program's marker file
 * "ccmemo.marker".  The memo's file "log" has a line for each compile it
 * saw: "compiled", "used", "used-direct" or "not-kept", the file and the
 * directory.  An
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

int main(int argc, char **argv)
{
    if (find_real_cc() != 0) {
        fprintf(stderr, "ccmemo: no cc on PATH besides this one\n");
        return 127;
    }
    const char *memo = getenv("CC_MEMO");
    const char *obj = NULL, *src = NULL;
    int compile = 0, oarg = -1;
    for (int k = 1; k < argc; k++) {
        const char *a = argv[k];
        size_t n = strlen(a);
        if (strcmp(a, "-c") == 0)
            compile = 1;
        else if (strcmp(a, "-o") == 0 && k + 1 < argc)
            obj = argv[oarg = ++k];
        else if (a[0] == '-' && (a[1] == 'E' || a[1] == 'S' || a[1] == 'M' || a[1] == 'o' ||
                                 strcmp(a, "-") == 0))
            compile = -1;                       /* not a plain compile */
        else if (a[0] != '-' && n > 2 && strcmp(a + n - 2, ".c") == 0 && !src)
            src = a;
        else if (a[0] != '-')
            compile = -1;                       /* another input */
    }
    if (!memo || !*memo || compile != 1 || !obj || !src)
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

    char entry[4096], lock[4200];
    snprintf(entry, sizeof entry, "%s/%016llx", memo,
             (unsigned long long)ccmemo_fnv1a(key, keylen, 14695981039346656037u));
    snprintf(lock, sizeof lock, "%s.lock", entry);

    /* 2. An entry, or the lock to make it, or wait for who holds it.  The
     * lock holds its maker's pid: a lock whose maker has died (a build
     * interrupted while it compiled) is taken over, not waited for. */
    char holder[4300];
    snprintf(holder, sizeof holder, "%s/pid", lock);
    struct timespec nap = { 0, 20 * 1000 * 1000 };
    for (long waited = 0;; waited++) {
        char *kept_messages = NULL;
        size_t kept_len = 0;
        if (use_entry(entry, key, keylen, obj, &kept_messages, &kept_len) == 0) {
            utimensat(AT_FDCWD, entry, NULL, 0);   /* used now: tests/run.sh keeps it */
            log_use(memo, "used", src);
            if (dkey)
                direct_keep(memo, dkey, dlen, pre, np - 1, src, text, textlen, obj, kept_messages,
                            kept_len);
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

    /* 3. Compile, with the messages kept, and keep a successful result. */
    char messages[4300];
    snprintf(messages, sizeof messages, "%s/messages.%ld", memo, (long)getpid());
    int mfd = open(messages, O_RDWR | O_CREAT | O_TRUNC, 0644);
    argv[0] = real_cc;
    int status = mfd < 0 ? -1 : ccmemo_run(argv, -1, mfd);
    size_t mlen = 0;
    char *m = NULL;
    if (mfd >= 0 && lseek(mfd, 0, SEEK_SET) == 0)
        m = ccmemo_slurp_fd(mfd, KEY_MAX, &mlen);
    if (mfd >= 0)
        close(mfd);
    unlink(messages);
    if (m)
        ccmemo_write_all(2, m, mlen);
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
            ok = ok && put(path, m ? m : "", m ? mlen : 0) == 0;
            snprintf(path, sizeof path, "%s/key", tmpdir);
            ok = ok && put(path, key, keylen) == 0;   /* last: an entry with a key is whole */
            if (!ok || rename(tmpdir, entry) != 0)
                log_use(memo, "not-kept", src);
        }
        free(o);
        log_use(memo, "compiled", src);
        if (dkey)
            direct_keep(memo, dkey, dlen, pre, np - 1, src, text, textlen, obj, m, mlen);
    }
    unlink(holder);
    rmdir(lock);
    free(m);
    if (status < 0)
        run_real(argv);
    return status;
}
