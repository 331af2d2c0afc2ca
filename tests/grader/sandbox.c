/*
 * sandbox.c - see sandbox.h.  POSIX: fork, setsid, setrlimit, poll; vfork
 * on Linux (macOS deprecates it), or the jail's clone (jail.c), which
 * shares memory as vfork does; and what each system offers to see a
 * process's memory (/proc on Linux, libproc on macOS).
 *
 * On Linux the child shares the grader's memory until it runs the program
 * (vfork, or clone with CLONE_VM | CLONE_VFORK): the grader holds tens of
 * megabytes of tests and figures, and a fork copies its page tables and
 * then makes every page the grader writes fault once (copy on write).  So
 * everything the child needs is prepared before (ChildPlan, jail_prepare)
 * and the child itself only calls the system.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE         /* setgroups, on glibc */
#define _DARWIN_C_SOURCE        /* setgroups, on macOS */
#include "sandbox.h"
#include "harness_init.h"
#include "jail.h"

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
#include <sys/ioctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#if defined(__APPLE__)
#include <libproc.h>
#endif
#if defined(__linux__)
#include <sys/prctl.h>         /* portable: __linux__ */
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
static bool user_known, user_held;
static uid_t user_uid;
static gid_t user_gid;

void sandbox_ids(uid_t *uid, gid_t *gid)
{
    if (!sandbox_drops_privileges()) {
        *uid = geteuid();
        *gid = getegid();
        return;
    }
    if (!user_known) {
        lookup_nobody(&user_uid, &user_gid);
        user_known = true;
    }
    *uid = user_uid;
    *gid = user_gid;
}

void sandbox_set_user(uid_t id, bool held)
{
    user_uid = id;
    user_gid = (gid_t)id;
    user_known = id != 0;
    user_held = id != 0 && held;
}

