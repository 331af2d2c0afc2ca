/*
 * ccmemo_util.c - hashing, writing, running and reading for the compile
 * memo (ccmemo_util.h).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include "ccmemo_util.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "kit/savefile.h"

uint64_t ccmemo_fnv1a(const char *s, size_t n, uint64_t h)
{
    for (size_t i = 0; i < n; i++) {
        h ^= (unsigned char)s[i];
        h *= 1099511628211u;
    }
    return h;
}

int ccmemo_write_all(int fd, const char *buf, size_t len)
{
    while (len > 0) {
        ssize_t w = write(fd, buf, len);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        buf += w;
        len -= (size_t)w;
    }
    return 0;
}

int ccmemo_run(char **argv, int out_fd, int err_fd)
{
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if ((out_fd >= 0 && dup2(out_fd, 1) < 0) || (err_fd >= 0 && dup2(err_fd, 2) < 0))
            _exit(127);
        execv(argv[0], argv);
        _exit(127);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

char *ccmemo_slurp_fd(int fd, size_t max, size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap + 1);
    if (!buf)
        return NULL;
    for (;;) {
        if (n == cap) {
            if (cap >= max) {
                free(buf);
                return NULL;
            }
            char *b = realloc(buf, (cap *= 2) + 1);
            if (!b) {
                free(buf);
                return NULL;
            }
            buf = b;
        }
        ssize_t r = read(fd, buf + n, cap - n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            free(buf);
            return NULL;
        }
        if (r == 0)
            break;
        n += (size_t)r;
    }
    buf[n] = '\0';
    *len = n;
    return buf;
}

bool ccmemo_same_key(const char *entry, const char *key, size_t keylen, size_t max)
{
    char path[4200];
    size_t n;
    snprintf(path, sizeof path, "%s/key", entry);
    char *kept = kit_load_file(path, max, &n);
    bool same = kept && n == keylen && memcmp(kept, key, n) == 0;
    free(kept);
    return same;
}

int ccmemo_serve(const char *entry, const char *obj, size_t max, char **messages, size_t *mlen)
{
    char path[4200], err[64];
    size_t n;
    snprintf(path, sizeof path, "%s/object", entry);
    char *o = kit_load_file(path, max, &n);
    int bad = !o || kit_save_file(obj, o, n, err, sizeof err) != 0;
    free(o);
    if (bad)
        return -1;
    snprintf(path, sizeof path, "%s/messages", entry);
    char *m = kit_load_file(path, max, &n);
    if (m)
        ccmemo_write_all(2, m, n);
    if (messages) {
        *messages = m;
        *mlen = m ? n : 0;
    } else {
        free(m);
    }
    return 0;
}
