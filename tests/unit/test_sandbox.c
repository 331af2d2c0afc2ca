/*
 * The grader's sandbox (tests/grader/sandbox.c) and its jail (jail.c) on
 * small shell programs: each limit stops what it is for, and says so; a
 * run sees nothing of the grader's, nothing of another run's, and leaves
 * nothing behind.  The programs are /bin/sh builtins only, so they run the
 * same on Linux and macOS, started as the grader starts its tests (through
 * init_sh, beside this program: harness_init.h); what only Linux has
 * (/proc, oom_score_adj) is checked there and said to be skipped
 * elsewhere.  Run in the mode the system allows, and again with
 * GRADE_JAIL=fallback (tests/run.sh).
 */
#define _XOPEN_SOURCE 700     /* posix_openpt and the rest of a pseudo-terminal */
#define _DEFAULT_SOURCE       /* syscall, on glibc */
#define _DARWIN_C_SOURCE      /* macOS: the rest too */
#include "check.h"            /* first: it sets the POSIX feature level */
#include <stdbool.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pwd.h>
#include <time.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/prctl.h>         /* portable: __linux__ */
#include <sys/syscall.h>
#endif
#include "../grader/jail.h"
#include "kit/savefile.h"
#include "../grader/sandbox.h"

/* init_sh, found beside this program (main). */
static char init_sh[4096];

/* Runs init_sh with the arguments first and second (sh -c script, or
 * --key NAME, or --socket and NULL) with spec's limits, its working folder made in a fresh
 * directory, through a copy of init_sh there (a folder it may read,
 * whatever folder the kit is in); 0 if it ran. */
static int run_init(const char *first, const char *second, SandboxSpec spec, SandboxResult *res)
{
    char dir[512], work[600], bin[600], program[700], err[256];
    if (check_temp_dir(dir, sizeof dir, "sandbox") != 0)
        return -1;
    chmod(dir, 0711);
    snprintf(work, sizeof work, "%s/run", dir);
    snprintf(bin, sizeof bin, "%s/bin", dir);
    snprintf(program, sizeof program, "%s/init_sh", bin);
    if (mkdir(bin, 0755) != 0 || chmod(bin, 0755) != 0 ||
        jail_take_file(init_sh[0] ? init_sh : "/", "init_sh", program, 16 << 20, err, sizeof err) != 0 ||
        chmod(program, 0755) != 0) {
        CHECK_MSG(0, "cannot copy init_sh (%s): %s", init_sh, err);
        check_remove_tree(dir);
        return -1;
    }
    const char *visible[] = { bin, NULL };
    char *argv[] = { program, (char *)first, (char *)second, NULL };
    spec.argv = argv;
    spec.workdir = work;
    spec.visible = visible;
    spec.init = true;
    if (!spec.timeout)
        spec.timeout = 10;
    spec.answer_max = 4096;
    spec.output_max = 4096;
    int rc = sandbox_run(&spec, res, err, sizeof err);
    CHECK_MSG(rc == 0, "sandbox_run: %s", err);
    if (check_remove_tree(dir) != 0)
        printf("    (could not remove %s)\n", dir);
    return rc;
}

static int run_sh(const char *script, SandboxSpec spec, SandboxResult *res)
{
    return run_init("-c", script, spec, res);
}

/* Of a run's flags (timed out, memory, output, output truncated): either
 * way (the default), set, or not set. */
enum { ANY, YES, NO };

/* One run of a shell script and what it must come to: on each line only
 * what is given is checked.  exit is the exit status wanted as text, "!0"
 * for any but 0; signal (or or_signal) the signal wanted; with or_exit a
 * nonzero exit will do instead of the signal, or of the memory flag. */
typedef struct {
    const char *name, *script;
    SandboxSpec spec;
    bool needs_watch;               /* skipped where sandbox_watches_memory() is false */
    int timed_out, memory, output, truncated;
    const char *exit;
    int signal, or_signal;
    bool or_exit;
    double within;                  /* seconds it must stop within, or 0 */
    const char *answer, *not_answer, *output_has;
} Run;

/* A shell that doubles a string up to 128 MiB (about three times that in
 * use while it copies), then sleeps: a hog with a ceiling, so that a broken
 * limit fails the test without taking the machine's memory.  The hogs'
 * limit, HOG_MB, is several times what dash or bash holds when it starts
 * (1.5 and 3 MiB here), and low enough that the hog reaches it in a few
 * doublings: each test with a hog burns CPU until it is stopped. */
