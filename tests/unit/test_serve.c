/*
 * The grader's server of tests (sandbox_serve_run in tests/grader/sandbox.c,
 * harness_serve.c) on small shell programs.  This program is its own
 * server: `test_serve --serve sh:SCRIPT` serves, each child then running
 * /bin/sh -c SCRIPT, and `test_serve sh:SCRIPT` is the runner the grader
 * starts itself when the server fails.  A script tells who started it by
 * its $PPID: the server, or the grader (this process).
 * Checked: results as a runner of its own gives them (answers, output,
 * exit status, signal, time out, output stop, CPU), the test's limits and
 * descriptors, and that a test that kills or stops the server, or a server
 * gone between tests, costs no test its verdict.  Linux only, as the
 * servers are (the prebuilt runners).
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include <stdbool.h>
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <time.h>
#include "../grader/sandbox.h"
#if defined(__linux__)
#include "../grader/harness_serve.h"

static char self[4096];
static char dir[512];

/* Readies a server of this program for script (not started yet). */
static void serve_init(SandboxServer *s, char *object, size_t size, const char *script)
{
    snprintf(object, size, "sh:%s", script);
    sandbox_serve_init(s, self, object, 0);
}

/* One run of s's script with spec's limits; 0 if it ran. */
static int run(SandboxServer *s, SandboxSpec spec, SandboxResult *res)
{
    spec.workdir = dir;
    if (!spec.timeout)
        spec.timeout = 10;
    spec.answer_max = 4096;
    spec.output_max = 4096;
    char err[256];
    int rc = sandbox_serve_run(s, &spec, res, err, sizeof err);
    CHECK_MSG(rc == 0, "sandbox_serve_run: %s", err);
    return rc;
}

/* Whether the run's answer says "ppid P" with P parent: the server's pid
 * for a served run, this process's for a runner the grader started. */
static bool started_by(const SandboxResult *res, pid_t parent)
{
    long ppid = -1;
    const char *at = strstr(res->answer, "ppid ");
    return at && sscanf(at, "ppid %ld", &ppid) == 1 && ppid == (long)parent;
}

#define PPID "echo \"ppid $PPID\" >&3; "

/* Two runs, each in a fresh child of one server: answers, output, exit. */
static void test_served_runs(void)
{
    SandboxServer s;
    char object[256];
    serve_init(&s, object, sizeof object, PPID "echo out; echo $$ >&3; exit 3");
    SandboxResult a, b;
    SandboxSpec spec = { .max_procs = 0 };
    if (run(&s, spec, &a) != 0)
        return;
    pid_t server = s.pid;
    CHECK(server > 0);
    CHECK(started_by(&a, server));
    CHECK_EQ_INT(a.exit_code, 3);
    CHECK_STR_CONTAINS(a.output, "out");
    if (run(&s, spec, &b) == 0) {
        CHECK(started_by(&b, server));
        CHECK_MSG(strcmp(a.answer, b.answer) != 0, "one process for two runs: %s", a.answer);
        CHECK(s.pid == server && !s.failed);
        sandbox_result_free(&b);
    }
    sandbox_result_free(&a);
    sandbox_serve_stop(&s);
    CHECK_MSG(kill(server, 0) != 0 && errno == ESRCH, "the server %ld is still there", (long)server);
}

/* The test's limits, set in the child: CPU, files, memory, and no new
 * process (a subshell is a fork, and fails). */
static void test_served_limits(void)
{
    SandboxServer s;
    char object[256];
    serve_init(&s, object, sizeof object,
               PPID "for o in t f v; do printf '%s ' $o; ulimit -$o; done >&3; "
               "(echo forked >&3) 2>/dev/null; :");
    SandboxResult res;
    SandboxSpec spec = { .max_procs = 0, .cpu_seconds = 7, .address_mb = 512, .max_file_mb = 0 };
    if (run(&s, spec, &res) != 0)
        return;
    CHECK(started_by(&res, s.pid));
    CHECK_STR_CONTAINS(res.answer, "t 7\nf 0\nv 524288\n");
    CHECK_MSG(!strstr(res.answer, "forked"), "the child could fork: %s", res.answer);
    sandbox_result_free(&res);
    sandbox_serve_stop(&s);
}

