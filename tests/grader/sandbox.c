/*
 * sandbox.c - see sandbox.h.  POSIX: fork, setpgid, setrlimit, poll; vfork
 * on Linux (macOS deprecates it); and what each system offers to see a
 * process's memory (/proc on Linux, libproc on macOS).
 *
 * On Linux vfork, not fork: the grader holds tens of megabytes of tests
 * and figures, and a fork copies its page tables and then makes every page
 * the grader writes fault once (copy on write).  Grading a submission whose
 * failing tests each run alone costs a third less CPU this way.  The child
 * borrows the parent's memory until it runs the program, so everything it
 * needs is prepared before (ChildPlan) and the child itself only calls the
 * system.
 *
 * sandbox_serve_run runs a test through a server of tests instead (a
 * prebuilt runner started with --serve, harness_serve.c): the test's pipes
 * go to the server over a socket (SCM_RIGHTS), the server forks the child,
 * and one watch (watch below) serves both ways; only how the child's end
 * is learnt (the grader's waitpid, or the server's message) and how it is
 * stopped (the grader's kill, or a word to the server) differ.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE         /* setgroups, on glibc */
#define _DARWIN_C_SOURCE        /* setgroups, on macOS */
#include "sandbox.h"
#include "serve_protocol.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#if defined(__APPLE__)
#include <libproc.h>
#endif

