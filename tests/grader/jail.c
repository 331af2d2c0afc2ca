/*
 * jail.c - see jail.h.  The namespaces are Linux's (clone, mount,
 * pivot_root); the fallback's sweep (but its statfs), the removal of a
 * tree and the taking back of a file are POSIX.
 */
#define _GNU_SOURCE             /* clone and the mount flags (Linux) */
#define _DARWIN_C_SOURCE        /* macOS: the rest */
#include "jail.h"
#include "kit/savefile.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <sched.h>
#include <sys/ipc.h>
#include <sys/mount.h>
#include <sys/msg.h>
#include <sys/prctl.h>
#include <sys/sem.h>
#include <sys/shm.h>
#include <sys/statfs.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
/* The seccomp filter (jail_deny_calls) needs the kernel's headers, which a
 * C library alone (musl's, say) may come without: where they are missing,
 * no filter. */
#if defined(__has_include)
#if __has_include(<linux/seccomp.h>) && __has_include(<linux/filter.h>) && __has_include(<linux/audit.h>)
#include <stddef.h>
#include <linux/audit.h>       /* portable: __linux__ */
#include <linux/filter.h>      /* portable: __linux__ */
#include <linux/seccomp.h>     /* portable: __linux__ */
#if defined(__x86_64__)
#define RUN_ARCH AUDIT_ARCH_X86_64
#elif defined(__aarch64__)
#define RUN_ARCH AUDIT_ARCH_AARCH64
#endif
#endif
#endif
#else
#include <sys/param.h>
#include <sys/mount.h>         /* fstatfs, MNT_LOCAL */
#endif

/* ---- the namespace jail (Linux) ------------------------------------------------ */

#if defined(__linux__)

/* What the child does, in order, with paths relative to the new root: the
 * root is a tmpfs mounted over /proc (the one folder of the system the
 * jail never reads), built there, then made the root (pivot_root). */
enum { STEP_DIR, STEP_LINK, STEP_BIND, STEP_DEVICE, STEP_TMPFS };

#define JAIL_PATH 1024
#define MAX_STEPS 64

typedef struct {
    int kind;
    char dst[JAIL_PATH];       /* relative to the new root                  */
    char src[JAIL_PATH];       /* bind, device: the host's path; link: its
                                  target; tmpfs: the mount's options        */
    unsigned long ro;          /* bind: 0 read-write, else the remount's
                                  flags (read-only and what the source's
                                  mount has, which a user namespace may not
                                  drop)                                     */
    mode_t mode;               /* dir                                       */
} Step;

static struct {
    Step steps[MAX_STEPS];
    int n, nsystem;            /* the system's steps come first, made once  */
    char cwd[JAIL_PATH];       /* the program's working folder              */
    bool pid_namespace;
    bool user;                 /* in a user namespace: the maps below      */
    char uid_map[64], gid_map[64];
} plan;

/* Sizes of the tmpfs mounts (jail.h): a test may write no file (its file
 * size limit is 0), so its folders hold names only; the compiler writes
 * in its working folder, the grader's (TMPDIR, sandbox.c). */
#define ROOT_OPTIONS   "size=1m,nr_inodes=512,mode=0755"
#define TMP_OPTIONS    "size=1m,nr_inodes=256,mode=1777"
#define SHM_OPTIONS    "size=1m,nr_inodes=64,mode=1777"
#define WORK_OPTIONS   "size=1m,nr_inodes=256,mode=0700"

static Step *add_step(int kind, const char *dst, const char *src)
{
    if (plan.n == MAX_STEPS || strlen(dst) >= JAIL_PATH || (src && strlen(src) >= JAIL_PATH))
        return NULL;
    Step *s = &plan.steps[plan.n++];
    memset(s, 0, sizeof *s);
    s->kind = kind;
    snprintf(s->dst, sizeof s->dst, "%s", dst);
    snprintf(s->src, sizeof s->src, "%s", src ? src : "");
    s->mode = 0755;
    return s;
}

/* The remount flags of a read-only bind of path: read-only, no set-id
 * programs, no devices, and what its own mount has. */