/* A served child has the test's descriptors and no other, the server's
 * socket included. */
static void test_served_descriptors(void)
{
    SandboxServer s;
    char object[256];
    serve_init(&s, object, sizeof object,
               PPID "for n in 4 5 6 7 8 9 10 11; do (: <&$n) 2>/dev/null && echo \"open $n\" >&3; done; "
               "echo checked >&3");
    SandboxResult res;
    SandboxSpec spec = { .max_procs = -1 };
    if (run(&s, spec, &res) != 0)
        return;
    CHECK(started_by(&res, s.pid));
    CHECK_STR_CONTAINS(res.answer, "checked");
    CHECK_MSG(!strstr(res.answer, "open"), "the child kept descriptors: %s", res.answer);
    sandbox_result_free(&res);
    sandbox_serve_stop(&s);
}

/* The served script of test_served_endings: it says its CPU limit, soft
 * and hard, then spins until it is stopped, or, asked on its input, sends
 * itself the CPU limit's signal.  A spin the system's limit stops costs a
 * whole CPU-second (the limit is counted in seconds); test_sandbox's
 * test_cpu_limit spins so once, and a served child's limit is the same
 * system's. */
#define SPIN CHECK_SAY_CPU_LIMIT "read how; [ \"$how\" != xcpu ] || kill -XCPU $$; while :; do :; done"

/* Out of time, crashed, over its output, out of CPU: each reported as a
 * runner of its own reports it, and the server serves on. */
static void test_served_endings(void)
{
    SandboxServer s;
    char object[256];
    SandboxResult res;
    serve_init(&s, object, sizeof object, SPIN);
    SandboxSpec spec = { .max_procs = 0, .timeout = 0.15 };       /* spent spinning: kept short */
    if (run(&s, spec, &res) == 0) {
        CHECK(res.timed_out);
        CHECK_EQ_INT(res.exit_code, -1);
        CHECK_MSG(res.seconds < 1.5, "stopped after %.2f s", res.seconds);
        CHECK_MSG(res.cpu_seconds > 0.01, "the child's CPU: %.3f s", res.cpu_seconds);
        sandbox_result_free(&res);
    }
    spec = (SandboxSpec){ .max_procs = 0, .cpu_seconds = 1, .timeout = 10, .input = "xcpu\n", .input_len = 5 };
    pid_t server = s.pid;
    if (run(&s, spec, &res) == 0) {
        CHECK_STR_CONTAINS(res.answer, "limit 1\nhard 1\n");
        CHECK_MSG(res.signal == SIGXCPU || res.signal == SIGKILL, "signal %d", res.signal);
        sandbox_result_free(&res);
    }
    CHECK(s.pid == server && !s.failed);
    sandbox_serve_stop(&s);

    serve_init(&s, object, sizeof object, "echo started >&3; kill -SEGV $$");
    if (run(&s, (SandboxSpec){ .max_procs = 0 }, &res) == 0) {
        CHECK_EQ_INT(res.signal, SIGSEGV);
        CHECK_STR_CONTAINS(res.answer, "started");
        sandbox_result_free(&res);
    }
    sandbox_serve_stop(&s);

    serve_init(&s, object, sizeof object, "while :; do echo spam spam spam spam spam spam; done");
    spec = (SandboxSpec){ .max_procs = 0, .output_stop = 256 << 10, .timeout = 5 };
    if (run(&s, spec, &res) == 0) {
        CHECK(res.output_exceeded);
        CHECK(!res.timed_out);
        CHECK_STR_CONTAINS(res.output, "spam");
        sandbox_result_free(&res);
    }
    CHECK(!s.failed);
    sandbox_serve_stop(&s);
}