#define HOG_MB 16
#define HOG "x=0123456789abcdef; while [ ${#x} -lt 134217728 ]; do x=$x$x; done; sleep 10"
#define SPAM "while :; do echo spam spam spam spam spam spam spam; done"

/* cpu_seconds bounds CPU time apart from the wall clock: the child's limit
 * is the spec's, soft and hard (so that it cannot lift it), and a child
 * that spins is stopped by it, reported as stopped by a signal and not as
 * out of time.  The system counts that limit in whole seconds, so the spin
 * costs a CPU-second; the sanitized build, whose sandbox code runs the same
 * either way, has its child send itself the limit's signal instead
 * (CHECK_SANITIZED).  This is the kit's one check that the system's limit
 * stops a spinning child. */
#if CHECK_SANITIZED
#define SPIN CHECK_SAY_CPU_LIMIT "kill -XCPU $$"
#else
#define SPIN CHECK_SAY_CPU_LIMIT "while :; do :; done"
#endif

static const Run runs[] = {
    /* Over memory_mb, the parent's watch stops it even with the address
     * space left wide open (as macOS leaves it), within a second or two. */
    { "the memory watch", HOG, { .memory_mb = HOG_MB, .address_mb = 2048 }, .needs_watch = true,
      .memory = YES, .timed_out = NO, .within = 5, .exit = "-1" },
    /* With the address space limited too, the hog is stopped one way or
     * the other (its allocation fails, or the watch kills it), never left
     * to run. */
    { "the hog", HOG, { .memory_mb = HOG_MB }, .timed_out = NO, .memory = YES, .or_exit = true, .within = 5 },
    /* A program under its memory limit runs to the end and is not flagged. */
    { "a small program", "x=abc; echo \"$x$x\" >&3", { .memory_mb = 48 }, .exit = "0", .memory = NO,
      .answer = "abcabc" },
    /* A child killed from outside (as by the out-of-memory killer) is
     * reported as killed by its signal, not as a timeout or a memory
     * overrun. */
    { "killed", "echo started >&3; kill -9 $$", { .memory_mb = 48 }, .signal = SIGKILL, .exit = "-1",
      .timed_out = NO, .memory = NO, .answer = "started" },
    { "the CPU limit", SPIN, { .memory_mb = 48, .cpu_seconds = 1, .timeout = 20 },
      .answer = "limit 1\nhard 1\n", .signal = SIGXCPU, .or_signal = SIGKILL, .timed_out = NO, .within = 10 },
    /* The wall clock stops a child that uses no CPU at all. */
    { "the wall clock", "sleep 5", { .memory_mb = 48, .max_procs = -1, .timeout = 0.2 }, .timed_out = YES,
      .within = 2 },
    /* No file output: writing one is stopped by SIGXFSZ. */
    { "no file output", "echo x >out.txt; echo after >&3", { .memory_mb = 48 }, .signal = SIGXFSZ,
      .or_exit = true },
    /* max_procs 0: the child itself runs (RLIMIT_NPROC is checked at fork,
     * and on Linux at exec only after a setuid that found the user over
     * it, which the limit, set after the setuid, cannot cause), but it
     * cannot fork: the shell says so.  -1, the compiler's: it must fork. */
    { "no processes", "echo ran >&3; /bin/echo forked >&3", { .memory_mb = 48 }, .answer = "ran",
      .not_answer = "forked", .exit = "!0" },
    { "processes", "/bin/echo forked >&3", { .memory_mb = 48, .max_procs = -1 }, .answer = "forked" },
    /* output_stop: a child that prints without end is stopped once the
     * parent has read that much, long before its time is up, and says so;
     * output_max of it is kept.  Without output_stop the same child runs
     * out of time (spent printing: kept short); a little output is fine
     * (5 s: a loaded machine may take 0.2 s). */
    { "output stop", SPAM, { .memory_mb = 48, .output_stop = 256 << 10, .timeout = 5 }, .output = YES,
      .timed_out = NO, .within = 2, .exit = "-1", .truncated = YES, .output_has = "spam" },
    { "no output stop", SPAM, { .memory_mb = 48, .timeout = 0.2 }, .output = NO, .timed_out = YES },
    { "a little output", "echo hello; echo done >&3", { .memory_mb = 48, .output_stop = 256 << 10, .timeout = 5 },
      .output = NO, .exit = "0", .answer = "done" },
};