/* The lock file, opened once; -1 with why set when it cannot be used. */
static int users_lock(const char **why)
{
    static int fd = -2;
    static const char *fault;
    if (fd == -2) {
        struct stat st;
        fd = open(SANDBOX_USERS_LOCK, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd < 0)
            fault = "cannot open " SANDBOX_USERS_LOCK;
        else if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != geteuid() ||
                 (st.st_mode & 022)) {
            fault = SANDBOX_USERS_LOCK " is not a file that only root may write";
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
                *unclaimed = "the system cannot lock " SANDBOX_USERS_LOCK;
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

static void limit(int resource, rlim_t value)
{
    struct rlimit rl = { value, value };
    setrlimit(resource, &rl);       /* best effort: macOS ignores some */
}

/* The memory the run holds, in bytes, or -1 where the system does not say.
 * macOS: the physical footprint (resident and compressed memory) of every
 * process of the child's group.  Linux: the resident size of the child and
 * of its own children (a test cannot fork; in the namespace jail its first
 * process is the one that forks the test: harness_init.h), from /proc. */
#if defined(__linux__)
static long long resident(long pid)
{
    char path[64], text[128];
    snprintf(path, sizeof path, "/proc/%ld/statm", pid);             /* portable: __linux__ */
    int fd = open(path, O_RDONLY);
    if (fd < 0)
        return -1;
    ssize_t n = read(fd, text, sizeof text - 1);
    close(fd);
    long size = 0, pages = 0, page = sysconf(_SC_PAGESIZE);
    if (n <= 0 || page <= 0)
        return -1;
    text[n] = '\0';
    if (sscanf(text, "%ld %ld", &size, &pages) != 2)
        return -1;
    return (long long)pages * page;
}
#endif

static long long group_memory(pid_t pid)
{
#if defined(__APPLE__)
    pid_t pids[256];
    int bytes = proc_listpids(PROC_PGRP_ONLY, (uint32_t)pid, pids, (int)sizeof pids);
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
    long long total = resident((long)pid);
    char path[96], text[256];
    snprintf(path, sizeof path, "/proc/%ld/task/%ld/children", (long)pid, (long)pid);  /* portable: __linux__ */
    int fd = total >= 0 ? open(path, O_RDONLY) : -1;
    ssize_t n = fd >= 0 ? read(fd, text, sizeof text - 1) : 0;
    if (fd >= 0)
        close(fd);
    text[n > 0 ? n : 0] = '\0';
    char *at = text, *end;
    for (long child = strtol(at, &end, 10); end != at; child = strtol(at = end, &end, 10)) {
        long long more = resident(child);
        total += more > 0 ? more : 0;
    }
    return total;
#else
    (void)pid;
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
 * effort: other systems have no /proc (nor has the namespace jail). */
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

/* What the child needs, prepared by the parent before it starts: the child
 * shares the parent's memory until it runs the program, so it calls
 * nothing that allocates or locks, only the system. */
typedef struct {
    const SandboxSpec *spec;
    int in_r, ans_w, out_w;
    int status_w;              /* fd 4 of a jail's first process (init), or -1 */
    int close_fds[256];        /* the parent's descriptors from 4 up          */
    int nclose;                /* -1: more than fit; close them all blindly  */
    bool jailed;               /* in the namespace jail (jail_enter first)   */
    bool drop;
    uid_t uid;
    gid_t gid;
    long nproc;                /* RLIMIT_NPROC, or -1: none                  */
    pid_t grader;              /* the process that starts it                */
    double entered;            /* set by the jailed child: when its jail was
                                  built (it shares this memory)             */
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

static void plan_child(ChildPlan *cp, const SandboxSpec *spec, int in_r, int ans_w, int out_w,
                       int status_w)
{
    cp->spec = spec;
    cp->in_r = in_r, cp->ans_w = ans_w, cp->out_w = out_w, cp->status_w = status_w;
    cp->grader = getpid();
    plan_close(cp, 4);
    cp->jailed = jail_namespaces();
    cp->drop = sandbox_drops_privileges();
    sandbox_ids(&cp->uid, &cp->gid);
    /* A jail's first process that forks the test (init) may make that one
     * (it and the test count two); the test then takes 0 (harness_init.h). */
    cp->nproc = spec->max_procs < 0 ? -1 : status_w >= 0 ? HARNESS_INIT_NPROC : 0;
    const char *path = spec->compiler && getenv("PATH") ? getenv("PATH") : "/usr/bin:/bin";
    snprintf(cp->path_env, sizeof cp->path_env, "PATH=%s", path);
    cp->envp[0] = cp->path_env;
    cp->envp[1] = "LC_ALL=C";
    cp->envp[2] = "HOME=/nonexistent";
    cp->envp[3] = NULL;
    if (spec->compiler) {          /* the compiler wants a TMPDIR it can write */
        snprintf(cp->tmp_env, sizeof cp->tmp_env, "TMPDIR=%s", spec->workdir);
        cp->envp[2] = cp->tmp_env;
    }
}

/* A session of its own, with no controlling terminal: through /dev/tty the
 * child could otherwise write on the grader's terminal, or push input into
 * it (TIOCSTI) that the grader's shell would run once grading ends.  Where
 * the parent made it a group leader first (fork, on macOS), setsid is
 * refused: it gives the terminal up instead. */
JAIL_CHILD_CODE static void leave_terminal(void)
{
    if (setsid() >= 0)
        return;
    setpgid(0, 0);
    int tty = open("/dev/tty", O_RDWR | O_NOCTTY | O_CLOEXEC);
    if (tty >= 0) {
        ioctl(tty, TIOCNOTTY);
        close(tty);
    }
}

/* In the child, after vfork (Linux), fork, or in the jail: never returns. */
JAIL_CHILD_CODE static void child(const ChildPlan *cp)
{
    const SandboxSpec *spec = cp->spec;
    leave_terminal();
    signal(SIGPIPE, SIG_DFL);
    if (!cp->jailed)
        prefer_oom_kill();          /* the jail does it as it enters (jail.c) */
    if (dup2(cp->in_r, 0) < 0 || dup2(cp->out_w, 1) < 0 || dup2(cp->out_w, 2) < 0 ||
        dup2(cp->ans_w, 3) < 0 || (cp->status_w >= 0 && dup2(cp->status_w, 4) < 0))
        _exit(126);
    if (cp->nclose >= 0) {
        for (int k = 0; k < cp->nclose; k++)
            if (cp->close_fds[k] != 4 || cp->status_w < 0)
                close(cp->close_fds[k]);
    } else {
        long maxfd = sysconf(_SC_OPEN_MAX);
        if (maxfd < 0 || maxfd > 65536)
            maxfd = 65536;
        for (long fd = cp->status_w >= 0 ? 5 : 4; fd < maxfd; fd++)
            close((int)fd);
    }
    if (!cp->jailed && chdir(spec->cwd ? spec->cwd : spec->workdir) != 0)
        _exit(126);

    limit(RLIMIT_CORE, 0);
    limit(RLIMIT_CPU, spec->cpu_seconds > 0 ? (rlim_t)spec->cpu_seconds : (rlim_t)(spec->timeout + 2));
    long address_mb = spec->address_mb ? spec->address_mb : spec->memory_mb;
    if (address_mb > 0)
        limit(RLIMIT_AS, (rlim_t)address_mb << 20);     /* macOS refuses it: see group_memory */
    limit(RLIMIT_FSIZE, (rlim_t)spec->max_file_mb << 20);
    /* As root: the run's own id.  In a user namespace the child is the user
     * already, and its capabilities go as it runs the program. */
    if (cp->drop) {
        if (setgroups(0, NULL) != 0 || setgid(cp->gid) != 0 || setuid(cp->uid) != 0 || setuid(0) == 0)
            _exit(126);
    }
    if (cp->nproc >= 0)
        limit(RLIMIT_NPROC, (rlim_t)cp->nproc);
#if defined(__linux__)
    /* Should the grader itself be killed (SIGKILL, which it cannot catch),
     * the run goes with it, and in the namespace jail its whole PID
     * namespace: nothing left waiting for ever.  Set after the change of
     * id, which clears it; a grader gone already is seen here (the parent
     * of the jail's first process is outside its namespace: 0). */
    prctl(PR_SET_PDEATHSIG, SIGKILL);                   /* portable: __linux__ */
    if (getppid() != cp->grader && getppid() != 0)
        _exit(126);
#endif
    jail_deny_calls();
    execve(spec->argv[0], spec->argv, cp->envp);
    _exit(127);
}

/* The namespace jail's child: the jail, then the rest as any child. */
JAIL_CHILD_CODE static int jailed_child(void *arg)
{
    ChildPlan *cp = arg;
    if (jail_enter(cp->out_w) != 0)
        _exit(125);
    cp->entered = sandbox_now();
    child(cp);
    return 127;
}

/* A pipe the grader reads (the answer's or the output's): its end, and
 * the result's buffer that collects at most max of its bytes. */
typedef struct {
    int fd;                     /* -1 once closed                  */
    char **buf;
    size_t *len, cap, max;
    bool *truncated;
    size_t total;               /* all it read, kept or not         */
} Pipe;

/* Appends what p has to its buffer; returns 0 at end of file, 1 if it
 * read or would block, -1 on error. */
static int pump(Pipe *p)
{
    char chunk[65536];
    ssize_t n = read(p->fd, chunk, sizeof chunk);
    if (n == 0)
        return 0;
    if (n < 0)
        return errno == EAGAIN || errno == EINTR ? 1 : -1;
    p->total += (size_t)n;
    size_t keep = (size_t)n;
    if (*p->len + keep > p->max) {
        keep = p->max > *p->len ? p->max - *p->len : 0;
        *p->truncated = true;
    }
    if (keep) {
        if (*p->len + keep + 1 > p->cap) {
            size_t ncap = (*p->len + keep + 1) * 2;
            char *nb = realloc(*p->buf, ncap);
            if (!nb)
                return -1;
            *p->buf = nb;
            p->cap = ncap;
        }
        memcpy(*p->buf + *p->len, chunk, keep);
        *p->len += keep;
    }
    return 1;
}

/* Pumps each of the pipes still open, closing it at its end or an error. */
static void pump_open(Pipe *pipes, int n)
{
    for (int k = 0; k < n; k++)
        if (pipes[k].fd >= 0 && pump(&pipes[k]) <= 0) {
            close(pipes[k].fd);
            pipes[k].fd = -1;
        }
}

/* ---- watching a run ----------------------------------------------------------- */

/* Stops the child, whatever is left of its group and (the namespace jail)
 * its PID namespace, and reaps it.  pid is the child's own: > 0, and its
 * group is not the grader's (it made one of its own, setpgid on both
 * sides), so this reaches no one else. */
static void stop(pid_t pid, int *status, bool *ended)
{
    if (pid <= 0 || pid == getpgrp())
        return;
    kill(-pid, SIGKILL);
    if (!*ended) {
        kill(pid, SIGKILL);
        while (waitpid(pid, status, 0) < 0 && errno == EINTR)
            continue;
        *ended = true;
    }
}

/* Feeds the child its input and collects what it writes until it ends or
 * breaks a limit (then stops it), then what is left in the pipes.  The
 * pipes are the grader's ends; each is closed here. */
static void watch(const SandboxSpec *spec, pid_t pid, int *status, SandboxResult *res, int in_fd,
                  int ans_fd, int out_fd, double start)
{
    fcntl(in_fd, F_SETFL, O_NONBLOCK);
    fcntl(ans_fd, F_SETFL, O_NONBLOCK);
    fcntl(out_fd, F_SETFL, O_NONBLOCK);
    Pipe pipes[2] = {
        { ans_fd, &res->answer, &res->answer_len, 0, spec->answer_max, &res->answer_truncated, 0 },
        { out_fd, &res->output, &res->output_len, 0, spec->output_max, &res->output_truncated, 0 },
    };
    Pipe *ans = &pipes[0], *out = &pipes[1];
    size_t in_off = 0;
    if (!spec->input_len) {
        close(in_fd);
        in_fd = -1;
    }
    double deadline = start + spec->timeout, next_watch = start;
    bool over = false, ended = false;

    while (!over) {
        struct pollfd pf[3];
        int n = 0;
        if (in_fd >= 0)
            pf[n++] = (struct pollfd){ in_fd, POLLOUT, 0 };
        if (ans->fd >= 0)
            pf[n++] = (struct pollfd){ ans->fd, POLLIN, 0 };
        if (out->fd >= 0)
            pf[n++] = (struct pollfd){ out->fd, POLLIN, 0 };
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
        pump_open(pipes, 2);
        /* Ended, out of time, over its output or its memory? */
        if (waitpid(pid, status, WNOHANG) == pid) {
            ended = over = true;
        } else if (spec->output_stop && out->total > spec->output_stop) {
            res->output_exceeded = over = true;
        } else if (sandbox_now() > deadline) {
            res->timed_out = over = true;
        } else if (spec->memory_mb > 0 && sandbox_now() >= next_watch) {
            next_watch = sandbox_now() + 0.02;
            if (group_memory(pid) > (long long)spec->memory_mb << 20)
                res->memory_exceeded = over = true;
        }
    }
    stop(pid, status, &ended);
    /* What is already in the pipes, without waiting for anyone to close them. */
    for (int round = 0; round < 64 && (ans->fd >= 0 || out->fd >= 0); round++) {
        pump_open(pipes, 2);
        if (ans->fd >= 0 || out->fd >= 0) {
            struct pollfd pf[2] = { { ans->fd, POLLIN, 0 }, { out->fd, POLLIN, 0 } };
            if (poll(pf, 2, round < 4 ? 5 : 0) == 0)
                break;
        }
    }
    if (in_fd >= 0)
        close(in_fd);
    if (ans->fd >= 0)
        close(ans->fd);
    if (out->fd >= 0)
        close(out->fd);
}

/* The result's last fields, from how the run ended; 0, or -1 out of memory. */
static int finish(int status, SandboxResult *res, double start)
{
    res->seconds = sandbox_now() - start;
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
}

/* The pipes of a run: [0] the child's stdin, [1] its answers (fd 3), [2]
 * its stdout and stderr, [3] the jail's first process's word of how the
 * test ended (fd 4); each p[k][0] is read, p[k][1] written. */
static int open_pipes(int p[4][2], int n, char *err, size_t errlen)
{
    for (int k = 0; k < n; k++)
        if (pipe(p[k]) != 0) {
            snprintf(err, errlen, "pipe: %s", strerror(errno));
            while (k-- > 0) {
                close(p[k][0]);
                close(p[k][1]);
            }
            return -1;
        }
    for (int k = n; k < 4; k++)
        p[k][0] = p[k][1] = -1;
    return 0;
}

/* The plan of the child about to start (see ChildPlan). */
static ChildPlan plan;

/* The runs started, and the seconds spent building their jails (the
 * child's, while the grader waits for it: sandbox_jail_cost). */
static int runs;
static double jail_seconds;

void sandbox_jail_cost(int *nruns, double *seconds)
{
    *nruns = runs;
    *seconds = jail_seconds;
}

/* Starts the child that runs spec's program: in the namespace jail, or
 * by vfork (Linux) or fork.  The child's pid, or -1 with err. */
static pid_t spawn(const SandboxSpec *spec, int in_r, int ans_w, int out_w, int status_w, char *err,
                   size_t errlen)
{
    plan_child(&plan, spec, in_r, ans_w, out_w, status_w);
    pid_t pid;
    if (plan.jailed) {
        JailPaths paths = { .workdir = spec->workdir, .workdir_shared = spec->keep != NULL,
                            .cwd = spec->cwd, .visible = spec->visible, .pid_namespace = status_w >= 0 };
        if (jail_prepare(&paths, plan.uid, plan.gid, err, errlen) != 0)
            return -1;
        double start = sandbox_now();
        plan.entered = 0;
        pid = jail_clone(jailed_child, &plan);
        if (pid > 0 && plan.entered > start)
            jail_seconds += plan.entered - start;
    } else {
#if defined(__linux__)
        pid = vfork();          /* portable: __linux__ (macOS deprecates vfork: fork there) */
#else
        pid = fork();
#endif
        if (pid == 0)
            child(&plan);
    }
    if (pid > 0) {
        setpgid(pid, pid);      /* also here, so killpg cannot race it */
        runs++;
    } else
        snprintf(err, errlen, "%s: %s", plan.jailed ? "clone" : "fork", strerror(errno));
    return pid;
}

/* The run's working folder on the grader's side: in the fallback jail,
 * and in the namespace jail when the grader reads back from it (keep).
 * Made afresh, the run's own; 0, or -1 with err. */
static int make_workdir(const SandboxSpec *spec, char *err, size_t errlen)
{
    if (jail_namespaces() && !spec->keep)
        return 0;                   /* a tmpfs of the jail's own */
    struct stat st;
    if (lstat(spec->workdir, &st) == 0)
        jail_remove_tree(spec->workdir);
    uid_t uid;
    gid_t gid;
    sandbox_ids(&uid, &gid);
    if (mkdir(spec->workdir, 0700) != 0 ||
        (sandbox_drops_privileges() && chown(spec->workdir, uid, gid) != 0)) {
        snprintf(err, errlen, "%s: %s", spec->workdir, strerror(errno));
        return -1;
    }
    return 0;
}

/* After the run: what the grader keeps of its folder, then the folder
 * gone; in the fallback jail as root, every process and file of the run's
 * id too (when the id is this grader's alone). */
static void clean_up(const SandboxSpec *spec)
{
    bool shared = !jail_namespaces() || spec->keep;
    for (int k = 0; spec->keep && spec->keep[k]; k++) {
        char to[4096], why[256];
        snprintf(to, sizeof to, "%s/%s", spec->keep_to, spec->keep[k]);
        unlink(to);
        jail_take_file(spec->workdir, spec->keep[k], to, spec->keep_max, why, sizeof why);
    }
    if (!jail_namespaces() && sandbox_drops_privileges() && user_held)
        jail_sweep(user_uid);
    if (shared)
        jail_remove_tree(spec->workdir);
}

int sandbox_run(const SandboxSpec *spec, SandboxResult *res, char *err, size_t errlen)
{
    int p[4][2];
    memset(res, 0, sizeof *res);
    if (errlen)
        err[0] = '\0';
    signal(SIGPIPE, SIG_IGN);
    /* A PID namespace of its own, whose first process (init) forks the
     * test: not as root with "nobody", whose processes elsewhere count
     * against the one process the jail's limit lets init make. */
    bool init = spec->init && jail_namespaces() && (!sandbox_drops_privileges() || user_held);
    if (make_workdir(spec, err, errlen) != 0)
        return -1;
    if (open_pipes(p, init ? 4 : 3, err, errlen) != 0) {
        clean_up(spec);
        return -1;
    }
    double cpu_start = sandbox_cpu(false);
    pid_t pid = spawn(spec, p[0][0], p[1][1], p[2][1], p[3][1], err, errlen);
    /* The time limit counts from here, when the child has started the
     * program (spawn returns once it has): building its jail, which the
     * kernel may keep waiting while it ends other runs' namespaces, is the
     * kit's time, not the code's. */
    double start = sandbox_now();
    /* The child's ends: stdin's read end, the others' write ends. */
    for (int k = 0; k < 4; k++)
        if (p[k][0] >= 0)
            close(p[k][k == 0 ? 0 : 1]);
    if (pid < 0) {
        for (int k = 0; k < 4; k++)
            if (p[k][0] >= 0)
                close(p[k][k == 0 ? 1 : 0]);
        clean_up(spec);
        return -1;
    }
    int status = 0;
    watch(spec, pid, &status, res, p[0][1], p[1][0], p[2][0], start);
    if (init) {
        /* The test's own end, as the jail's first process saw it. */
        int told;
        fcntl(p[3][0], F_SETFL, O_NONBLOCK);
        if (read(p[3][0], &told, sizeof told) == (ssize_t)sizeof told && !res->timed_out &&
            !res->memory_exceeded && !res->output_exceeded)
            status = told;
        close(p[3][0]);
    }
    res->cpu_seconds = sandbox_cpu(false) - cpu_start;
    clean_up(spec);
    return finish(status, res, start);
}

void sandbox_result_free(SandboxResult *res)
{
    free(res->answer);
    free(res->output);
    memset(res, 0, sizeof *res);
}
