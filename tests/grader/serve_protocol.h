/*
 * serve_protocol.h - what the grader and a prebuilt runner started as a
 * server (`runner --serve OBJECT`, harness_serve.c) say to each other over
 * the socket on the server's fd 3 (sandbox.c, sandbox_serve_run).
 *
 * Per test, in order:
 *   grader -> server  a ServeRequest, with the test's three descriptors
 *                     (its stdin, stdout-and-stderr, answers) passed along
 *                     (SCM_RIGHTS)
 *   child -> grader   a ServeStarted: its pid, before it runs anything of
 *                     the student's (or the server's, pid -1: fork failed)
 *   grader -> server  at most one byte, SERVE_KILL, when the grader stops
 *                     the test (out of time, memory or output)
 *   server -> grader  a ServeEnded, once it has reaped the child
 * The socket keeps messages apart (SOCK_SEQPACKET): a SERVE_KILL that
 * reaches the server after the child has ended (it ended at its deadline)
 * is read alone, and ignored, never as the start of the next request.
 * Both sides are the kit's own code: the student's code runs only in the
 * children, which close the socket before anything of theirs runs.
 */
#ifndef SERVE_PROTOCOL_H
#define SERVE_PROTOCOL_H

#include <stdint.h>
#include <string.h>
#include <sys/socket.h>

#define SERVE_KILL 'k'
#define SERVE_FDS 3                /* a request's descriptors               */
#define SERVE_CONTROL CMSG_SPACE(SERVE_FDS * sizeof(int))

typedef struct {
    int32_t cpu_seconds;       /* RLIMIT_CPU                                 */
    int32_t max_procs;         /* RLIMIT_NPROC; -1: left as it is            */
    int64_t address_bytes;     /* RLIMIT_AS; 0: left as it is                */
    int64_t file_bytes;        /* RLIMIT_FSIZE                               */
} ServeRequest;

typedef struct {
    int32_t pid;
} ServeStarted;

typedef struct {
    int32_t status;            /* as waitpid gives it                        */
    int32_t unused;
    double cpu_seconds;        /* the child's user and system CPU            */
} ServeEnded;

/* A request's message, as both sides lay it out: the request in iov,
 * room for SERVE_FDS descriptors in control (SERVE_CONTROL bytes). */
static inline void serve_message(struct msghdr *msg, struct iovec *iov, void *request,
                                 char *control)
{
    iov->iov_base = request;
    iov->iov_len = sizeof(ServeRequest);
    memset(msg, 0, sizeof *msg);
    memset(control, 0, SERVE_CONTROL);
    msg->msg_iov = iov;
    msg->msg_iovlen = 1;
    msg->msg_control = control;
    msg->msg_controllen = SERVE_CONTROL;
}

#endif