/* Whether flag is as want (ANY, YES or NO) says. */
static bool flag_is(bool flag, int want)
{
    return want == ANY || flag == (want == YES);
}

/* Whether r came to what c wants of its flags, its end and its time. */
static bool ended_as_wanted(const Run *c, const SandboxResult *r)
{
    char code[16];
    snprintf(code, sizeof code, "%d", r->exit_code);
    bool by_exit = c->or_exit && r->exit_code != 0;
    return flag_is(r->timed_out, c->timed_out) && flag_is(r->output_exceeded, c->output) &&
           flag_is(r->output_truncated, c->truncated) && (flag_is(r->memory_exceeded, c->memory) || by_exit) &&
           (!c->signal || r->signal == c->signal || (c->or_signal && r->signal == c->or_signal) || by_exit) &&
           (!c->exit || strcmp(code, c->exit) == 0 || (strcmp(c->exit, "!0") == 0 && r->exit_code != 0)) &&
           (!c->within || r->seconds < c->within);
}

/* Each run of the table, and what it came to. */
static void test_runs(void)
{
    for (int k = 0; k < CHECK_COUNT(runs); k++) {
        const Run *c = &runs[k];
        SandboxResult r;
        if (c->needs_watch && !sandbox_watches_memory()) {
            printf("    %s skipped: this system does not let the grader see a child's memory\n", c->name);
            continue;
        }
        if (run_sh(c->script, c->spec, &r) != 0)
            continue;
        CHECK_MSG(ended_as_wanted(c, &r),
                  "%s: exit %d, signal %d, timed out %d, memory %d, output %d (truncated %d), after %.2f s",
                  c->name, r.exit_code, r.signal, r.timed_out, r.memory_exceeded, r.output_exceeded,
                  r.output_truncated, r.seconds);
        CHECK_MSG(!c->answer || strstr(r.answer, c->answer), "%s: answered \"%s\"", c->name, r.answer);
        CHECK_MSG(!c->not_answer || !strstr(r.answer, c->not_answer), "%s: answered \"%s\"", c->name, r.answer);
        CHECK_MSG(!c->output_has || strstr(r.output, c->output_has), "%s: printed \"%s\"", c->name, r.output);
        sandbox_result_free(&r);
    }
}

/* The process of a run whose command line ends in word, seen from here
 * (/proc): its pid, or 0 when none is there within seconds. */
static long find_process(const char *word, double seconds)
{
    for (double waited = 0; waited < seconds; waited += 0.01) {
        DIR *d = opendir("/proc");                               /* portable: Linux only, guarded */
        struct dirent *e;
        long found = 0;
        while (d && !found && (e = readdir(d))) {
            char path[300], cmd[256];
            snprintf(path, sizeof path, "/proc/%s/cmdline", e->d_name);     /* portable: as above */
            FILE *f = e->d_name[0] >= '1' && e->d_name[0] <= '9' ? fopen(path, "r") : NULL;
            size_t n = f ? fread(cmd, 1, sizeof cmd - 1, f) : 0;
            if (f)
                fclose(f);
            cmd[n] = '\0';
            size_t last = n > 1 ? n - 1 : 0;              /* the last argument, after its NUL */
            while (last > 0 && cmd[last - 1] != '\0')
                last--;
            if (n > 0 && strcmp(cmd + last, word) == 0)
                found = strtol(e->d_name, NULL, 10);
        }
        if (d)
            closedir(d);
        if (found)
            return found;
        nanosleep(&(struct timespec){ 0, 10000000 }, NULL);
    }
    return 0;
}

/* The line of /proc/PID/status that starts with key, or "". */
static void status_line(long pid, const char *key, char *out, size_t n)
{
    char path[64], line[256];
    snprintf(path, sizeof path, "/proc/%ld/status", pid);                  /* portable: Linux only */
    FILE *f = fopen(path, "r");
    out[0] = '\0';
    while (f && fgets(line, sizeof line, f))
        if (strncmp(line, key, strlen(key)) == 0)
            snprintf(out, n, "%s", line + strlen(key));
    if (f)
        fclose(f);
}

/* On Linux the child asks the out-of-memory killer to take it first.  In
 * the namespace jail, which has no /proc, that is seen from here, with the
 * process's other namespace: a PID of its own (two numbers on NSpid). */
