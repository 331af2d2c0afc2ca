/*
 * init_sh - /bin/sh as the grader's runners start (harness_init.h): the
 * sandbox's unit test (test_sandbox.c) runs its shell scripts through it,
 * so that in the namespace jail the script is not its PID namespace's
 * first process (whose own signals, and its limits' signals, would not
 * end it), as a test's program is not.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "../grader/harness_init.h"

int main(int argc, char **argv)
{
    (void)argc;
    harness_init();
    argv[0] = "/bin/sh";
    execv(argv[0], argv);
    return 127;
}