double sandbox_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double sandbox_cpu(bool self)
{
    struct rusage ru;
    if (getrusage(self ? RUSAGE_SELF : RUSAGE_CHILDREN, &ru) != 0)
        return 0;
    return (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec +
           (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
}

bool sandbox_drops_privileges(void)
{
    return geteuid() == 0;
}

/* "nobody"'s ids, from the system's list of users. */
static void lookup_nobody(uid_t *uid, gid_t *gid)
{
    struct passwd *pw = getpwnam("nobody");
    *uid = pw ? pw->pw_uid : 65534;
    *gid = pw ? pw->pw_gid : 65534;
}

/* The user the children run as when the grader is root: "nobody" (looked
 * up once), or the id sandbox_set_user gave, as user and as group. */
static bool user_known;
static uid_t user_uid;
static gid_t user_gid;

static void child_ids(uid_t *uid, gid_t *gid)
{
    if (!user_known) {
        lookup_nobody(&user_uid, &user_gid);
        user_known = true;
    }
    *uid = user_uid;
    *gid = user_gid;
}

void sandbox_set_user(uid_t id)
{
    user_uid = id;
    user_gid = (gid_t)id;
    user_known = id != 0;
}

/* The file one byte of which, at the offset of an id, is locked by the
 * grader that holds that id (sandbox.h).  /var/run is root's alone on
 * Linux and macOS, so no one else can make or replace the file. */
#define USERS_LOCK "/var/run/rtgrade-users.lock"

/* The lock file, opened once; -1 with why set when it cannot be used. */
static int users_lock(const char **why)
{
    static int fd = -2;
    static const char *fault;
    if (fd == -2) {
        struct stat st;
        fd = open(USERS_LOCK, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd < 0)
            fault = "cannot open " USERS_LOCK;
        else if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != geteuid() ||
                 (st.st_mode & 022)) {
            fault = USERS_LOCK " is not a file that only root may write";
            close(fd);
            fd = -1;
        }
    }
    *why = fault;
    return fd;
}

/* Locks id's byte: 1 held now by this process, 0 held by another, -1
 * the system cannot lock the file. */
static int claim(int fd, uid_t id, short type)
{
    struct flock fl;
    memset(&fl, 0, sizeof fl);
    fl.l_type = type;
    fl.l_whence = SEEK_SET;
    fl.l_start = (off_t)id;
    fl.l_len = 1;
    if (fcntl(fd, F_SETLK, &fl) == 0)
        return 1;
    return errno == EACCES || errno == EAGAIN ? 0 : -1;
}

int sandbox_spare_users(uid_t *ids, int n, const char **unclaimed)
{
    uid_t nobody;
    gid_t nogroup;
    lookup_nobody(&nobody, &nogroup);
    int fd = users_lock(unclaimed);
    int found = 0;
    for (uid_t id = 65533; id >= 1000 && found < n; id--) {
        if (id == nobody || (gid_t)id == nogroup || getpwuid(id) || getgrgid((gid_t)id))
            continue;
        if (fd >= 0) {
            int held = claim(fd, id, F_WRLCK);
            if (held == 0)
                continue;       /* another grader's */
            if (held < 0) {
                *unclaimed = "the system cannot lock " USERS_LOCK;
                fd = -1;
            }
        }
        pid_t pid = fork();
        if (pid == 0)
            _exit(setgroups(0, NULL) == 0 && setgid((gid_t)id) == 0 && setuid(id) == 0 &&
                  setuid(0) != 0 ? 0 : 1);
        int status;
        if (pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
            WEXITSTATUS(status) == 0) {
            ids[found++] = id;
            continue;
        }
        if (fd >= 0)
            claim(fd, id, F_UNLCK);
        break;              /* this system will not give such ids (a user namespace's map) */
    }
    return found;
}

int sandbox_give(const char *path)
{
    if (!sandbox_drops_privileges())
        return 0;
    uid_t uid;
    gid_t gid;
    child_ids(&uid, &gid);
    return chown(path, uid, gid);
}

static void limit(int resource, rlim_t value)
{
    struct rlimit rl = { value, value };
    setrlimit(resource, &rl);       /* best effort: macOS ignores some */
}

/* The memory the child's group holds, in bytes, or -1 where the system
 * does not say.  macOS: the physical footprint (resident and compressed
 * memory) of every process of the group.  Linux: the leader's resident
 * size, from /proc (tests cannot fork; each of the compiler's processes has
 * its own RLIMIT_AS). */
static long long group_memory(pid_t pgid)
{
#if defined(__APPLE__)
    pid_t pids[256];
    int bytes = proc_listpids(PROC_PGRP_ONLY, (uint32_t)pgid, pids, (int)sizeof pids);
    if (bytes <= 0)
        return -1;
    long long total = 0;
    for (int k = 0; k < bytes / (int)sizeof pids[0]; k++) {
        struct rusage_info_v2 ri;
        if (pids[k] > 0 && proc_pid_rusage(pids[k], RUSAGE_INFO_V2, (rusage_info_t *)&ri) == 0)
            total += (long long)ri.ri_phys_footprint;
    }
    return total;
#elif defined(__linux__)
    char path[64], text[128];
    snprintf(path, sizeof path, "/proc/%ld/statm", (long)pgid);    /* portable: __linux__ */
    int fd = open(path, O_RDONLY);
    if (fd < 0)
        return -1;
    ssize_t n = read(fd, text, sizeof text - 1);
    close(fd);
    long size = 0, resident = 0;
    long page = sysconf(_SC_PAGESIZE);
    if (n <= 0 || page <= 0)
        return -1;
    text[n] = '\0';
    if (sscanf(text, "%ld %ld", &size, &resident) != 2)
        return -1;
    return (long long)resident * page;
#else
    (void)pgid;
    return -1;
#endif
}

bool sandbox_watches_memory(void)
{
#if defined(__APPLE__) || defined(__linux__)
    return true;
#else
    return false;
#endif
}

/* Asks Linux's out-of-memory killer to take this process (and what it
 * runs) before any other, so that the grader survives to report it.  Best
 * effort: other systems have no /proc. */
static void prefer_oom_kill(void)
{
    int fd = open("/proc/self/oom_score_adj", O_WRONLY);      /* portable: none elsewhere */
    if (fd < 0)
        return;
    if (write(fd, "1000\n", 5) < 0) {
        /* nothing to do: the limits still hold */
    }
    close(fd);
}

/* What the child needs, prepared by the parent before it forks: the child
 * shares the parent's memory until it runs the program (vfork), so it
 * calls nothing that allocates or locks, only the system. */
typedef struct {
    const SandboxSpec *spec;
    int in_r, ans_w, out_w;
    int close_fds[256];        /* the parent's descriptors from 4 up          */
    int nclose;                /* -1: more than fit; close them all blindly  */
    bool drop;
    uid_t uid;
    gid_t gid;
    char *envp[4];
    char path_env[4096];
    char tmp_env[4200];
} ChildPlan;

/* The parent's open descriptors from low up, as /dev/fd lists them (Linux,
 * macOS); closing blindly up to the limit can mean a million calls. */
static void plan_close(ChildPlan *cp, int low)
{
    cp->nclose = 0;
    DIR *d = opendir("/dev/fd");
    if (!d) {
        cp->nclose = -1;
        return;
    }
    int self = dirfd(d);
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9')
            continue;
        int fd = atoi(e->d_name);
        if (fd < low || fd == self)
            continue;
        if (cp->nclose == (int)(sizeof cp->close_fds / sizeof cp->close_fds[0])) {
            cp->nclose = -1;
            break;
        }
        cp->close_fds[cp->nclose++] = fd;
    }
    closedir(d);
}