static unsigned long ro_flags(const char *path)
{
    unsigned long flags = MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV;
    struct statvfs sv;
    if (statvfs(path, &sv) == 0) {
        if (sv.f_flag & ST_NOEXEC)
            flags |= MS_NOEXEC;
        if (sv.f_flag & ST_NOATIME)
            flags |= MS_NOATIME;
        if (sv.f_flag & ST_NODIRATIME)
            flags |= MS_NODIRATIME;
        if (sv.f_flag & ST_RELATIME)
            flags |= MS_RELATIME;
    }
    return flags;
}

/* Whether step dst (relative) is made already, or lies in one made read-only. */
static bool made(const char *dst)
{
    for (int k = 0; k < plan.n; k++) {
        size_t n = strlen(plan.steps[k].dst);
        if (strcmp(plan.steps[k].dst, dst) == 0)
            return true;
        if (plan.steps[k].kind != STEP_DIR && plan.steps[k].kind != STEP_TMPFS &&
            strncmp(plan.steps[k].dst, dst, n) == 0 && dst[n] == '/')
            return true;
    }
    return false;
}

/* Folders for every parent of path (absolute), from the top; -1 when a
 * parent lies in a folder bound read-only (nothing can be made there). */
static int add_parents(const char *path)
{
    char dst[JAIL_PATH];
    for (const char *p = path + 1; (p = strchr(p, '/')); p++) {
        snprintf(dst, sizeof dst, "%.*s", (int)(p - path - 1), path + 1);
        if (!made(dst) && !add_step(STEP_DIR, dst, NULL))
            return -1;
    }
    return 0;
}

/* A host path, read-only at the same place (dir or file); 0, or -1. */
static int add_bind(const char *path, bool ro)
{
    if (path[0] != '/' || add_parents(path) != 0)
        return -1;
    Step *s = add_step(STEP_BIND, path + 1, path);
    if (!s)
        return -1;
    s->ro = ro ? ro_flags(path) : 0;
    return 0;
}

/* The system's part of every root: its program folders as they are
 * (links kept as links: /lib is one where /usr is merged), the loader's
 * cache, the alternatives' links (/usr/bin/cc is one), three devices, a
 * private /tmp and /dev/shm. */
static int plan_system(void)
{
    static const char *const dirs[] = { "/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64",
                                        "/libx32", "/etc/alternatives", "/etc/ld.so.cache" };
    plan.n = 0;
    add_step(STEP_DIR, "etc", NULL);
    for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; k++) {
        struct stat st;
        if (lstat(dirs[k], &st) != 0)
            continue;
        if (S_ISLNK(st.st_mode)) {
            char target[JAIL_PATH];
            ssize_t n = readlink(dirs[k], target, sizeof target - 1);
            if (n <= 0)
                continue;
            target[n] = '\0';
            if (!add_step(STEP_LINK, dirs[k] + 1, target))
                return -1;
        } else if ((S_ISDIR(st.st_mode) || S_ISREG(st.st_mode)) && add_bind(dirs[k], true) != 0) {
            return -1;
        }
    }
    static const char *const devices[] = { "/dev/null", "/dev/zero", "/dev/urandom" };
    add_step(STEP_DIR, "dev", NULL);
    for (size_t k = 0; k < sizeof devices / sizeof devices[0]; k++)
        if (!add_step(STEP_DEVICE, devices[k] + 1, devices[k]))
            return -1;
    Step *tmp = add_step(STEP_DIR, "tmp", NULL);
    if (!tmp || !add_step(STEP_TMPFS, "tmp", TMP_OPTIONS) || !add_step(STEP_DIR, "dev/shm", NULL) ||
        !add_step(STEP_TMPFS, "dev/shm", SHM_OPTIONS))
        return -1;
    tmp->mode = 01777;
    plan.nsystem = plan.n;
    return 0;
}