/* Over memory_mb, the grader's watch stops a served child too (it reads
 * the child's memory, though the child is the server's and cannot be
 * traced), with the address space left wide open.  The limit is low, as
 * test_sandbox's hogs' (HOG_MB): the hog spins until it is stopped. */
static void test_served_memory(void)
{
    SandboxServer s;
    char object[256];
    serve_init(&s, object, sizeof object,
               "x=0123456789abcdef; while [ ${#x} -lt 134217728 ]; do x=$x$x; done; sleep 10");
    SandboxResult res;
    SandboxSpec spec = { .memory_mb = 16, .address_mb = 2048, .max_procs = 0 };
    if (run(&s, spec, &res) != 0)
        return;
    CHECK_MSG(res.memory_exceeded, "not stopped for memory: exit %d, signal %d, timed out %d, %.2f s",
              res.exit_code, res.signal, res.timed_out, res.seconds);
    CHECK_MSG(res.seconds < 5, "stopped after %.2f s", res.seconds);
    CHECK(s.pid > 0 && !s.failed);
    sandbox_result_free(&res);
    sandbox_serve_stop(&s);
}

/* A test that kills the server, or stops it, runs again in a runner the
 * grader starts, and so does every later test; the verdict is that run's.
 * The grader notices at once, not at the end of the test's time. */
static void test_server_attacked(void)
{
    /* Only the server: run by the grader, the script's parent is the
     * grader, which it could signal too when the grader is not root (as
     * any test could: the sandbox then runs tests as the grader's user). */
    const char *signals[] = { "KILL", "STOP" };
    for (int k = 0; k < 2; k++) {
        SandboxServer s;
        char object[256], script[200];
        snprintf(script, sizeof script, "[ $PPID = %ld ] || kill -%s $PPID; " PPID "exit 5",
                 (long)getpid(), signals[k]);
        serve_init(&s, object, sizeof object, script);
        SandboxResult res;
        double start = sandbox_now();
        if (run(&s, (SandboxSpec){ .max_procs = 0, .timeout = 5 }, &res) != 0)
            return;
        double took = sandbox_now() - start;
        CHECK_MSG(took < 2, "%s: noticed after %.2f s", script, took);
        CHECK_MSG(started_by(&res, getpid()), "%s: the verdict's run: %s", script, res.answer);
        CHECK_EQ_INT(res.exit_code, 5);
        CHECK(s.failed && s.off && s.pid == 0);
        sandbox_result_free(&res);
        if (run(&s, (SandboxSpec){ .max_procs = 0 }, &res) == 0) {
            CHECK(started_by(&res, getpid()));
            sandbox_result_free(&res);
        }
        sandbox_serve_stop(&s);
    }
}

/* A word to stop a test that reaches the server after the test has ended
 * (it ended at its deadline, say) is ignored, even when it arrives with
 * the next test's request: that test still gets its own limits, from the
 * same server.  (The server is stopped while both are sent, so that it
 * reads them together.) */
static void test_late_kill(void)
{
    SandboxServer s;
    char object[256];
    serve_init(&s, object, sizeof object, PPID "for o in t v; do printf '%s ' $o; ulimit -$o; done >&3");
    SandboxResult res;
    SandboxSpec spec = { .max_procs = 0, .cpu_seconds = 7, .address_mb = 512 };
    if (run(&s, spec, &res) != 0)
        return;
    sandbox_result_free(&res);
    pid_t server = s.pid;
    kill(server, SIGSTOP);
    char k = 'k';
    CHECK(write(s.sock, &k, 1) == 1);
    pid_t helper = fork();
    if (helper == 0) {
        struct timespec wait = { 0, 300 * 1000 * 1000 };
        nanosleep(&wait, NULL);
        kill(server, SIGCONT);
        _exit(0);
    }
    if (run(&s, spec, &res) == 0) {
        CHECK_MSG(s.pid == server && !s.failed, "the server %s", s.failed ? "failed" : "changed");
        CHECK(started_by(&res, server));
        CHECK_STR_CONTAINS(res.answer, "t 7\nv 524288\n");
        sandbox_result_free(&res);
    }
    waitpid(helper, NULL, 0);
    sandbox_serve_stop(&s);
}