static void plan_child(ChildPlan *cp, const SandboxSpec *spec, int in_r, int ans_w, int out_w)
{
    cp->spec = spec;
    cp->in_r = in_r, cp->ans_w = ans_w, cp->out_w = out_w;
    plan_close(cp, 4);
    cp->drop = sandbox_drops_privileges();
    if (cp->drop)
        child_ids(&cp->uid, &cp->gid);
    const char *path = spec->inherit_path && getenv("PATH") ? getenv("PATH") : "/usr/bin:/bin";
    snprintf(cp->path_env, sizeof cp->path_env, "PATH=%s", path);
    cp->envp[0] = cp->path_env;
    cp->envp[1] = "LC_ALL=C";
    cp->envp[2] = "HOME=/nonexistent";
    cp->envp[3] = NULL;
    if (spec->inherit_path) {      /* the compiler wants a TMPDIR it can write */
        snprintf(cp->tmp_env, sizeof cp->tmp_env, "TMPDIR=%s", spec->workdir);
        cp->envp[2] = cp->tmp_env;
    }
}

/* In the child, after vfork (Linux) or fork: never returns. */
static void child(const ChildPlan *cp)
{
    const SandboxSpec *spec = cp->spec;
    setpgid(0, 0);
    signal(SIGPIPE, SIG_DFL);
    prefer_oom_kill();
    if (dup2(cp->in_r, 0) < 0 || dup2(cp->out_w, 1) < 0 || dup2(cp->out_w, 2) < 0 ||
        dup2(cp->ans_w, 3) < 0)
        _exit(126);
    if (cp->nclose >= 0) {
        for (int k = 0; k < cp->nclose; k++)
            close(cp->close_fds[k]);
    } else {
        long maxfd = sysconf(_SC_OPEN_MAX);
        if (maxfd < 0 || maxfd > 65536)
            maxfd = 65536;
        for (long fd = 4; fd < maxfd; fd++)
            close((int)fd);
    }
    if (chdir(spec->workdir) != 0)
        _exit(126);

    limit(RLIMIT_CORE, 0);
    limit(RLIMIT_CPU, spec->cpu_seconds > 0 ? (rlim_t)spec->cpu_seconds : (rlim_t)(spec->timeout + 2));
    long address_mb = spec->address_mb ? spec->address_mb : spec->memory_mb;
    if (address_mb > 0)
        limit(RLIMIT_AS, (rlim_t)address_mb << 20);     /* macOS refuses it: see group_memory */
    limit(RLIMIT_FSIZE, (rlim_t)spec->max_file_mb << 20);
    if (cp->drop) {
        if (setgroups(0, NULL) != 0 || setgid(cp->gid) != 0 || setuid(cp->uid) != 0 || setuid(0) == 0)
            _exit(126);
    }
    if (spec->max_procs >= 0)
        limit(RLIMIT_NPROC, (rlim_t)spec->max_procs);
    execve(spec->argv[0], spec->argv, cp->envp);
    _exit(127);
}

/* Appends what fd has to (buf, len), keeping at most max bytes and adding
 * to *total all it read; returns 0 at end of file, 1 if it read or would
 * block, -1 on error. */
static int pump(int fd, char **buf, size_t *len, size_t *cap, size_t max, bool *truncated,
                size_t *total)
{
    char chunk[65536];
    ssize_t n = read(fd, chunk, sizeof chunk);
    if (n == 0)
        return 0;
    if (n < 0)
        return errno == EAGAIN || errno == EINTR ? 1 : -1;
    *total += (size_t)n;
    size_t keep = (size_t)n;
    if (*len + keep > max) {
        keep = max > *len ? max - *len : 0;
        *truncated = true;
    }
    if (keep) {
        if (*len + keep + 1 > *cap) {
            size_t ncap = (*len + keep + 1) * 2;
            char *nb = realloc(*buf, ncap);
            if (!nb)
                return -1;
            *buf = nb;
            *cap = ncap;
        }
        memcpy(*buf + *len, chunk, keep);
        *len += keep;
    }
    return 1;
}

