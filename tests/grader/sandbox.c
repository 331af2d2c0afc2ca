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
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE         /* setgroups, on glibc */
#define _DARWIN_C_SOURCE        /* setgroups, on macOS */
#include "sandbox.h"

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

static void nobody_ids(uid_t *uid, gid_t *gid)
{
    struct passwd *pw = getpwnam("nobody");
    *uid = pw ? pw->pw_uid : 65534;
    *gid = pw ? pw->pw_gid : 65534;
}

int sandbox_give(const char *path)
{
    if (!sandbox_drops_privileges())
        return 0;
    uid_t uid;
    gid_t gid;
    nobody_ids(&uid, &gid);
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
        nobody_ids(&cp->uid, &cp->gid);
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

int sandbox_run(const SandboxSpec *spec, SandboxResult *res, char *err, size_t errlen)
{
    int in_p[2], ans_p[2], out_p[2];
    memset(res, 0, sizeof *res);
    if (errlen)
        err[0] = '\0';
    signal(SIGPIPE, SIG_IGN);
    if (pipe(in_p) != 0)
        goto fail_pipe0;
    if (pipe(ans_p) != 0)
        goto fail_pipe1;
    if (pipe(out_p) != 0)
        goto fail_pipe2;

    static ChildPlan plan;
    plan_child(&plan, spec, in_p[0], ans_p[1], out_p[1]);
    double start = sandbox_now(), cpu_start = sandbox_cpu(false);
#if defined(__linux__)
    pid_t pid = vfork();        /* portable: __linux__ (macOS deprecates vfork: fork there) */
#else
    pid_t pid = fork();
#endif
    if (pid < 0) {
        snprintf(err, errlen, "fork: %s", strerror(errno));
        close(out_p[0]);
        close(out_p[1]);
        goto fail_pipe2;
    }
    if (pid == 0)
        child(&plan);
    setpgid(pid, pid);              /* also here, so killpg cannot race it */
    close(in_p[0]);
    close(ans_p[1]);
    close(out_p[1]);
    fcntl(in_p[1], F_SETFL, O_NONBLOCK);
    fcntl(ans_p[0], F_SETFL, O_NONBLOCK);
    fcntl(out_p[0], F_SETFL, O_NONBLOCK);

    size_t in_off = 0, ans_cap = 0, out_cap = 0, ans_total = 0, out_total = 0;
    int in_fd = spec->input_len ? in_p[1] : -1, ans_fd = ans_p[0], out_fd = out_p[0];
    if (in_fd < 0)
        close(in_p[1]);
    int status = 0;
    bool exited = false, reaped = false;
    double deadline = start + spec->timeout, next_watch = start;

    while (!exited) {
        struct pollfd pf[3];
        int n = 0;
        if (in_fd >= 0)
            pf[n++] = (struct pollfd){ in_fd, POLLOUT, 0 };
        if (ans_fd >= 0)
            pf[n++] = (struct pollfd){ ans_fd, POLLIN, 0 };
        if (out_fd >= 0)
            pf[n++] = (struct pollfd){ out_fd, POLLIN, 0 };
        /* With the pipes closed only the child's exit is left to wait for. */
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
        /* Exited, out of time, over its output or its memory? */
        if (waitpid(pid, &status, WNOHANG) == pid) {
            reaped = true;
            exited = true;
        } else if (spec->output_stop && out_total > spec->output_stop) {
            res->output_exceeded = true;
            exited = true;
        } else if (sandbox_now() > deadline) {
            res->timed_out = true;
            exited = true;
        } else if (spec->memory_mb > 0 && sandbox_now() >= next_watch) {
            next_watch = sandbox_now() + 0.02;
            if (group_memory(pid) > (long long)spec->memory_mb << 20) {
                res->memory_exceeded = true;
                exited = true;
            }
        }
    }
    /* Kill whatever is left of the group (its id stays reserved while any
     * member lives, so this reaches no one else), reap the child, then take
     * what is already in the pipes without waiting for anyone to close them. */
    kill(-pid, SIGKILL);
    if (!reaped) {
        kill(pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            continue;
    }
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

    res->seconds = sandbox_now() - start;
    res->cpu_seconds = sandbox_cpu(false) - cpu_start;
    bool killed = res->timed_out || res->memory_exceeded || res->output_exceeded;
    res->exit_code = WIFEXITED(status) && !killed ? WEXITSTATUS(status) : -1;
    res->signal = WIFSIGNALED(status) && !killed ? WTERMSIG(status) : 0;
    if (!res->answer && !(res->answer = calloc(1, 1)))
        return -1;
    if (!res->output && !(res->output = calloc(1, 1)))
        return -1;
    res->answer[res->answer_len] = '\0';
    res->output[res->output_len] = '\0';
    return 0;

fail_pipe2:
    close(ans_p[0]);
    close(ans_p[1]);
fail_pipe1:
    close(in_p[0]);
    close(in_p[1]);
fail_pipe0:
    if (!err[0])
        snprintf(err, errlen, "pipe: %s", strerror(errno));
    return -1;
}

void sandbox_result_free(SandboxResult *res)
{
    free(res->answer);
    free(res->output);
    memset(res, 0, sizeof *res);
}