static void test_oom_score_adj(void)
{
    struct stat st;
    if (stat("/proc/self/oom_score_adj", &st) != 0) {         /* portable: skipped */
        printf("    skipped: no /proc/self/oom_score_adj on this system\n");
        return;
    }
    SandboxResult res;
    SandboxSpec spec = { .memory_mb = 48, .max_procs = 0 };
    if (!jail_namespaces()) {
        if (run_sh("read v </proc/self/oom_score_adj; echo \"adj $v\" >&3", spec, &res) != 0)
            return;
        CHECK_STR_CONTAINS(res.answer, "adj 1000");
        sandbox_result_free(&res);
        return;
    }
    pid_t pid = fork();
    if (pid == 0) {
        if (run_sh("exec /bin/sleep 0.718281", spec, &res) == 0)
            sandbox_result_free(&res);
        _exit(0);
    }
    long seen = find_process("0.718281", 5);
    CHECK_MSG(seen > 0, "the jailed sleep was not found in /proc");
    if (seen > 0) {
        char path[64], adj[32] = "", nspid[256];
        snprintf(path, sizeof path, "/proc/%ld/oom_score_adj", seen);     /* portable: Linux only */
        FILE *f = fopen(path, "r");
        if (f && !fgets(adj, sizeof adj, f))
            adj[0] = '\0';
        if (f)
            fclose(f);
        CHECK_MSG(strncmp(adj, "1000", 4) == 0, "oom_score_adj %s", adj);
        status_line(seen, "NSpid:", nspid, sizeof nspid);
        long outer = 0, inner = 0;
        CHECK_MSG(sscanf(nspid, "%ld %ld", &outer, &inner) == 2 && inner == 2,
                  "NSpid:%s (want this pid and 2: the second process of a PID namespace of its own)", nspid);
    }
    while (pid > 0 && waitpid(pid, NULL, 0) < 0 && errno == EINTR)
        continue;
}

/* The ids another process is given while this one holds its own: in
 * out[0 .. 2], and how many it was given; -1 if it could not say. */
static int others_ids(uid_t out[3])
{
    int p[2];
    if (pipe(p) != 0)
        return -1;
    pid_t pid = fork();
    if (pid == 0) {
        const char *unclaimed;
        uid_t ids[3];
        int n = sandbox_spare_users(ids, 3, &unclaimed);
        ssize_t w = write(p[1], ids, (size_t)n * sizeof ids[0]);
        _exit(w == (ssize_t)((size_t)n * sizeof ids[0]) ? 0 : 1);
    }
    close(p[1]);
    ssize_t r = pid > 0 ? read(p[0], out, 3 * sizeof out[0]) : -1;
    close(p[0]);
    int status;
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
        r < 0)
        return -1;
    return (int)((size_t)r / sizeof out[0]);
}

/* Whether some live process holds id now (another grader on this machine,
 * as beside the other suites of make test).  Asked by a child: closing a
 * descriptor of the lock file here would drop this process's own claims. */
static bool held_now(uid_t id)
{
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open(SANDBOX_USERS_LOCK, O_RDONLY);
        struct flock fl = { .l_type = F_WRLCK, .l_whence = SEEK_SET, .l_start = (off_t)id, .l_len = 1 };
        _exit(fd >= 0 && fcntl(fd, F_GETLK, &fl) == 0 && fl.l_type != F_UNLCK ? 0 : 1);
    }
    int status;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* Two graders at once are given different ids; and ids are free again
 * when the grader that held them has ended (unless another grader on the
 * machine has taken them since). */
static void check_claims(const uid_t *ids, int n)
{
    uid_t first[3], again[3];
    int m = others_ids(first);
    CHECK_MSG(m > 0, "another process was given %d ids while this one held %d", m, n);
    for (int k = 0; k < m; k++)
        for (int j = 0; j < n; j++)
            CHECK_MSG(first[k] != ids[j], "id %lu given to two processes at once", (unsigned long)ids[j]);
    bool freed = m <= 0;
    for (int tries = 0; tries < 5 && !freed; tries++) {    /* another grader may come and go */
        int got = others_ids(again);
        for (int k = 0; k < got; k++)
            freed = freed || again[k] == first[0];
        freed = freed || held_now(first[0]);
    }
    CHECK_MSG(freed, "ids not freed when their process ended: %lu, then %lu", (unsigned long)first[0],
              (unsigned long)again[0]);
}

/* As root, grade --all's spare users: distinct ids that are not nobody's
 * and that no account has, and a child given one runs as it (the empty
 * file it makes, which the file-size limit of 0 allows, is that id's).
 * Where the system gives none (a user namespace that maps few ids), grade
 * --all grades one at a time, and this says it skipped. */