/* ---- watching a run ----------------------------------------------------------- */

/* The child being watched: the grader's own (vfork), or a server's. */
typedef struct {
    pid_t pid;                 /* the test's process, which leads its group  */
    SandboxServer *server;     /* NULL: the child is the grader's own        */
    int status;
    bool ended;                /* reaped: status (and, served, cpu) known    */
    bool server_failed;        /* the server died, stopped or fell silent    */
    double cpu;                /* served: the child's CPU, from the server   */
} Run;

/* n bytes from fd (non-blocking) within seconds; 0, or -1 on end of file,
 * error or time out. */
static int read_within(int fd, void *buf, size_t n, double seconds)
{
    char *p = buf;
    double deadline = sandbox_now() + seconds;
    while (n > 0) {
        ssize_t r = read(fd, p, n);
        if (r > 0) {
            p += r;
            n -= (size_t)r;
            continue;
        }
        if (r == 0 || (errno != EAGAIN && errno != EINTR))
            return -1;
        double left = deadline - sandbox_now();
        if (left <= 0)
            return -1;
        struct pollfd pf = { fd, POLLIN, 0 };
        poll(&pf, 1, (int)(left * 1000) + 1);
    }
    return 0;
}

/* Whether the server is still there to report: not dead, not stopped. */
static bool server_alive(SandboxServer *s)
{
    int st;
    pid_t w = waitpid(s->pid, &st, WNOHANG | WUNTRACED);
    if (w == s->pid && !WIFSTOPPED(st))
        s->reaped = true;
    return w == 0;
}

/* Has the child ended?  Served, readable says the socket has news. */
static void check_ended(Run *r, bool readable)
{
    if (!r->server) {
        if (waitpid(r->pid, &r->status, WNOHANG) == r->pid)
            r->ended = true;
        return;
    }
    ServeEnded en;
    if (readable) {
        if (read_within(r->server->sock, &en, sizeof en, 2) != 0) {
            r->server_failed = true;
            return;
        }
        r->status = en.status;
        r->cpu = en.cpu_seconds;
        r->ended = true;
    } else if (!server_alive(r->server)) {
        r->server_failed = true;
    }
}

/* Stops the child and reaps it (the server reaps a served one). */
static void stop(Run *r)
{
    if (!r->server) {
        /* Whatever is left of the group too (its id stays reserved while any
         * member lives, so this reaches no one else). */
        kill(-r->pid, SIGKILL);
        if (!r->ended) {
            kill(r->pid, SIGKILL);
            while (waitpid(r->pid, &r->status, 0) < 0 && errno == EINTR)
                continue;
            r->ended = true;
        }
        return;
    }
    if (!r->ended && !r->server_failed) {
        char k = SERVE_KILL;
        ServeEnded en;
        if (write(r->server->sock, &k, 1) == 1 &&
            read_within(r->server->sock, &en, sizeof en, 2) == 0) {
            r->status = en.status;
            r->cpu = en.cpu_seconds;
            r->ended = true;
        } else {
            r->server_failed = true;
        }
    }
    if (r->server_failed) {
        /* No one reaps it in time: the child cannot have forked (no new
         * processes), so it alone holds its group. */
        kill(-r->pid, SIGKILL);
        kill(r->pid, SIGKILL);
    }
}

/* Feeds the child its input and collects what it writes until it ends or
 * breaks a limit (then stops it), then what is left in the pipes.  The
 * pipes are the grader's ends; each is closed here. */