/* A server gone between two tests: the second runs in a runner of its own. */
static void test_server_gone(void)
{
    SandboxServer s;
    char object[256];
    serve_init(&s, object, sizeof object, PPID "exit 0");
    SandboxResult res;
    if (run(&s, (SandboxSpec){ .max_procs = 0 }, &res) != 0)
        return;
    CHECK(started_by(&res, s.pid));
    sandbox_result_free(&res);
    kill(s.pid, SIGKILL);
    if (run(&s, (SandboxSpec){ .max_procs = 0 }, &res) == 0) {
        CHECK(started_by(&res, getpid()));
        CHECK_EQ_INT(res.exit_code, 0);
        CHECK(s.failed);
        sandbox_result_free(&res);
    }
    sandbox_serve_stop(&s);
}

/* Turned off, it never starts a server; told to start at the third run,
 * the first two start a runner each. */
static void test_server_off(void)
{
    SandboxServer s;
    char object[256];
    snprintf(object, sizeof object, "sh:" PPID "exit 0");
    sandbox_serve_init(&s, self, object, -1);
    SandboxResult res;
    for (int k = 0; k < 3; k++) {
        if (run(&s, (SandboxSpec){ .max_procs = 0 }, &res) != 0)
            return;
        CHECK(started_by(&res, getpid()));
        CHECK(s.pid == 0 && !s.failed);
        sandbox_result_free(&res);
    }
    sandbox_serve_stop(&s);
    sandbox_serve_init(&s, self, object, 2);
    for (int k = 0; k < 4; k++) {
        if (run(&s, (SandboxSpec){ .max_procs = 0 }, &res) != 0)
            return;
        CHECK_MSG(started_by(&res, k < 2 ? getpid() : s.pid), "run %d: %s", k, res.answer);
        CHECK_MSG((s.pid != 0) == (k >= 2), "run %d: server %ld", k, (long)s.pid);
        sandbox_result_free(&res);
    }
    sandbox_serve_stop(&s);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_served_runs),    CHECK_TEST(test_served_limits), CHECK_TEST(test_served_descriptors),
    CHECK_TEST(test_served_endings), CHECK_TEST(test_served_memory), CHECK_TEST(test_server_attacked),
    CHECK_TEST(test_late_kill),      CHECK_TEST(test_server_gone),    CHECK_TEST(test_server_off),
};

int main(int argc, char **argv)
{
    /* The server, and the runner started instead of it. */
    if (argc == 3 && strcmp(argv[1], "--serve") == 0 && strncmp(argv[2], "sh:", 3) == 0) {
        harness_serve(3);
        execl("/bin/sh", "sh", "-c", argv[2] + 3, (char *)NULL);
        _exit(127);
    }
    if (argc == 2 && strncmp(argv[1], "sh:", 3) == 0) {
        execl("/bin/sh", "sh", "-c", argv[1] + 3, (char *)NULL);
        _exit(127);
    }
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);    /* portable: __linux__ */
    if (n <= 0) {
        fprintf(stderr, "test_serve: cannot find its own program\n");
        return 2;
    }
    self[n] = '\0';
    if (check_temp_dir(dir, sizeof dir, "serve") != 0)
        return 2;
    chmod(dir, 0755);
    sandbox_give(dir);
    int status = check_main(argc, argv, tests, CHECK_COUNT(tests));
    if (check_remove_tree(dir) != 0)
        printf("    (could not remove %s)\n", dir);
    return status;
}
#else
static void test_skipped(void)
{
    printf("    skipped: servers of tests are Linux's, as the prebuilt runners are\n");
}

static const CheckTest tests[] = { CHECK_TEST(test_skipped) };

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
#endif