static void test_spare_users(void)
{
    if (!sandbox_drops_privileges()) {
        printf("    skipped: not root, so the children run as this user\n");
        return;
    }
    uid_t ids[3];
    const char *unclaimed;
    int n = sandbox_spare_users(ids, 3, &unclaimed);
    if (n == 0) {
        printf("    skipped: this system gives no spare user ids (a user namespace that maps few)\n");
        return;
    }
    if (unclaimed)
        printf("    the ids are not held against other graders (%s): that check was skipped\n", unclaimed);
    else
        check_claims(ids, n);
    struct passwd *nobody = getpwnam("nobody");
    for (int k = 0; k < n; k++) {
        CHECK_MSG(getpwuid(ids[k]) == NULL, "id %lu has an account", (unsigned long)ids[k]);
        CHECK(!nobody || ids[k] != nobody->pw_uid);
        CHECK(ids[k] != 0);
        for (int j = 0; j < k; j++)
            CHECK(ids[j] != ids[k]);
    }
    uid_t held_uid;
    gid_t held_gid;
    sandbox_ids(&held_uid, &held_gid);
    sandbox_set_user(ids[0], false);
    SandboxResult res;
    if (run_sh("exec /usr/bin/id -u >&3", (SandboxSpec){ .memory_mb = 48, .max_procs = 0 }, &res) == 0) {
        char want[64];
        snprintf(want, sizeof want, "%lu\n", (unsigned long)ids[0]);
        CHECK_MSG(strcmp(res.answer, want) == 0, "ran as %s, not %lu", res.answer, (unsigned long)ids[0]);
        sandbox_result_free(&res);
    }
    sandbox_set_user(held_uid, true);
}

/* The child gets stdin, stdout and stderr and the answers on fd 3, and
 * none of the grader's other descriptors; the grader's own stay open. */
static void test_descriptors_closed(void)
{
    int keep[3] = { -1, -1, -1 }, want[3] = { 5, 7, 9 };
    for (int k = 0; k < 3; k++) {
        int fd = open("/dev/null", O_RDONLY);
        CHECK(fd >= 0);
        if (fd < 0)
            return;
        keep[k] = dup2(fd, want[k]);
        close(fd);
        CHECK(keep[k] == want[k]);
    }
    SandboxResult res;
    SandboxSpec spec = { .memory_mb = 48, .max_procs = -1 };
    if (run_sh("for n in 4 5 6 7 8 9; do (: <&$n) 2>/dev/null && echo \"open $n\" >&3; done; "
               "echo checked >&3", spec, &res) == 0) {
        CHECK_STR_CONTAINS(res.answer, "checked");
        CHECK_MSG(!strstr(res.answer, "open"), "the child kept descriptors: %s", res.answer);
        sandbox_result_free(&res);
    }
    for (int k = 0; k < 3; k++) {
        CHECK_MSG(fcntl(want[k], F_GETFD) != -1, "the grader's fd %d was closed", want[k]);
        close(want[k]);
    }
}

/* Opened from the grader's session, a child with a controlling terminal
 * could write on it and push input into it (TIOCSTI).  Here a process that
 * has a terminal of its own (a pseudo-terminal, its controlling terminal)
 * runs a child that tries to open /dev/tty.  Exit status of that process:
 * 0 the child could not, 1 it could, 2 no terminal to be had here. */
static int terminal_probe(void)
{
    alarm(60);                      /* never a hung suite */
    int master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0 || !ptsname(master) || setsid() < 0)
        return 2;
    int tty = open(ptsname(master), O_RDWR);
    if (tty >= 0)
        ioctl(tty, TIOCSCTTY, 0);   /* Linux made it ours as it opened; BSD needs this */
    int own = open("/dev/tty", O_RDWR);
    if (tty < 0 || own < 0)
        return 2;
    close(own);
    SandboxResult res;
    SandboxSpec spec = { .memory_mb = 48, .max_procs = -1 };
    if (run_sh("(: <>/dev/tty) 2>/dev/null && echo reached >&3; echo checked >&3", spec, &res) != 0)
        return 2;
    int reached = strstr(res.answer, "checked") && strstr(res.answer, "reached") ? 1 : 0;
    if (!strstr(res.answer, "checked"))
        reached = 1;                /* the check did not run: no pass */
    sandbox_result_free(&res);
    return reached;
}

