/*
 * harness_serve.c - see harness_serve.h.  Linux: fork, SCM_RIGHTS, prctl.
 *
 * The server runs as the tests do (the sandbox's user, directory and
 * environment), so its children need only their own descriptors and the
 * limits a test's exec would have had.  It cannot be traced or read by its
 * children, though they run as the same user (PR_SET_DUMPABLE 0); a child
 * can still signal it, and a server that dies or stops is the grader's
 * cue to go back to starting the runner for each test (sandbox.c).
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE         /* CMSG_SPACE, on glibc */
#define _DARWIN_C_SOURCE        /* macOS: the rest too (built only on Linux today) */
#include "harness_serve.h"
#include "serve_protocol.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdbool.h>
#include <string.h>
#include <sys/prctl.h>            /* portable: built only on Linux, as the runners */
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

static int chld_pipe[2] = { -1, -1 };

/* SIGCHLD wakes the loop's poll through a pipe of its own. */
static void on_chld(int sig)
{
    (void)sig;
    int saved = errno;
    if (write(chld_pipe[1], "c", 1) < 0) {
        /* full: the loop wakes anyway */
    }
    errno = saved;
}

static int write_full(int fd, const void *p, size_t n)
{
    const char *c = p;
    while (n > 0) {
        ssize_t w = write(fd, c, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        c += w;
        n -= (size_t)w;
    }
    return 0;
}

/* One message: 0 a request (rq and fds filled), 1 a late SERVE_KILL, -1
 * anything else or the end. */
static int receive_one(int sock, ServeRequest *rq, int fds[SERVE_FDS])
{
    char control[SERVE_CONTROL];
    struct iovec iov;
    struct msghdr msg;
    serve_message(&msg, &iov, rq, control);
    ssize_t n;
    do
        n = recvmsg(sock, &msg, 0);
    while (n < 0 && errno == EINTR);
    struct cmsghdr *c = CMSG_FIRSTHDR(&msg);
    if (n == 1 && !c && *(const char *)rq == SERVE_KILL)
        return 1;
    bool ok = n == (ssize_t)sizeof *rq && !(msg.msg_flags & (MSG_TRUNC | MSG_CTRUNC)) && c &&
              c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_RIGHTS &&
              c->cmsg_len == CMSG_LEN(SERVE_FDS * sizeof(int)) &&
              rq->cpu_seconds > 0 && rq->max_procs >= -1 && rq->address_bytes >= 0 &&
              rq->file_bytes >= 0;      /* a request's limits make sense, or none is run */
    if (c && c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_RIGHTS) {
        int got = (int)((c->cmsg_len - CMSG_LEN(0)) / sizeof(int));
        int passed[SERVE_FDS] = { -1, -1, -1 };
        memcpy(passed, CMSG_DATA(c), (size_t)(got < SERVE_FDS ? got : SERVE_FDS) * sizeof(int));
        for (int k = 0; k < SERVE_FDS; k++) {
            fds[k] = passed[k];
            if (!ok && passed[k] >= 0)
                close(passed[k]);
        }
    }
    return ok ? 0 : -1;
}

/* The next request and its three descriptors, past any late SERVE_KILL;
 * -1 when the grader closed the socket or sent something else. */
static int receive(int sock, ServeRequest *rq, int fds[SERVE_FDS])
{
    for (;;) {
        int got = receive_one(sock, rq, fds);
        if (got != 1)
            return got;
    }
}

static void limit(int resource, rlim_t value)
{
    struct rlimit rl = { value, value };
    setrlimit(resource, &rl);
}

/* In the child: the test's descriptors on 0-3 and nothing else, its own
 * process group, the test's limits. */
static void become_test(int sock, const ServeRequest *rq, const int fds[SERVE_FDS])
{
    /* The grader learns the child's pid from the child, before any of the
     * student's code runs: even if that code kills the server at once, the
     * grader can stop the child. */
    ServeStarted st = { (int32_t)getpid() };
    if (write_full(sock, &st, sizeof st) != 0)
        _exit(126);
    close(sock);
    close(chld_pipe[0]);
    close(chld_pipe[1]);
    signal(SIGCHLD, SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
    setpgid(0, 0);
    if (dup2(fds[0], 0) < 0 || dup2(fds[1], 1) < 0 || dup2(fds[1], 2) < 0 || dup2(fds[2], 3) < 0)
        _exit(126);
    for (int k = 0; k < SERVE_FDS; k++)
        if (fds[k] > 3)
            close(fds[k]);
    limit(RLIMIT_CPU, (rlim_t)rq->cpu_seconds);
    if (rq->address_bytes > 0)
        limit(RLIMIT_AS, (rlim_t)rq->address_bytes);
    limit(RLIMIT_FSIZE, (rlim_t)rq->file_bytes);
    if (rq->max_procs >= 0)
        limit(RLIMIT_NPROC, (rlim_t)rq->max_procs);
}

/* Waits for the child, killing it if the grader asks or goes; its status
 * and CPU seconds.  Returns -1 when the grader has gone. */
static int await(int sock, pid_t pid, int *status, double *cpu)
{
    bool gone = false;
    for (;;) {
        struct rusage ru;
        pid_t w = wait4(pid, status, WNOHANG, &ru);
        if (w == pid) {
            *cpu = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec +
                   (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
            return gone ? -1 : 0;
        }
        if (w < 0 && errno != EINTR)
            return -1;
        struct pollfd pf[2] = { { chld_pipe[0], POLLIN, 0 }, { gone ? -1 : sock, POLLIN, 0 } };
        if (poll(pf, 2, -1) < 0 && errno != EINTR)
            return -1;
        char buf[64];
        if (pf[0].revents)
            while (read(chld_pipe[0], buf, sizeof buf) > 0)
                continue;
        if (pf[1].revents) {
            char c;
            ssize_t n = read(sock, &c, 1);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0 || c == SERVE_KILL) {
                kill(-pid, SIGKILL);
                kill(pid, SIGKILL);
                gone = n <= 0;
            }
        }
    }
}

void harness_serve(int sock)
{
    prctl(PR_SET_DUMPABLE, 0, 0, 0, 0);     /* portable: built only on Linux */
    signal(SIGPIPE, SIG_IGN);
    if (pipe(chld_pipe) != 0)
        _exit(126);
    for (int k = 0; k < 2; k++)
        fcntl(chld_pipe[k], F_SETFL, O_NONBLOCK);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_chld;
    sa.sa_flags = SA_RESTART | SA_NOCLDSTOP;
    sigemptyset(&sa.sa_mask);
    if (sigaction(SIGCHLD, &sa, NULL) != 0)
        _exit(126);
    for (;;) {
        ServeRequest rq;
        int fds[SERVE_FDS];
        if (receive(sock, &rq, fds) != 0)
            _exit(0);
        pid_t pid = fork();
        if (pid == 0) {
            become_test(sock, &rq, fds);
            return;
        }
        for (int k = 0; k < SERVE_FDS; k++)
            close(fds[k]);
        if (pid < 0) {
            ServeStarted st = { -1 };
            if (write_full(sock, &st, sizeof st) != 0)
                _exit(0);
            continue;
        }
        ServeEnded en;
        memset(&en, 0, sizeof en);
        int status = 0;
        if (await(sock, pid, &status, &en.cpu_seconds) != 0)
            _exit(0);
        en.status = status;
        if (write_full(sock, &en, sizeof en) != 0)
            _exit(0);
    }
}