static void watch(const SandboxSpec *spec, Run *r, SandboxResult *res, int in_fd, int ans_fd,
                  int out_fd, double start)
{
    fcntl(in_fd, F_SETFL, O_NONBLOCK);
    fcntl(ans_fd, F_SETFL, O_NONBLOCK);
    fcntl(out_fd, F_SETFL, O_NONBLOCK);
    size_t in_off = 0, ans_cap = 0, out_cap = 0, ans_total = 0, out_total = 0;
    if (!spec->input_len) {
        close(in_fd);
        in_fd = -1;
    }
    int sock = r->server ? r->server->sock : -1;
    double deadline = start + spec->timeout, next_watch = start;
    bool over = false;

    while (!over) {
        struct pollfd pf[4];
        int n = 0, sock_at = -1;
        if (in_fd >= 0)
            pf[n++] = (struct pollfd){ in_fd, POLLOUT, 0 };
        if (ans_fd >= 0)
            pf[n++] = (struct pollfd){ ans_fd, POLLIN, 0 };
        if (out_fd >= 0)
            pf[n++] = (struct pollfd){ out_fd, POLLIN, 0 };
        if (sock >= 0) {
            sock_at = n;
            pf[n++] = (struct pollfd){ sock, POLLIN, 0 };
        }
        /* With the pipes closed only the child's exit is left to wait for
         * (a served child's is news on the socket, which wakes the poll). */
        poll(pf, (nfds_t)n, n ? 20 : 1);
        if (in_fd >= 0) {
            ssize_t w = write(in_fd, spec->input + in_off, spec->input_len - in_off);
            if (w > 0)
                in_off += (size_t)w;
            if ((w < 0 && errno != EAGAIN && errno != EINTR) || in_off == spec->input_len) {
                close(in_fd);
                in_fd = -1;
            }
        }
        if (ans_fd >= 0 && pump(ans_fd, &res->answer, &res->answer_len, &ans_cap,
                                spec->answer_max, &res->answer_truncated, &ans_total) <= 0) {
            close(ans_fd);
            ans_fd = -1;
        }
        if (out_fd >= 0 && pump(out_fd, &res->output, &res->output_len, &out_cap,
                                spec->output_max, &res->output_truncated, &out_total) <= 0) {
            close(out_fd);
            out_fd = -1;
        }
        /* Ended, out of time, over its output or its memory? */
        check_ended(r, sock_at >= 0 && pf[sock_at].revents);
        if (r->ended || r->server_failed) {
            over = true;
        } else if (spec->output_stop && out_total > spec->output_stop) {
            res->output_exceeded = true;
            over = true;
        } else if (sandbox_now() > deadline) {
            res->timed_out = true;
            over = true;
        } else if (spec->memory_mb > 0 && sandbox_now() >= next_watch) {
            next_watch = sandbox_now() + 0.02;
            if (group_memory(r->pid) > (long long)spec->memory_mb << 20) {
                res->memory_exceeded = true;
                over = true;
            }
        }
    }
    stop(r);
    /* What is already in the pipes, without waiting for anyone to close them. */
    for (int round = 0; round < 64 && (ans_fd >= 0 || out_fd >= 0); round++) {
        if (ans_fd >= 0 && pump(ans_fd, &res->answer, &res->answer_len, &ans_cap,
                                spec->answer_max, &res->answer_truncated, &ans_total) <= 0) {
            close(ans_fd);
            ans_fd = -1;
        }
        if (out_fd >= 0 && pump(out_fd, &res->output, &res->output_len, &out_cap,
                                spec->output_max, &res->output_truncated, &out_total) <= 0) {
            close(out_fd);
            out_fd = -1;
        }
        if (ans_fd >= 0 || out_fd >= 0) {
            struct pollfd pf[2] = { { ans_fd, POLLIN, 0 }, { out_fd, POLLIN, 0 } };
            if (poll(pf, 2, round < 4 ? 5 : 0) == 0)
                break;
        }
    }
    if (in_fd >= 0)
        close(in_fd);
    if (ans_fd >= 0)
        close(ans_fd);
    if (out_fd >= 0)
        close(out_fd);
}

/* The result's last fields, from how the run ended; 0, or -1 out of memory. */
static int finish(const Run *r, SandboxResult *res, double start)
{
    res->seconds = sandbox_now() - start;
    bool killed = res->timed_out || res->memory_exceeded || res->output_exceeded;
    res->exit_code = WIFEXITED(r->status) && !killed ? WEXITSTATUS(r->status) : -1;
    res->signal = WIFSIGNALED(r->status) && !killed ? WTERMSIG(r->status) : 0;
    if (!res->answer && !(res->answer = calloc(1, 1)))
        return -1;
    if (!res->output && !(res->output = calloc(1, 1)))
        return -1;
    res->answer[res->answer_len] = '\0';
    res->output[res->output_len] = '\0';
    return 0;
}