static void test_no_terminal(void)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0)
        _exit(terminal_probe());
    CHECK(pid > 0);
    int status = 0;
    if (pid <= 0 || waitpid(pid, &status, 0) != pid)
        return;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 2) {
        printf("    skipped: no pseudo-terminal to be had here\n");
        return;
    }
    CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0,
              "a child reached the grader's terminal through /dev/tty (status %d)", status);
}

/* Seconds on the monotonic clock. */
static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec / 1e9;
}

/* Should the grader be killed (SIGKILL, which it cannot catch), its run
 * goes with it: nothing is left waiting.  A process of the test's, the
 * grader here, starts a run that sleeps 3 s and is killed once the run
 * has begun; the test, made the process that orphans come to (a
 * subreaper), sees the run end at once by SIGKILL, not by itself later.
 * It signals only its own child. */
static void test_run_ends_with_grader(void)
{
#if defined(__linux__)
    CHECK(prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);                   /* portable: __linux__ */
    fflush(stdout);
    pid_t grader = fork();
    if (grader == 0) {
        SandboxResult res;
        SandboxSpec spec = { .memory_mb = 48, .max_procs = -1, .timeout = 20 };
        if (run_sh("sleep 3", spec, &res) == 0)
            sandbox_result_free(&res);
        _exit(0);
    }
    CHECK(grader > 0);
    if (grader <= 0)
        return;
    /* The run has begun once the grader has a child. */
    char children[128], text[64] = "";
    snprintf(children, sizeof children, "/proc/%ld/task/%ld/children", (long)grader, (long)grader);  /* portable: __linux__ */
    for (double t0 = now_seconds(); !text[0] && now_seconds() - t0 < 10;) {
        FILE *f = fopen(children, "r");
        if (!f || !fgets(text, sizeof text, f))
            text[0] = '\0';
        if (f)
            fclose(f);
        nanosleep(&(struct timespec){ 0, 20000000 }, NULL);
    }
    CHECK_MSG(text[0], "the run did not begin");
    kill(grader, SIGKILL);
    int status = 0;
    waitpid(grader, &status, 0);
    double killed_at = now_seconds();
    pid_t run = 0;
    while (run == 0 && now_seconds() - killed_at < 6) {
        run = waitpid(-1, &status, WNOHANG);
        if (run == 0)
            nanosleep(&(struct timespec){ 0, 20000000 }, NULL);
    }
    CHECK_MSG(run > 0, "no run came to the test (waitpid: %s)", run < 0 ? strerror(errno) : "none");
    CHECK_MSG(run <= 0 || (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL && now_seconds() - killed_at < 1.5),
              "the run outlived its grader: it ended %.1f s later, status %d", now_seconds() - killed_at, status);
#else
    printf("    skipped: only Linux ends a process with its parent (PR_SET_PDEATHSIG)\n");
#endif
}

/* Runs init_sh FIRST SECOND and checks that its answer says want, else
 * fails saying what; unless this build has no seccomp filter, which is
 * said to be skipped. */
static void check_filtered(const char *first, const char *second, const char *want, const char *what)
{
    if (!jail_filters()) {
        printf("    skipped: runs get no seccomp filter here (it needs Linux on x86-64 or arm64, the kernel's headers and a kernel with seccomp)\n");
        return;
    }
    SandboxResult res;
    SandboxSpec spec = { .memory_mb = 48, .max_procs = -1 };
    if (run_init(first, second, spec, &res) == 0) {
        CHECK_MSG(strstr(res.answer, want), "%s: %s", what, res.answer);
        sandbox_result_free(&res);
    }
}

/* No run reaches the kernel's key store: not the grader's session keys,
 * and nothing it could leave there for a later run.  The test puts a key
 * in its own session keyring, which a child shares, and the run looks
 * for it. */
static void test_no_keys(void)
{
#if defined(__linux__)
    const char *name = "rtgrade-test-key";
    long key = syscall(SYS_add_key, "user", name, "secret", 6L, -3L);    /* the session keyring */
    if (key < 0) {
        printf("    skipped: this system keeps no keys for its processes (%s)\n", strerror(errno));
        return;
    }
    check_filtered("--key", name, "key not found", "the run reached the grader's keys");
    syscall(SYS_keyctl, 9L, key, -3L);                                  /* KEYCTL_UNLINK */
#else
    printf("    skipped: only Linux has a key store\n");
#endif
}

