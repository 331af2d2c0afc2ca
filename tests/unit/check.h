/*
 * check.h - the kit's own unit-test runner, in one header.
 *
 *     #include "check.h"
 *     static void test_dot(void) { CHECK_EQ_DOUBLE(vec3_dot(a, b), 32.0); }
 *     static const CheckTest tests[] = { CHECK_TEST(test_dot), ... };
 *     int main(int argc, char **argv) { return check_main(argc, argv, tests, CHECK_COUNT(tests)); }
 *
 * Each test runs in its own child process, so a crash or a hang fails that
 * test alone.  A failed check prints "file:line: what" and the test goes on.
 * Messages appear only on failure; the last line is "N passed, N failed".
 * An argument runs only the tests whose names contain it.
 * check_temp_dir and check_remove_tree give a test a directory of its own,
 * and check_write_file and check_write_in a file in it.
 * check_file_is reads a file back.  check_xorshift32 and check_xorshift64
 * are small deterministic pseudo-random generators for a test's inputs,
 * check_random_bytes fills a buffer from the first, check_damaged changes
 * some bytes of a copy.  CHECK_SANITIZED is 1 in the sanitized build, where each
 * test's child also checks for leaks before it ends.
 * Include it before any other header: it sets _POSIX_C_SOURCE.
 */
#ifndef CHECK_H
#define CHECK_H

#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* CHECK_SANITIZED: 1 when built with the address sanitizer (gcc says so
 * with __SANITIZE_ADDRESS__, clang with __has_feature), else 0.  The
 * sanitized build runs the same tests to find memory errors; where a test
 * spends seconds on what no build changes (a second of CPU the system's
 * limit must stop, the same sums at a larger size), that build may do the
 * cheaper form of it, and the plain build does the whole. */
#if defined(__SANITIZE_ADDRESS__)
#define CHECK_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CHECK_SANITIZED 1
#endif
#endif
#ifndef CHECK_SANITIZED
#define CHECK_SANITIZED 0
#endif
#if CHECK_SANITIZED
#include <sanitizer/lsan_interface.h>
/* Of the sanitizers' <sanitizer/allocator_interface.h>, which gcc does not
 * install: the bytes the program holds, allocated and not freed. */
size_t __sanitizer_get_current_allocated_bytes(void);
#endif

#ifndef CHECK_TIMEOUT_SECONDS
#define CHECK_TIMEOUT_SECONDS 120
#endif

/* A shell script's first lines that write its CPU limit, soft and hard, to
 * its descriptor 3: "limit N\nhard N\n" (shell builtins alone, for tests
 * whose children may not start processes: test_sandbox). */
#define CHECK_SAY_CPU_LIMIT \
    "printf 'limit ' >&3; ulimit -S -t >&3; printf 'hard ' >&3; ulimit -H -t >&3; "

typedef struct {
    const char *name;
    void (*fn)(void);
} CheckTest;

#define CHECK_TEST(fn) { #fn, fn }
#define CHECK_COUNT(array) ((int)(sizeof(array) / sizeof((array)[0])))

static int check_failures_;