/* The three pipes of a run: [0] the child's stdin, [1] its answers (fd 3),
 * [2] its stdout and stderr; each p[k][0] is read, p[k][1] written. */
static int open_pipes(int p[3][2], char *err, size_t errlen)
{
    for (int k = 0; k < 3; k++)
        if (pipe(p[k]) != 0) {
            snprintf(err, errlen, "pipe: %s", strerror(errno));
            while (k-- > 0) {
                close(p[k][0]);
                close(p[k][1]);
            }
            return -1;
        }
    return 0;
}

/* The server's own CPU limit: it only forks, once per test. */
#define SERVE_CPU_SECONDS 600

/* The plan of the child about to be forked (see ChildPlan). */
static ChildPlan plan;

/* vfork (Linux) or fork, then the child runs spec's program; the child's
 * pid, or -1. */
static pid_t spawn(const SandboxSpec *spec, int in_r, int ans_w, int out_w)
{
    plan_child(&plan, spec, in_r, ans_w, out_w);
#if defined(__linux__)
    pid_t pid = vfork();        /* portable: __linux__ (macOS deprecates vfork: fork there) */
#else
    pid_t pid = fork();
#endif
    if (pid == 0)
        child(&plan);
    if (pid > 0)
        setpgid(pid, pid);      /* also here, so killpg cannot race it */
    return pid;
}

int sandbox_run(const SandboxSpec *spec, SandboxResult *res, char *err, size_t errlen)
{
    int p[3][2];
    memset(res, 0, sizeof *res);
    if (errlen)
        err[0] = '\0';
    signal(SIGPIPE, SIG_IGN);
    if (open_pipes(p, err, errlen) != 0)
        return -1;
    double start = sandbox_now(), cpu_start = sandbox_cpu(false);
    pid_t pid = spawn(spec, p[0][0], p[1][1], p[2][1]);
    if (pid < 0) {
        snprintf(err, errlen, "fork: %s", strerror(errno));
        for (int k = 0; k < 3; k++) {
            close(p[k][0]);
            close(p[k][1]);
        }
        return -1;
    }
    close(p[0][0]);
    close(p[1][1]);
    close(p[2][1]);
    Run r = { .pid = pid };
    watch(spec, &r, res, p[0][1], p[1][0], p[2][0], start);
    res->cpu_seconds = sandbox_cpu(false) - cpu_start;
    return finish(&r, res, start);
}

/* ---- a server of tests -------------------------------------------------------- */

void sandbox_serve_init(SandboxServer *s, const char *program, const char *object, int start_at)
{
    memset(s, 0, sizeof *s);
    s->argv[0] = (char *)program;
    s->argv[1] = "--serve";
    s->argv[2] = (char *)object;
    s->argv[3] = NULL;
    s->sock = -1;
    s->off = start_at < 0;
    s->start_at = start_at;
}

/* Starts the server in the sandbox spec describes (its directory, user,
 * memory), with fd 3 its end of a socket and nothing to read or write. */
static int serve_start(SandboxServer *s, const SandboxSpec *spec)
{
    int sv[2];
    /* Packets: each message is read whole and alone (serve_protocol.h). */
    if (socketpair(AF_UNIX, SOCK_SEQPACKET, 0, sv) != 0)
        return -1;
    int null_r = open("/dev/null", O_RDONLY), null_w = open("/dev/null", O_WRONLY);
    SandboxSpec ss = *spec;
    ss.argv = s->argv;
    ss.cpu_seconds = SERVE_CPU_SECONDS;
    ss.max_procs = -1;          /* it forks; each child sets the test's limits */
    ss.memory_mb = 0;
    ss.address_mb = -1;
    pid_t pid = null_r >= 0 && null_w >= 0 ? spawn(&ss, null_r, sv[1], null_w) : -1;
    if (null_r >= 0)
        close(null_r);
    if (null_w >= 0)
        close(null_w);
    close(sv[1]);
    if (pid < 0) {
        close(sv[0]);
        return -1;
    }
    fcntl(sv[0], F_SETFD, FD_CLOEXEC);
    fcntl(sv[0], F_SETFL, O_NONBLOCK);
    s->pid = pid;
    s->sock = sv[0];
    s->reaped = false;
    return 0;
}