int jail_prepare(const JailPaths *paths, uid_t uid, gid_t gid, char *why, size_t whylen)
{
    static bool system_planned;
    if (!system_planned && plan_system() != 0) {
        snprintf(why, whylen, "the jail's root has too many steps");
        return -1;
    }
    system_planned = true;
    plan.n = plan.nsystem;
    int bad = 0;
    for (int k = 0; paths->visible && paths->visible[k] && !bad; k++)
        if (!made(paths->visible[k] + 1))
            bad = add_bind(paths->visible[k], true);
    if (!bad && paths->workdir_shared) {
        bad = add_bind(paths->workdir, false);
    } else if (!bad) {
        char options[128];
        snprintf(options, sizeof options, "%s,uid=%ld,gid=%ld", WORK_OPTIONS, (long)uid, (long)gid);
        bad = paths->workdir[0] != '/' || add_parents(paths->workdir) != 0 ||
              !add_step(STEP_DIR, paths->workdir + 1, NULL) ||
              !add_step(STEP_TMPFS, paths->workdir + 1, options);
    }
    const char *cwd = paths->cwd ? paths->cwd : paths->workdir;
    if (bad || strlen(cwd) >= sizeof plan.cwd) {
        snprintf(why, whylen, "a folder of the run cannot be placed in the jail: %s", paths->workdir);
        return -1;
    }
    snprintf(plan.cwd, sizeof plan.cwd, "%s", cwd);
    plan.pid_namespace = paths->pid_namespace;
    plan.user = geteuid() != 0;
    snprintf(plan.uid_map, sizeof plan.uid_map, "%ld %ld 1\n", (long)uid, (long)geteuid());
    snprintf(plan.gid_map, sizeof plan.gid_map, "%ld %ld 1\n", (long)gid, (long)getegid());
    return 0;
}

/* ---- in the child: only system calls (it shares the grader's memory) ---- */

/* Writes "jail: what: errno N" to fd. */
static void say_failed(int fd, const char *what, int err)
{
    char digits[16];
    int n = 0;
    do
        digits[sizeof digits - 1 - n++] = (char)('0' + err % 10);
    while ((err /= 10) > 0 && n < 15);
    if (write(fd, "jail: ", 6) < 0 || write(fd, what, strlen(what)) < 0 ||
        write(fd, ": errno ", 8) < 0 || write(fd, digits + sizeof digits - n, (size_t)n) < 0 ||
        write(fd, "\n", 1) < 0)
        return;
}

static int write_file(const char *path, const char *text)
{
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0)
        return -1;
    ssize_t n = write(fd, text, strlen(text));
    close(fd);
    return n == (ssize_t)strlen(text) ? 0 : -1;
}

static int take_step(const Step *s)
{
    switch (s->kind) {
    case STEP_DIR:
        return mkdir(s->dst, s->mode) == 0 || errno == EEXIST ? chmod(s->dst, s->mode) : -1;
    case STEP_LINK:
        return symlink(s->src, s->dst);
    case STEP_BIND: {
        struct stat st;
        if (stat(s->src, &st) != 0)
            return -1;
        if (S_ISDIR(st.st_mode) ? mkdir(s->dst, 0755) != 0 && errno != EEXIST
                                : mknod(s->dst, S_IFREG | 0644, 0) != 0)
            return -1;
        if (mount(s->src, s->dst, NULL, MS_BIND | MS_REC, NULL) != 0)
            return -1;
        return s->ro ? mount(NULL, s->dst, NULL, s->ro, NULL) : 0;
    }
    case STEP_DEVICE:
        if (mknod(s->dst, S_IFREG | 0666, 0) != 0)
            return -1;
        return mount(s->src, s->dst, NULL, MS_BIND, NULL);
    case STEP_TMPFS:
        return mount("jail", s->dst, "tmpfs", MS_NOSUID | MS_NODEV, s->src);
    }
    return -1;
}

int jail_enter(int fd)
{
    if (plan.user && (write_file("/proc/self/uid_map", plan.uid_map) != 0 ||      /* portable: Linux */
                      write_file("/proc/self/setgroups", "deny") != 0 ||          /* portable: Linux */
                      write_file("/proc/self/gid_map", plan.gid_map) != 0)) {     /* portable: Linux */
        say_failed(fd, "the user namespace's maps", errno);
        return -1;
    }
    /* The out-of-memory killer takes the run first (its own /proc is gone below). */
    write_file("/proc/self/oom_score_adj", "1000\n");          /* portable: Linux */
    if (mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0 ||
        mount("jail", "/proc", "tmpfs", MS_NOSUID | MS_NODEV, ROOT_OPTIONS) != 0 || chdir("/proc") != 0) {
        say_failed(fd, "the root", errno);
        return -1;
    }
    for (int k = 0; k < plan.n; k++)
        if (take_step(&plan.steps[k]) != 0) {
            say_failed(fd, plan.steps[k].dst, errno);
            return -1;
        }
    if (syscall(SYS_pivot_root, ".", ".") != 0 || umount2(".", MNT_DETACH) != 0 || chdir("/") != 0 ||
        mount(NULL, "/", NULL, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV, NULL) != 0 ||
        chdir(plan.cwd) != 0) {
        say_failed(fd, "entering the root", errno);
        return -1;
    }
    prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);  /* portable: Linux only (in its #if) */
    return 0;
}