/* No run reaches the network: not even a socket (in the fallback jail the
 * network would be the system's, and a run could send its cases away). */
static void test_no_network(void)
{
    check_filtered("--socket", NULL, "inet refused, unix refused", "a run made a socket");
}

/* jail_remove_tree removes a folder 20,000 deep (deeper than a path may
 * be long), with links in it that it does not follow, and a folder made
 * unreadable; without recursion, so it cannot run out of stack. */
static void test_remove_deep_tree(void)
{
    char dir[512], top[600], keep[600];
    if (check_temp_dir(dir, sizeof dir, "deep") != 0)
        return;
    snprintf(top, sizeof top, "%s/tree", dir);
    snprintf(keep, sizeof keep, "%s/kept", dir);
    check_write_file(keep, "", 0);
    CHECK(mkdir(top, 0700) == 0);
    int at = open(top, O_RDONLY | O_DIRECTORY);
    for (int k = 0; k < 20000 && at >= 0; k++) {
        if (k % 1000 == 0) {
            CHECK(symlinkat(keep, at, "link") == 0);
            CHECK(symlinkat(dir, at, "up") == 0);
        }
        int down = mkdirat(at, "d", k == 19999 ? 0 : 0700) == 0 ? openat(at, "d", O_RDONLY | O_DIRECTORY) : -1;
        close(at);
        at = down;
    }
    if (at >= 0)
        close(at);
    CHECK_EQ_INT(jail_remove_tree(top), 0);
    struct stat st;
    CHECK_MSG(lstat(top, &st) != 0, "the tree is still there");
    CHECK_MSG(stat(keep, &st) == 0, "a file a link pointed at was removed");
    check_remove_tree(dir);
}

/* jail_take_file copies a plain file back and refuses anything else a run
 * could have put in its place: a link (to a file only the grader may
 * read), a second link to a file, a pipe, a folder, a file over its size. */
static void test_take_file(void)
{
    char dir[512], path[700], secret[700], to[700], why[256];
    if (check_temp_dir(dir, sizeof dir, "take") != 0)
        return;
    snprintf(secret, sizeof secret, "%s/secret", dir);
    snprintf(to, sizeof to, "%s/copy", dir);
    check_write_file(secret, "not for the run\n", 16);
    snprintf(path, sizeof path, "%s/plain", dir);
    check_write_file(path, "object\n", 7);
    CHECK_EQ_INT(jail_take_file(dir, "plain", to, 100, why, sizeof why), 0);
    size_t n = 0;
    char *copied = kit_load_file(to, 100, &n);
    CHECK_MSG(copied && n == 7 && memcmp(copied, "object\n", 7) == 0, "copied %zu bytes", n);
    free(copied);
    CHECK_MSG(jail_take_file(dir, "plain", to, 6, why, sizeof why) != 0, "a file over its size taken");
    snprintf(path, sizeof path, "%s/link", dir);
    CHECK(symlink(secret, path) == 0);
    CHECK_MSG(jail_take_file(dir, "link", to, 100, why, sizeof why) != 0, "a link followed");
    snprintf(path, sizeof path, "%s/hard", dir);
    CHECK(link(secret, path) == 0);
    CHECK_MSG(jail_take_file(dir, "hard", to, 100, why, sizeof why) != 0, "a second link to a file taken");
    snprintf(path, sizeof path, "%s/pipe", dir);
    CHECK(mkfifo(path, 0600) == 0);
    CHECK_MSG(jail_take_file(dir, "pipe", to, 100, why, sizeof why) != 0, "a pipe taken");
    snprintf(path, sizeof path, "%s/folder", dir);
    CHECK(mkdir(path, 0700) == 0);
    CHECK_MSG(jail_take_file(dir, "folder", to, 100, why, sizeof why) != 0, "a folder taken");
    copied = kit_load_file(to, 100, &n);
    CHECK_MSG(!copied || !strstr(copied, "not for the run"), "the secret was copied");
    free(copied);
    check_remove_tree(dir);
}

/* As root, a folder anyone may write in away from /tmp and the other
 * usual places, four levels below / (as /var/lib/php/sessions is): what a
 * run leaves there is gone after it, swept in the fallback jail, never
 * made in the namespace jail (where the run cannot see the folder).  The
 * first test: the sweep finds its places at the grader's first run, and
 * a system's folders are there before it. */