static void check_fail_(const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#include <stdarg.h>
static void check_fail_(const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    check_failures_++;
    fprintf(stdout, "    %s:%d: ", file, line);
    va_start(ap, fmt);
    vfprintf(stdout, fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
    fflush(stdout);
}

#define CHECK(cond)                                                         \
    do { if (!(cond)) check_fail_(__FILE__, __LINE__, "CHECK(%s) failed", #cond); } while (0)

#define CHECK_MSG(cond, ...)                                                \
    do { if (!(cond)) check_fail_(__FILE__, __LINE__, __VA_ARGS__); } while (0)

#define CHECK_EQ_INT(got, want)                                             \
    do { long long g_ = (long long)(got), w_ = (long long)(want);           \
         if (g_ != w_) check_fail_(__FILE__, __LINE__, "%s is %lld, want %lld", #got, g_, w_); } while (0)

/* Bitwise-equal doubles (or both NaN), printed as hex floats on failure. */
#define CHECK_EQ_DOUBLE(got, want)                                          \
    do { double g_ = (got), w_ = (want);                                    \
         if (!(g_ == w_ || (isnan(g_) && isnan(w_))))                       \
             check_fail_(__FILE__, __LINE__, "%s is %a (%.17g), want %a (%.17g)", #got, g_, g_, w_, w_); } while (0)

/* |got - want| <= tol, printed on failure. */
#define CHECK_NEAR(got, want, tol)                                          \
    do { double g_ = (got), w_ = (want), t_ = (tol);                        \
         if (!(fabs(g_ - w_) <= t_))                                        \
             check_fail_(__FILE__, __LINE__, "%s is %.17g, want %.17g within %.3g (off by %.3g)", \
                         #got, g_, w_, t_, fabs(g_ - w_)); } while (0)

#define CHECK_STR_CONTAINS(haystack, needle)                                \
    do { const char *h_ = (haystack), *n_ = (needle);                       \
         if (!h_ || !strstr(h_, n_))                                        \
             check_fail_(__FILE__, __LINE__, "%s is \"%s\", want it to contain \"%s\"", #haystack, h_ ? h_ : "(null)", n_); } while (0)

/* The next number of a small deterministic pseudo-random generator
 * (xorshift32) whose state is *state, not 0. */
static inline uint32_t check_xorshift32(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *state = x;
}

/* The same, xorshift64 (shifts 13, 7, 17) of the 64-bit state *state. */
static inline uint64_t check_xorshift64(uint64_t *state)
{
    *state ^= *state << 13;
    *state ^= *state >> 7;
    return *state ^= *state << 17;
}

/* p[0 .. n-1] made the top bytes of n numbers of check_xorshift32(state). */
static inline void check_random_bytes(uint32_t *state, void *p, size_t n)
{
    for (size_t k = 0; k < n; k++)
        ((unsigned char *)p)[k] = (unsigned char)(check_xorshift32(state) >> 24);
}

/* A malloc'd copy of data[0 .. n-1] (n > 0) with flips of its bytes
 * changed, each at a place and by a nonzero xor drawn from
 * check_xorshift32(state): random damage, for a reader to survive. */
static inline unsigned char *check_damaged(uint32_t *state, const void *data, size_t n, int flips)
{
    unsigned char *p = malloc(n);
    if (p)
        memcpy(p, data, n);
    for (int f = 0; p && f < flips; f++) {
        size_t at = check_xorshift32(state) % n;
        p[at] ^= (unsigned char)(1 + check_xorshift32(state) % 255);
    }
    return p;
}

/* A fresh empty directory under $TMPDIR or /tmp, named after name, in
 * path[]; 0, or -1 with a failed check. */
static inline int check_temp_dir(char *path, size_t size, const char *name)
{
    const char *base = getenv("TMPDIR");
    int n = snprintf(path, size, "%s/kit-test-%s-XXXXXX", base && *base ? base : "/tmp", name);
    if (n > 0 && (size_t)n < size && mkdtemp(path))
        return 0;
    CHECK_MSG(0, "cannot make the directory %s (TMPDIR too long?)", path);
    return -1;
}

/* Removes path and everything below it (links are removed, not followed;
 * directories made unreadable are opened again first).  0 when nothing of
 * it is left. */
static inline int check_remove_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return 0;
    if (S_ISDIR(st.st_mode)) {
        chmod(path, 0700);
        DIR *d = opendir(path);
        struct dirent *e;
        char sub[2048];
        while (d && (e = readdir(d)) != NULL) {
            if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
                continue;
            if (snprintf(sub, sizeof sub, "%s/%s", path, e->d_name) < (int)sizeof sub)
                check_remove_tree(sub);
        }
        if (d)
            closedir(d);
        return rmdir(path);
    }
    return unlink(path);
}

/* Writes data[0 .. n-1] to the file path, made or emptied; 0, or -1 with a
 * failed check naming it. */
static inline int check_write_file(const char *path, const void *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    int ok = f && fwrite(data, 1, n, f) == n;
    if (f && fclose(f) != 0)
        ok = 0;
    if (!ok)
        CHECK_MSG(0, "cannot write %s", path);
    return ok ? 0 : -1;
}

/* check_write_file of dir/name, its path left in path[0 .. size-1]: text's
 * first n bytes, or with n 0 all of it up to its NUL. */
static inline int check_write_in(char *path, size_t size, const char *dir, const char *name,
                                 const char *text, size_t n)
{
    snprintf(path, size, "%s/%s", dir, name);
    return check_write_file(path, text, n ? n : strlen(text));
}

/* Whether path is a plain file holding exactly data[0 .. n-1] whose
 * permissions are mode, or with mode -1 those a new file is given (0666
 * less the umask: not mkstemp's 0600). */
static inline int check_file_is(const char *path, const void *data, size_t n, int mode)
{
    struct stat st;
    if (mode < 0) {
        mode_t mask = umask(022);
        umask(mask);
        mode = (int)(0666 & ~mask);
    }
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode) || (size_t)st.st_size != n ||
        (int)(st.st_mode & 0777) != mode)
        return 0;
    FILE *f = fopen(path, "rb");
    unsigned char *buf = malloc(n + 1);
    int same = f && buf && fread(buf, 1, n + 1, f) == n && (n == 0 || memcmp(buf, data, n) == 0);
    free(buf);
    if (f)
        fclose(f);
    return same;
}

/* The number of entries in the directory path but "." and ".." (0 when it
 * cannot be opened). */
static inline int check_count_entries(const char *path)
{
    DIR *d = opendir(path);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL)
        n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    if (d)
        closedir(d);
    return n;
}

static int check_main(int argc, char **argv, const CheckTest *tests, int ntests)
{
    const char *suite = strrchr(argv[0], '/') ? strrchr(argv[0], '/') + 1 : argv[0];
    int passed = 0, failed = 0;
    for (int k = 0; k < ntests; k++) {
        if (argc > 1 && !strstr(tests[k].name, argv[1]))
            continue;
        fflush(stdout);
        pid_t pid = fork();
        if (pid < 0) {
            perror("fork");
            return 2;
        }
        if (pid == 0) {
            alarm(CHECK_TIMEOUT_SECONDS);
            check_failures_ = 0;
#if CHECK_SANITIZED
            size_t held = __sanitizer_get_current_allocated_bytes();
#endif
            tests[k].fn();
            fflush(stdout);
#if CHECK_SANITIZED
            /* _exit skips LeakSanitizer's check at exit: made here, a leak
             * fails the test (the report says where it was allocated).  A
             * test that ends holding no more of the heap than it started
             * with has freed all it allocated (it frees nothing of its
             * parent's), so only the others are checked: a check costs
             * some 28 ms, and most tests free everything. */
            if (__sanitizer_get_current_allocated_bytes() > held && __lsan_do_recoverable_leak_check())
                check_failures_++;
#endif
            _exit(check_failures_ ? 1 : 0);
        }
        int status;
        while (waitpid(pid, &status, 0) < 0)
            ;
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
            passed++;
        } else {
            failed++;
            if (WIFSIGNALED(status))
                printf("FAIL %s: %s: killed by signal %d%s\n", suite, tests[k].name, WTERMSIG(status),
                       WTERMSIG(status) == SIGALRM ? " (timed out)" : "");
            else
                printf("FAIL %s: %s\n", suite, tests[k].name);
        }
    }
    printf("%s: %d passed, %d failed\n", suite, passed, failed);
    return failed ? 1 : 0;
}

#endif