/* The child's stack: it shares the grader's memory, not its stack. */
static _Alignas(16) char child_stack[1 << 16];

pid_t jail_clone(int (*child_main)(void *), void *arg)
{
    int flags = CLONE_VM | CLONE_VFORK | SIGCHLD | CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWIPC |
                CLONE_NEWUTS | (plan.pid_namespace ? CLONE_NEWPID : 0) | (plan.user ? CLONE_NEWUSER : 0);
    return clone(child_main, child_stack + sizeof child_stack, flags, arg);
}

/* The probe's child: the jail, then nothing. */
JAIL_CHILD_CODE static int probe_child(void *arg)
{
    int *fd = arg;
    _exit(jail_enter(*fd) == 0 ? 0 : 125);
}

/* Whether a jail can be made here; why not in why. */
static bool probe(char *why, size_t whylen)
{
    JailPaths paths = { .workdir = "/tmp/jail-probe", .pid_namespace = true };
    uid_t uid = geteuid() == 0 ? 65534 : geteuid();
    if (jail_prepare(&paths, uid, geteuid() == 0 ? 65534 : getegid(), why, whylen) != 0)
        return false;
    int p[2];
    if (pipe(p) != 0) {
        snprintf(why, whylen, "pipe: %s", strerror(errno));
        return false;
    }
    pid_t pid = jail_clone(probe_child, &p[1]);
    int err = errno, status = 0;
    close(p[1]);
    if (pid < 0) {
        snprintf(why, whylen, "the system refused new namespaces (%s)", strerror(err));
        close(p[0]);
        return false;
    }
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        continue;
    char said[300] = "";
    ssize_t n = read(p[0], said, sizeof said - 1);
    close(p[0]);
    said[n > 0 ? n : 0] = '\0';
    said[strcspn(said, "\n")] = '\0';
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return true;
    snprintf(why, whylen, "the namespaces could not be set up (%s)", said[0] ? said : "no reason given");
    return false;
}

#else   /* not Linux */

int jail_prepare(const JailPaths *paths, uid_t uid, gid_t gid, char *why, size_t whylen)
{
    (void)paths, (void)uid, (void)gid;
    snprintf(why, whylen, "this system has no namespaces");
    return -1;
}
pid_t jail_clone(int (*child_main)(void *), void *arg)
{
    (void)child_main, (void)arg;
    errno = ENOSYS;
    return -1;
}
int jail_enter(int fd)
{
    (void)fd;
    return -1;
}
static bool probe(char *why, size_t whylen)
{
    snprintf(why, whylen, "this system has no namespaces");
    return false;
}

#endif

/* ---- the mode ----------------------------------------------------------------- */

static int mode = -1;
static char refused[400];

JailMode jail_mode(void)
{
    if (mode >= 0)
        return (JailMode)mode;
    const char *want = getenv("GRADE_JAIL");
    bool root = geteuid() == 0;
    if (want && strcmp(want, "fallback") == 0) {
        snprintf(refused, sizeof refused, "GRADE_JAIL=fallback");
        mode = root ? JAIL_FALLBACK_ROOT : JAIL_FALLBACK_USER;
    } else if (probe(refused, sizeof refused)) {
        mode = root ? JAIL_NAMESPACES_ROOT : JAIL_NAMESPACES_USER;
    } else {
        mode = root ? JAIL_FALLBACK_ROOT : JAIL_FALLBACK_USER;
    }
    return (JailMode)mode;
}

bool jail_namespaces(void)
{
    JailMode m = jail_mode();
    return m == JAIL_NAMESPACES_ROOT || m == JAIL_NAMESPACES_USER;
}