void sandbox_serve_stop(SandboxServer *s)
{
    if (s->sock >= 0)
        close(s->sock);
    s->sock = -1;
    if (s->pid > 0 && !s->reaped) {
        /* It exits when it reads the end of the socket; it may be stopped. */
        kill(s->pid, SIGKILL);
        while (waitpid(s->pid, NULL, 0) < 0 && errno == EINTR)
            continue;
    }
    s->pid = 0;
    s->reaped = false;
}

#ifndef MSG_NOSIGNAL
#define MSG_NOSIGNAL 0          /* macOS has none; SIGPIPE is ignored here anyway */
#endif

static int send_request(int sock, const ServeRequest *rq, const int fds[SERVE_FDS])
{
    char control[SERVE_CONTROL];
    struct iovec iov;
    struct msghdr msg;
    serve_message(&msg, &iov, (void *)rq, control);
    struct cmsghdr *c = CMSG_FIRSTHDR(&msg);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SCM_RIGHTS;
    c->cmsg_len = CMSG_LEN(SERVE_FDS * sizeof(int));
    memcpy(CMSG_DATA(c), fds, SERVE_FDS * sizeof(int));
    ssize_t n;
    do
        n = sendmsg(sock, &msg, MSG_NOSIGNAL);
    while (n < 0 && errno == EINTR);
    return n == (ssize_t)sizeof *rq ? 0 : -1;
}

/* One test through the server; 1 when the server failed (nothing of the
 * run is kept), else as sandbox_run. */
static int served(SandboxServer *s, const SandboxSpec *spec, SandboxResult *res, char *err,
                  size_t errlen)
{
    int p[3][2];
    if (open_pipes(p, err, errlen) != 0)
        return -1;
    long address_mb = spec->address_mb ? spec->address_mb : spec->memory_mb;
    ServeRequest rq = {
        .cpu_seconds = spec->cpu_seconds > 0 ? spec->cpu_seconds : (int32_t)(spec->timeout + 2),
        .max_procs = spec->max_procs,
        .address_bytes = address_mb > 0 ? (int64_t)address_mb << 20 : 0,
        .file_bytes = (int64_t)spec->max_file_mb << 20,
    };
    int fds[SERVE_FDS] = { p[0][0], p[2][1], p[1][1] };
    double start = sandbox_now();
    ServeStarted st;
    bool sent = send_request(s->sock, &rq, fds) == 0;
    close(p[0][0]);
    close(p[1][1]);
    close(p[2][1]);
    if (!sent || read_within(s->sock, &st, sizeof st, 2) != 0 || st.pid <= 0) {
        for (int k = 0; k < 3; k++)
            close(p[k][k == 0 ? 1 : 0]);
        return 1;
    }
    Run r = { .pid = (pid_t)st.pid, .server = s };
    watch(spec, &r, res, p[0][1], p[1][0], p[2][0], start);
    if (r.server_failed) {
        sandbox_result_free(res);
        return 1;
    }
    res->cpu_seconds = r.cpu;
    return finish(&r, res, start);
}

int sandbox_serve_run(SandboxServer *s, const SandboxSpec *spec, SandboxResult *res, char *err,
                      size_t errlen)
{
    memset(res, 0, sizeof *res);
    if (errlen)
        err[0] = '\0';
    signal(SIGPIPE, SIG_IGN);
    bool now = !s->off && s->runs++ >= s->start_at;
    if (now && !s->pid && serve_start(s, spec) != 0)
        s->off = true;
    if (now && !s->off) {
        int status = served(s, spec, res, err, errlen);
        if (status != 1)
            return status;
        /* The server is gone or stuck: from here on, one runner per test;
         * this test too runs again, in a process the grader started. */
        sandbox_serve_stop(s);
        s->off = true;
        s->failed = true;
    }
    SandboxSpec own = *spec;
    char *argv[3] = { s->argv[0], s->argv[2], NULL };
    own.argv = argv;
    return sandbox_run(&own, res, err, errlen);
}

void sandbox_result_free(SandboxResult *res)
{
    free(res->answer);
    free(res->output);
    memset(res, 0, sizeof *res);
}