static void test_sweep_places(void)
{
    if (!sandbox_drops_privileges()) {
        printf("    skipped: not root, so no run has an id of its own to sweep\n");
        return;
    }
    char top[32] = "/rtsweep.XXXXXX", dir[64], left[96], script[160];
    static const char *const below[] = { "/a", "/a/b", "/a/b/drop" };
    if (!mkdtemp(top) || chmod(top, 0755) != 0) {
        CHECK_MSG(0, "cannot make %s: %s", top, strerror(errno));
        return;
    }
    for (int k = 0; k < 3; k++) {
        snprintf(dir, sizeof dir, "%s%s", top, below[k]);
        CHECK(mkdir(dir, 0755) == 0 && chmod(dir, k == 2 ? 01777 : 0755) == 0);
    }
    snprintf(left, sizeof left, "%s/left", dir);
    snprintf(script, sizeof script, ": >%s && echo made >&3", left);
    SandboxResult res;
    if (run_sh(script, (SandboxSpec){ .memory_mb = 48, .max_procs = 0 }, &res) == 0) {
        struct stat st;
        CHECK_MSG(lstat(left, &st) != 0, "what the run left in %s is still there", dir);
        if (jail_namespaces())
            CHECK_MSG(!strstr(res.answer, "made"), "a run in the namespace jail wrote in %s", dir);
        else
            CHECK_MSG(strstr(res.answer, "made"), "the run could not write in %s: nothing checked", dir);
        sandbox_result_free(&res);
    }
    check_remove_tree(top);
}

/* A program that cannot be started (no such file), and a jail that cannot
 * be built (a folder to show it that is not there): each is reported as the
 * run's exit status (127, and 125 in the namespace jail), and nothing is
 * signalled but the run's own process: this test, and its suite, go on. */
static void test_cannot_start(void)
{
    char dir[512], work[600], missing[600], err[256];
    if (check_temp_dir(dir, sizeof dir, "nostart") != 0)
        return;
    chmod(dir, 0711);
    snprintf(work, sizeof work, "%s/run", dir);
    snprintf(missing, sizeof missing, "%s/not-there", dir);
    char *argv[] = { missing, NULL };
    SandboxSpec spec = { .argv = argv, .workdir = work, .timeout = 5, .answer_max = 64,
                         .output_max = 4096, .memory_mb = 48, .max_procs = 0, .init = true };
    SandboxResult res;
    CHECK_EQ_INT(sandbox_run(&spec, &res, err, sizeof err), 0);
    CHECK_EQ_INT(res.exit_code, 127);
    CHECK(!res.timed_out && res.signal == 0);
    sandbox_result_free(&res);
    if (jail_namespaces()) {
        const char *visible[] = { missing, NULL };
        char *sh[] = { "/bin/sh", "-c", "exit 0", NULL };
        spec.argv = sh;
        spec.visible = visible;
        CHECK_EQ_INT(sandbox_run(&spec, &res, err, sizeof err), 0);
        CHECK_EQ_INT(res.exit_code, 125);
        CHECK_STR_CONTAINS(res.output, "jail: ");
        sandbox_result_free(&res);
    }
    check_remove_tree(dir);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_sweep_places),     CHECK_TEST(test_cannot_start),
    CHECK_TEST(test_remove_deep_tree), CHECK_TEST(test_take_file),
    CHECK_TEST(test_runs),             CHECK_TEST(test_oom_score_adj),    CHECK_TEST(test_descriptors_closed),
    CHECK_TEST(test_spare_users),
    CHECK_TEST(test_no_terminal),      CHECK_TEST(test_run_ends_with_grader),
    CHECK_TEST(test_no_keys),          CHECK_TEST(test_no_network),
};

int main(int argc, char **argv)
{
    char exe[4096], self[4096];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);         /* portable: argv[0] else */
    snprintf(self, sizeof self, "%.*s", n > 0 ? (int)n : (int)strlen(argv[0]), n > 0 ? exe : argv[0]);
    char *slash = strrchr(self, '/');
    if (slash)
        snprintf(init_sh, sizeof init_sh, "%.*s", (int)(slash - self), self);
    /* As root, the children run as a spare id held here, as the grader's
     * do (with "nobody" they get no PID namespace of their own). */
    uid_t id;
    const char *unclaimed = NULL;
    if (sandbox_drops_privileges() && sandbox_spare_users(&id, 1, &unclaimed) == 1)
        sandbox_set_user(id, unclaimed == NULL);
    printf("    jail: %s\n", jail_describe());
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
