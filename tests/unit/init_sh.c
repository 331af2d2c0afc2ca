/*
 * init_sh - /bin/sh as the grader's runners start (harness_init.h): the
 * sandbox's unit test (test_sandbox.c) runs its shell scripts through it,
 * so that in the namespace jail the script is not its PID namespace's
 * first process (whose own signals, and its limits' signals, would not
 * end it), as a test's program is not.  Instead, `init_sh --key NAME`
 * looks for the user key NAME in its session keyring (Linux), and
 * `init_sh --socket` tries to make an Internet socket and a Unix one; each
 * writes on fd 3 what it found.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE         /* syscall, on glibc */
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "../grader/harness_init.h"
#include <stdio.h>
#include <sys/socket.h>
#include <string.h>
#if defined(__linux__)
#include <sys/syscall.h>
#endif

int main(int argc, char **argv)
{
    harness_init();
    if (argc == 3 && strcmp(argv[1], "--key") == 0) {
#if defined(__linux__)
        long id = syscall(SYS_keyctl, 10L, -3L, "user", argv[2], 0L);  /* KEYCTL_SEARCH, the session keyring */
        dprintf(3, id > 0 ? "key found\n" : "key not found: %s\n", strerror(errno));
#endif
        return 0;
    }
    if (argc == 2 && strcmp(argv[1], "--socket") == 0) {
        int inet = socket(AF_INET, SOCK_DGRAM, 0), local = socket(AF_UNIX, SOCK_STREAM, 0);
        dprintf(3, "inet %s, unix %s\n", inet >= 0 ? "made" : "refused", local >= 0 ? "made" : "refused");
        return 0;
    }
    argv[0] = "/bin/sh";
    execv(argv[0], argv);
    return 127;
}