const char *jail_describe(void)
{
    static char text[700];
    switch (jail_mode()) {
    case JAIL_NAMESPACES_ROOT:
    case JAIL_NAMESPACES_USER:
        return "namespaces: each run of the submission's code had a root of its own with only the "
               "system's programs, its own files and an empty private /tmp, no network and no "
               "other process in view; nothing it made outlived it";
    case JAIL_FALLBACK_ROOT:
        snprintf(text, sizeof text, "fallback (%s): each run of the submission's code ran as a user "
                 "id of its own in a fresh folder%s; after each run every process of that id was "
                 "killed and every file it made removed", refused,
                 jail_filters() ? ", with no network" : ", with the system's network");
        return text;
    case JAIL_FALLBACK_USER:
        snprintf(text, sizeof text, "limits only (%s): the submission's code ran as the user who "
                 "graded it, and could read what that user can%s", refused,
                 jail_filters() ? ", with no network" : " and reach the network");
        return text;
    }
    return "";
}

int jail_make_private(const char *path, char *why, size_t whylen)
{
    struct stat st;
    if (jail_mode() != JAIL_FALLBACK_ROOT || stat(path, &st) != 0 || !(st.st_mode & 007))
        return 0;
    if (chmod(path, st.st_mode & 07770) != 0) {
        snprintf(why, whylen, "%s: the submissions' code runs as a user of its own here (no "
                 "namespaces), which could read this folder; chmod o-rwx failed: %s", path,
                 strerror(errno));
        return -1;
    }
    fprintf(stderr, "grade: %s made private (chmod o-rwx): without namespaces here, the "
            "submissions' code runs as a user of its own, which must not read it\n", path);
    return 0;
}

/* ---- the seccomp filter (Linux) --------------------------------------------------- */

#if defined(__linux__) && defined(RUN_ARCH)
/* A DENY of the filter: the system call numbered nr fails with EPERM. */
#define DENY(nr) BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, (nr), 0, 1), \
                 BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | EPERM)

/* What no namespace shuts off, a seccomp filter does: these system calls
 * fail (EPERM).  Docker's default profile fails the key store's and
 * io_uring's too.
 *   - The key store (keyctl, add_key, request_key).  Keyrings belong to no
 *     namespace: through the session keyring it shares with the grader a
 *     run could read the grader's keys, and keys it left under its id would
 *     wait there for the next run given that id.
 *   - The network (socket, and io_uring, which makes sockets without it).
 *     In the fallback jail the network is the system's: a run could send
 *     every case it is given, the hidden ones too, to anywhere.
 *   - A system call of another ABI (x86-64's x32, or i386's int 0x80 and
 *     its socketcall), so that none of these is reached by another number.
 * Best effort: a kernel without seccomp runs the program as is, and so
 * does a build without the kernel's headers or on another processor
 * (RUN_ARCH undefined). */
JAIL_CHILD_CODE void jail_deny_calls(void)
{
    struct sock_filter code[] = {
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, arch)),
        BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, RUN_ARCH, 1, 0),
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | EPERM),
        BPF_STMT(BPF_LD | BPF_W | BPF_ABS, offsetof(struct seccomp_data, nr)),
        BPF_JUMP(BPF_JMP | BPF_JGE | BPF_K, 0x40000000, 0, 1),     /* x32 (x86-64 only) */
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ERRNO | EPERM),
        DENY(__NR_keyctl), DENY(__NR_add_key), DENY(__NR_request_key), DENY(__NR_socket),
#if defined(__NR_io_uring_setup)
        DENY(__NR_io_uring_setup),
#endif
        BPF_STMT(BPF_RET | BPF_K, SECCOMP_RET_ALLOW),
    };
    struct sock_fprog program = { (unsigned short)(sizeof code / sizeof code[0]), code };
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0)                            /* portable: __linux__ */
        prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program);                    /* portable: __linux__ */
}

/* Whether the kernel has seccomp (PR_GET_SECCOMP fails where it has none). */
bool jail_filters(void)
{
    return prctl(PR_GET_SECCOMP, 0, 0, 0, 0) >= 0;                              /* portable: __linux__ */
}
#else
void jail_deny_calls(void)
{
}

bool jail_filters(void)
{
    return false;
}
#endif

/* ---- removing a tree ---------------------------------------------------------- */

/* Removes name in the folder dfd, and all in it.  Descends one folder at
 * a time (one descriptor open, the names on the way kept in a list), and
 * climbs back by "..": no process of the run is left to move anything. */
