/*
 * jail.h - the box that every run of student code gets (sandbox.c runs
 * the program in it): compiling, the tests, the diagnosis's probes, the
 * report page's render.
 *
 * The strongest of two ways the system allows, found once per process
 * (jail_mode); what each gives and lacks is tabled in tests/grader/
 * README.md ("The jail").  Here, where each promise is kept:
 *
 *   namespaces: the run's root is a tmpfs holding, read-only, the system's
 *   program folders and the folders the run may read (JailPaths.visible),
 *   then its working folder and a private /tmp and /dev/shm.  A run of
 *   student code (JailPaths.pid_namespace) has a PID namespace of its own,
 *   whose first process is the test's (harness_init.h): when it ends, the
 *   kernel ends every other.  The compiler, which runs none, keeps the
 *   system's.
 *
 *   fallback: as root, the spare user id's processes are killed and the
 *   names it owns in the world-writable places removed after every run
 *   (jail_sweep); on Linux no run can make a socket (jail_deny_calls); the
 *   grader checks that the id cannot read the kit (grade_main.c).
 */
#ifndef JAIL_H
#define JAIL_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

typedef enum {
    JAIL_NAMESPACES_ROOT,      /* namespaces, the grader root             */
    JAIL_NAMESPACES_USER,      /* namespaces in a user namespace          */
    JAIL_FALLBACK_ROOT,        /* a user id of its own, swept after      */
    JAIL_FALLBACK_USER         /* limits only: runs as the user          */
} JailMode;

/* The mode runs take in this process: probed at the first call (a trial
 * jail), or fallback when GRADE_JAIL is "fallback". */
JailMode jail_mode(void);
bool jail_namespaces(void);
/* What the mode guarantees, in a sentence for the results file and the
 * grader's --jail line; when namespaces were wanted but refused, why. */
const char *jail_describe(void);

/* The folders of one run.  Paths are absolute; each is where the program
 * sees it too. */
typedef struct {
    const char *workdir;       /* the run's fresh working folder: made for
                                  it, removed with all in it after        */
    bool workdir_shared;       /* namespaces: the grader's folder itself,
                                  so that the grader reads back what the
                                  run wrote (a compiler's output); else a
                                  tmpfs the grader never sees             */
    const char *cwd;           /* NULL: workdir; else a visible folder    */
    const char *const *visible;/* NULL-terminated: folders it may read   */
    bool pid_namespace;        /* a PID namespace of its own (see above)  */
} JailPaths;

/* Prepares the namespace jail for the next clone (jail_clone): the
 * steps the child takes, made here so that the child, which shares the
 * grader's memory until it runs the program, only calls the system.
 * Returns 0, or -1 with why (a path too long, too many folders). */
int jail_prepare(const JailPaths *paths, uid_t uid, gid_t gid, char *why, size_t whylen);

/* Starts child_main(arg) in the jail prepared (new namespaces, sharing
 * this process's memory until it runs its program or exits, as vfork):
 * child_main calls jail_enter first, then sets up its descriptors and
 * runs the program.  The child's pid (the first of its PID namespace),
 * or -1 with errno. */
pid_t jail_clone(int (*child_main)(void *), void *arg);

/* In the child: builds the root prepared and enters it; 0, or -1 after
 * writing why to fd (the run's output). */
/* The functions that run on the jail's child's own stack, which the
 * address sanitizer (make sanitize-grader, the unit tests) does not know:
 * not instrumented, so that it does not mistake that stack for a fault. */
#if defined(__GNUC__)
#define JAIL_CHILD_CODE __attribute__((no_sanitize_address))
#else
#define JAIL_CHILD_CODE
#endif
int jail_enter(int fd);

/* In the child, just before it runs the program (Linux, x86-64 and arm64):
 * a seccomp filter fails the system calls of the key store and the
 * network, and any of another ABI (jail.c says why).  jail_filters: whether
 * runs get the filter (the build needs the kernel's headers, and the
 * kernel seccomp). */
void jail_deny_calls(void);
bool jail_filters(void);

/* As root, fallback: kills every process of id and removes every name it
 * owns in the world-writable places (/tmp, /var/tmp, /dev/shm, /run/lock,
 * /dev/mqueue, every other folder anyone may write in within 4 levels of /,
 * found at the first sweep, and folders under them anyone may write in) and
 * its System V IPC objects.  Only for an id this grader holds alone. */
void jail_sweep(uid_t id);

/* As root in the fallback jail: makes the folder path unreadable and
 * impassable to others (chmod o-rwx), where the runs' user could reach
 * it: the kit (the reference, the hidden tests' seed), a class's
 * submissions, the grades.  Says so on stderr, once per folder; 0, or -1
 * when it could not (then the grader refuses to grade: why says so). */
int jail_make_private(const char *path, char *why, size_t whylen);

/* rm -rf path: links are removed, never followed; no recursion, so a
 * folder of any depth is removed.  0, or -1 when something is left. */
int jail_remove_tree(const char *path);

/* Copies the plain file name of the folder dir (a folder the run could
 * write) to the path to: opened without following links, refused unless
 * it is a regular file with one link and at most max bytes.  0, or -1
 * with why. */
int jail_take_file(const char *dir, const char *name, const char *to, size_t max, char *why,
                   size_t whylen);

#endif
