/*
 * sandbox.h - running untrusted student code in a child process.
 *
 * Every run (compiling a stage file, a part's tests, a test alone, a probe
 * of the diagnosis, the report page's render) is a fresh child in a jail
 * of its own (jail.h: namespaces where the system allows them, else a user
 * id of its own that is swept after the run).  The child gets a fresh
 * empty working folder, a small environment, no file descriptors but
 * stdin, stdout/stderr (one pipe) and the answer pipe on fd 3, and
 * resource limits: CPU time, memory, no new processes, no file output,
 * and, if asked, how much it may print.  The parent enforces the
 * wall-clock and output limits by killing the whole run -- nothing the
 * child does (alarm, signals, exit, fork, closing descriptors) can stall
 * it or forge a result.  What the grader reads back from a run's folder
 * (a compiler's output: keep) it opens without following links, as plain
 * files only, and copies into a folder of its own.
 *
 * Memory: the kernel enforces memory_mb as each process's address space
 * (RLIMIT_AS) on Linux.  macOS refuses so small an address space (every
 * process maps gigabytes of shared libraries), so there the parent watches
 * the physical footprint of the child's whole group every 20 ms and kills
 * the group over memory_mb; on Linux it watches the run's resident size
 * the same way, behind RLIMIT_AS.  On Linux the child also asks the
 * out-of-memory killer to take it, not the grader, should memory run out.
 */
#ifndef SANDBOX_H
#define SANDBOX_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

typedef struct {
    char *const *argv;         /* argv[0] is the program's path               */
    const char *workdir;       /* the run's working folder: made for it (it
                                  must not exist), removed after           */
    const char *cwd;           /* NULL: workdir; else a folder of visible
                                  the program starts in                    */
    const char *const *visible;/* NULL-terminated folders it may read; in
                                  the namespace jail, the only ones besides
                                  the system's programs                    */
    const char *const *keep;   /* NULL-terminated names of plain files the
                                  run writes in workdir, copied into keep_to
                                  after it (at most keep_max bytes each); a
                                  name the run did not write so is left out */
    const char *keep_to;
    size_t keep_max;
    const char *input;         /* bytes written to the child's stdin          */
    size_t input_len;
    double timeout;            /* wall-clock seconds before the run is killed */
    size_t answer_max;         /* bytes kept from fd 3 (the rest is dropped)  */
    size_t output_max;         /* bytes kept from stdout and stderr           */
    size_t output_stop;        /* bytes of stdout and stderr after which the
                                  run is stopped; 0: never (what is over
                                  output_max is read and dropped)            */
    long memory_mb;            /* memory limit (see above); 0 = none          */
    long address_mb;           /* RLIMIT_AS when not memory_mb (0: memory_mb,
                                  -1: none); the tests of the sandbox set it
                                  above memory_mb to reach the watch alone   */
    int cpu_seconds;           /* RLIMIT_CPU; 0: the timeout plus 2 s         */
    int max_procs;             /* -1: no limit (the compiler needs its own);
                                  0: the child may not create processes
                                  (nor any other value)                    */
    long max_file_mb;          /* largest file the child may write; 0 = none  */
    bool compiler;             /* the caller's PATH, and TMPDIR the working
                                  folder                                    */
    bool init;                 /* student code: in the namespace jail, a PID
                                  namespace of its own, whose first process
                                  the program is; it knows the jail
                                  (harness_init.h): it forks the one process
                                  that runs the test, and reports that
                                  one's end on fd 4.  Without (the
                                  compiler), the system's PID namespace     */
} SandboxSpec;

typedef struct {
    char *answer;              /* NUL-terminated; what the child wrote on fd 3 */
    size_t answer_len;
    bool answer_truncated;
    char *output;              /* NUL-terminated; stdout and stderr, merged   */
    size_t output_len;
    bool output_truncated;
    bool timed_out;
    bool memory_exceeded;      /* killed by the parent for using more than
                                  memory_mb                                   */
    bool output_exceeded;      /* killed by the parent for printing more than
                                  output_stop bytes                           */
    int exit_code;             /* the exit status, or -1 when killed          */
    int signal;                /* the signal that ended it, or 0             */
    double seconds;
    double cpu_seconds;        /* user and system CPU of the child and of the
                                  processes it waited for (the compiler's)   */
} SandboxResult;

/* Runs spec's program.  Returns 0 when it ran (whatever it did), or -1 when
 * the sandbox itself failed, with a reason in err.  One call at a time per
 * process: the child's plan is prepared in static storage (sandbox.c). */
int sandbox_run(const SandboxSpec *spec, SandboxResult *res, char *err, size_t errlen);
void sandbox_result_free(SandboxResult *res);

/* True where the parent can see the child's memory (Linux, macOS), so that
 * memory_mb holds even where the kernel ignores RLIMIT_AS. */
bool sandbox_watches_memory(void);

/* True when the grader runs as root and so drops children to an
 * unprivileged user. */
bool sandbox_drops_privileges(void);
/* The user and group id runs take: as root, "nobody" or the id
 * sandbox_set_user gave; else the grader's own. */
void sandbox_ids(uid_t *uid, gid_t *gid);
/* As root: the children of this process run as the user and group id
 * instead of "nobody" (grade --all gives each submission graded at once an
 * id of its own, and a submission graded alone takes one, so that one's
 * code cannot signal another's tests); 0: as "nobody" again.  held: the
 * id is this grader's alone (sandbox_spare_users), so that in the fallback
 * jail every process and file of it is removed after each run. */
void sandbox_set_user(uid_t id, bool held);
/* As root: up to n ids, from 65533 down, that no user and no group has
 * (nor nobody), each checked by a child that takes it; stores them in
 * ids and returns how many it found.  Each is held until this process
 * ends, against every other grader that asks for ids at the same time (a
 * lock on one byte of SANDBOX_USERS_LOCK, at the id's offset), which then
 * gets others.
 * *unclaimed is NULL, or says why the ids could not be held so (they are
 * found all the same, but another grader may be given them too). */
int sandbox_spare_users(uid_t *ids, int n, const char **unclaimed);
/* /var/run is root's alone on Linux and macOS, so no one else can make or
 * replace the file. */
#define SANDBOX_USERS_LOCK "/var/run/rtgrade-users.lock"

/* The runs this process started, and the seconds their namespace jails
 * took to build (0 in the fallback), for grade --cost. */
void sandbox_jail_cost(int *runs, double *seconds);

/* Seconds on a monotonic clock. */
double sandbox_now(void);
/* CPU seconds (user and system) used so far by this process (self) or by
 * the children it has waited for (!self). */
double sandbox_cpu(bool self);

#endif
