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

#define SERVE_KILL 'k'

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

#endif