static int remove_at(int dfd, const char *name)
{
    if (unlinkat(dfd, name, 0) == 0 || errno == ENOENT)
        return 0;
    fchmodat(dfd, name, 0700, AT_SYMLINK_NOFOLLOW);   /* a folder made unreadable; fails for links */
    int fd = openat(dfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return -1;
    char **path = NULL;         /* the names from name down to fd's folder */
    size_t depth = 0, cap = 0;
    int status = 0;
    for (;;) {
        int dup_fd = dup(fd);
        DIR *d = dup_fd >= 0 ? fdopendir(dup_fd) : NULL;
        if (!d) {
            if (dup_fd >= 0)
                close(dup_fd);
            status = -1;
            break;
        }
        char sub[NAME_MAX + 1] = "";
        struct dirent *e;
        while ((e = readdir(d))) {
            if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
                continue;
            if (unlinkat(fd, e->d_name, 0) == 0 || errno == ENOENT)
                continue;
            snprintf(sub, sizeof sub, "%s", e->d_name);     /* a folder: down into it */
            break;
        }
        closedir(d);
        if (sub[0]) {
            fchmodat(fd, sub, 0700, AT_SYMLINK_NOFOLLOW);
            int down = openat(fd, sub, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            char *copy = strdup(sub);
            if (depth == cap) {
                size_t ncap = cap ? 2 * cap : 64;
                char **grown = realloc(path, ncap * sizeof *path);
                if (grown)
                    path = grown, cap = ncap;
            }
            if (down < 0 || !copy || depth == cap) {
                if (down >= 0)
                    close(down);
                free(copy);
                status = -1;
                break;
            }
            close(fd);
            fd = down;
            path[depth++] = copy;
            continue;
        }
        if (depth == 0)         /* name itself is empty now */
            break;
        int up = openat(fd, "..", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (up < 0) {
            status = -1;
            break;
        }
        close(fd);
        fd = up;
        char *child = path[--depth];
        int rc = unlinkat(fd, child, AT_REMOVEDIR);
        free(child);
        if (rc != 0 && errno != ENOENT) {
            status = -1;
            break;
        }
    }
    close(fd);
    while (depth > 0)
        free(path[--depth]);
    free(path);
    if (status == 0 && unlinkat(dfd, name, AT_REMOVEDIR) != 0 && errno != ENOENT)
        status = -1;
    return status;
}

int jail_remove_tree(const char *path)
{
    return remove_at(AT_FDCWD, path);
}

/* ---- the fallback's sweep ----------------------------------------------------- */

/* Every process of id, killed: kill(-1) as id reaches every process of its
 * own and no other. */
static void kill_once(uid_t id)
{
#if defined(__linux__)
    pid_t pid = vfork();        /* portable: __linux__ (macOS deprecates vfork: fork there) */
#else
    pid_t pid = fork();
#endif
    if (pid == 0) {
        if (setgroups(0, NULL) == 0 && setgid((gid_t)id) == 0 && setuid(id) == 0)
            kill(-1, SIGKILL);
        _exit(0);
    }
    if (pid > 0)
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR)
            continue;
}

/* Twice: a process started while the first went round dies in the second. */
static void kill_user(uid_t id)
{
    kill_once(id);
    kill_once(id);
}

/* Removes what id owns in the folder dfd, looking into the folders under
 * it that anyone may write in (/tmp/.X11-unix, say), depth levels down. */
static void sweep_folder(int dfd, uid_t id, int depth)
{
    int dup_fd = dup(dfd);
    DIR *d = dup_fd >= 0 ? fdopendir(dup_fd) : NULL;
    if (!d) {
        if (dup_fd >= 0)
            close(dup_fd);
        return;
    }
    struct dirent *e;
    while ((e = readdir(d))) {
        struct stat st;
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") ||
            fstatat(dfd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        if (st.st_uid == id) {
            remove_at(dfd, e->d_name);
        } else if (S_ISDIR(st.st_mode) && (st.st_mode & S_IWOTH) && depth < 3) {
            int sub = openat(dfd, e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (sub >= 0) {
                sweep_folder(sub, id, depth + 1);
                close(sub);
            }
        }
    }
    closedir(d);
}

#if defined(__linux__)
/* Removes the System V IPC objects id owns or made (/proc/sysvipc: the
 * owner's and the maker's ids are the columns named uid and cuid). */
static void remove_ipc(uid_t id)
{
    static const char *const tables[] = { "/proc/sysvipc/shm", "/proc/sysvipc/sem", "/proc/sysvipc/msg" };  /* portable: Linux only (in its #if) */
    for (int t = 0; t < 3; t++) {
        FILE *f = fopen(tables[t], "r");
        if (!f)
            continue;
        char line[1024];
        int uid_col = -1, cuid_col = -1;
        if (fgets(line, sizeof line, f)) {
            int col = 0;
            for (char *w = strtok(line, " \t\n"); w; w = strtok(NULL, " \t\n"), col++) {
                if (!strcmp(w, "uid"))
                    uid_col = col;
                if (!strcmp(w, "cuid"))
                    cuid_col = col;
            }
        }
        while (uid_col >= 0 && fgets(line, sizeof line, f)) {
            long v[32];
            int n = 0;
            for (char *w = strtok(line, " \t\n"); w && n < 32; w = strtok(NULL, " \t\n"))
                v[n++] = strtol(w, NULL, 10);
            if (n <= uid_col || n <= cuid_col ||
                ((uid_t)v[uid_col] != id && (cuid_col < 0 || (uid_t)v[cuid_col] != id)))
                continue;
            int ipc_id = (int)v[1];
            if (t == 0)
                shmctl(ipc_id, IPC_RMID, NULL);
            else if (t == 1)
                semctl(ipc_id, 0, IPC_RMID);
            else
                msgctl(ipc_id, IPC_RMID, NULL);
        }
        fclose(f);
    }
}
#else
static void remove_ipc(uid_t id)
{
    (void)id;       /* macOS: ipcs(1) only; left to the machine's own cleaning */
}
#endif

/* The places swept: the folders anyone may write in, found at the first
 * sweep (find_places).  None lies under a link (the walk follows none),
 * but one below a folder anyone may write in (the walk enters those too,
 * for a course's /tmp/course/shared) may be a folder the first run made,
 * and a later run may put a link where it was.  That costs nothing: a
 * place is opened without following its last name, and sweep_folder
 * removes only what the run's own id owns, wherever it is. */
static char **places;
static size_t nplaces;

static void add_place(const char *path)
{
    for (size_t k = 0; k < nplaces; k++)
        if (strcmp(places[k], path) == 0)
            return;
    char **grown = realloc(places, (nplaces + 1) * sizeof *places);
    if (grown)
        places = grown;
    if (grown && (places[nplaces] = strdup(path)))
        nplaces++;
}

#if defined(__linux__)
#define NO_AUTOMOUNT AT_NO_AUTOMOUNT
#define PATH_ONLY O_PATH                /* portable: Linux only (in its #if) */
#else
#define NO_AUTOMOUNT 0
#define PATH_ONLY O_RDONLY
#endif

/* Whether the walk goes into a file system mounted under the one it was
 * in: into any but the network's (and user space's, FUSE), where a walk is
 * slow or hangs and root is often refused anyway, and autofs, whose mounts
 * it does not trigger.  Local ones (a /var of its own, a container's
 * volumes, tmpfs) are walked as the root's: a run may write there too.
 * (A mount point anyone may write in is a place, whatever its kind.) */
static bool walked(const struct statfs *sf)
{
#if defined(__linux__)
    /* NFS, SMB, CIFS, SMB2, FUSE, 9p, AFS, kAFS, Ceph, autofs */
    static const unsigned remote[] = { 0x6969, 0x517B, 0xFF534D42, 0xFE534D42, 0x65735546,
                                     0x01021997, 0x5346414F, 0x6B414653, 0x00C36400, 0x0187 };
    for (size_t k = 0; k < sizeof remote / sizeof remote[0]; k++)
        if ((unsigned)sf->f_type == remote[k])
            return false;
    return true;
#else
    return sf->f_flags & MNT_LOCAL;
#endif
}

/* The folder name in dfd opened to be read, links not followed; when it
 * is another file system's (other), only one walked, which is opened as
 * a path only first (Linux's O_PATH triggers no automount). */
static int open_folder(int dfd, const char *name, bool other)
{
    if (!other)
        return openat(dfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    int at = openat(dfd, name, PATH_ONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    struct statfs sf;
    int fd = -1;
    if (at >= 0 && fstatfs(at, &sf) == 0 && walked(&sf))
        fd = openat(at, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (at >= 0)
        close(at);
    return fd;
}

/* Adds the folders anyone may write in under the folder dfd (path, on
 * device dev, whose names are depth levels below /), down to PLACES_DEPTH,
 * not in /proc or /sys; under one found too, where sweep_folder does not
 * look: it goes only through folders anyone may write in, and a course's
 * shared folder may be in one closed to others (/tmp/course/shared).  Only
 * folders are looked at (a stat each), never through a link, and not into
 * one others may not go through (a run cannot reach what is in it) nor one
 * with 2 links (no folder in it, where links count folders; 1 where they
 * do not).  dfd is closed. */
#define PLACES_DEPTH 4
static void walk(int dfd, const char *path, dev_t dev, int depth)
{
    DIR *d = fdopendir(dfd);
    if (!d) {
        close(dfd);
        return;
    }
    struct dirent *e;
    while ((e = readdir(d))) {
        char sub[PATH_MAX];
        struct stat st;
        if ((e->d_type != DT_DIR && e->d_type != DT_UNKNOWN) || !strcmp(e->d_name, ".") ||
            !strcmp(e->d_name, "..") ||
            snprintf(sub, sizeof sub, "%s/%s", path, e->d_name) >= (int)sizeof sub ||
            !strcmp(sub, "/proc") || !strcmp(sub, "/sys") ||
            fstatat(dfd, e->d_name, &st, AT_SYMLINK_NOFOLLOW | NO_AUTOMOUNT) != 0 ||
            !S_ISDIR(st.st_mode))
            continue;
        if (st.st_mode & S_IWOTH)
            add_place(sub);
        if (depth < PLACES_DEPTH && (st.st_mode & S_IXOTH) && st.st_nlink != 2) {
            int fd = open_folder(dfd, e->d_name, st.st_dev != dev);
            if (fd >= 0)
                walk(fd, sub, st.st_dev, depth + 1);
        }
    }
    closedir(d);
}

/* The places: the usual ones, and every folder anyone may write in found
 * within PLACES_DEPTH levels of / (/var/crash, /var/mail, a course's
 * shared folder...): what a run leaves there, a later run given the same
 * id would find.  A stat per folder down there: some 2,600 folders and
 * 15 ms on a Debian container, once per grade process (grade --all grades
 * each submission in one of its own). */
static void find_places(void)
{
    static const char *const usual[] = { "/tmp", "/var/tmp", "/dev/shm", "/run/lock", "/dev/mqueue" };
    for (size_t k = 0; k < sizeof usual / sizeof usual[0]; k++)
        add_place(usual[k]);
    int fd = open("/", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    struct stat st;
    if (fd >= 0 && fstat(fd, &st) == 0)
        walk(fd, "", st.st_dev, 1);
    else if (fd >= 0)
        close(fd);
}

void jail_sweep(uid_t id)
{
    if (id == 0)
        return;
    kill_user(id);
    if (nplaces == 0)
        find_places();
    for (size_t k = 0; k < nplaces; k++) {
        int fd = open(places[k], O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (fd >= 0) {
            sweep_folder(fd, id, 0);
            close(fd);
        }
    }
    remove_ipc(id);
}

/* ---- taking a file back ------------------------------------------------------- */

int jail_take_file(const char *dir, const char *name, const char *to, size_t max, char *why,
                   size_t whylen)
{
    int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    int in = dfd >= 0 ? openat(dfd, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC) : -1;
    if (dfd >= 0)
        close(dfd);
    struct stat st;
    if (in < 0 || fstat(in, &st) != 0 || !S_ISREG(st.st_mode) || st.st_nlink != 1 ||
        (size_t)st.st_size > max) {
        snprintf(why, whylen, "%s was not written as a plain file of at most %zu bytes", name, max);
        if (in >= 0)
            close(in);
        return -1;
    }
    FILE *f = fdopen(in, "rb");
    size_t n = 0;
    char *bytes = f ? kit_load_stream(f, max, &n) : NULL;
    if (!f)
        close(in);
    int status = bytes ? kit_save_file(to, bytes, n, why, whylen) : -1;
    if (!bytes)
        snprintf(why, whylen, "%s could not be read back", name);
    free(bytes);
    return status;
}
