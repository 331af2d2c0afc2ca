/*
 * memo.c - see memo.h.  An entry is the directory
 * MEMO/<stage>-<kind>-<FNV-1a of the bytes>-<k>, holding the file's bytes
 * ("source") and what was kept of its build; k counts files whose bytes
 * differ but share the hash, which only the whole comparison tells apart.
 * The grading that made an entry compiles its file; one that finds it
 * waits for that (memo_wait), so a file is compiled once even when two
 * gradings reach it at the same time.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "memo.h"
#include "build.h"
#include "kit/savefile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define MEMO_FILE_MAX (64 << 20)    /* an object or a shared object           */
#define MEMO_CHAIN 64               /* files of one stage sharing a hash      */

/* Writes len bytes as name in dir, all or nothing (kit_save_file). */
static int put(const char *dir, const char *name, const char *bytes, size_t len)
{
    char path[1200], err[64];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return kit_save_file(path, bytes, len, err, sizeof err);
}

/* Removes a new entry that was not taken: its bytes, then itself. */
static void discard(const char *fresh)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/source", fresh);
    unlink(path);
    rmdir(fresh);
}

bool memo_find(const char *memo, const char *stage, const char *kind, const char *src, MemoEntry *e)
{
    e->dir[0] = '\0';
    e->found = false;
    if (!memo || !*memo)
        return false;
    size_t len = 0;
    char *bytes = kit_load_file(src, BUILD_SOURCE_MAX, &len);
    if (!bytes)
        return false;
    uint64_t h = 14695981039346656037u;
    for (size_t i = 0; i < len; i++) {
        h ^= (unsigned char)bytes[i];
        h *= 1099511628211u;
    }
    /* An entry that is there has its bytes: a new one is made under a name
     * of its own, its bytes written, and only then renamed into place, so
     * two gradings of the same file at the same time share one entry. */
    char fresh[1100] = "";
    bool taken = false, again = false;
    for (int k = 0; k < MEMO_CHAIN && !taken; k++) {
        snprintf(e->dir, sizeof e->dir, "%s/%s-%s-%016llx-%d", memo, stage, kind, (unsigned long long)h, k);
        char path[1200];
        size_t kept_len = 0;
        snprintf(path, sizeof path, "%s/source", e->dir);
        char *kept = kit_load_file(path, BUILD_SOURCE_MAX, &kept_len);
        if (kept) {
            again = false;
            e->found = kept_len == len && memcmp(kept, bytes, len) == 0;
            free(kept);
            if (e->found)
                break;
            continue;                   /* another file with the same hash */
        }
        if (!fresh[0]) {
            snprintf(fresh, sizeof fresh, "%s/.new-XXXXXX", memo);
            if (!mkdtemp(fresh) || put(fresh, "source", bytes, len) != 0)
                break;
        }
        if (rename(fresh, e->dir) == 0)
            taken = true;               /* a new entry, empty but for the bytes */
        else if ((errno == EEXIST || errno == ENOTEMPTY) && !again)
            k--, again = true;          /* made just now beside this one: compare */
        else if (errno != EEXIST && errno != ENOTEMPTY)
            break;
        else
            again = false;              /* there, but not readable: the next one */
    }
    if (fresh[0] && !taken)
        discard(fresh);
    free(bytes);
    if (!taken && !e->found)
        e->dir[0] = '\0';
    return taken || e->found;
}

bool memo_wait(const MemoEntry *e, double seconds)
{
    char object[1200], done[1200];
    memo_path(e, "object.o", object, sizeof object);
    memo_path(e, "done", done, sizeof done);
    long pause_ns = 1000000;            /* a long holds 16 ms, not the whole wait */
    double waited = 0;
    while (e->dir[0]) {
        if (access(object, F_OK) == 0)
            return true;
        if (access(done, F_OK) == 0 || waited >= seconds)
            return false;
        struct timespec pause = { 0, pause_ns };
        nanosleep(&pause, NULL);
        waited += pause_ns * 1e-9;
        if (pause_ns < 16000000)
            pause_ns *= 2;
    }
    return false;
}

void memo_path(const MemoEntry *e, const char *name, char *path, size_t len)
{
    snprintf(path, len, "%s/%s", e->dir, name);
}

int memo_keep(const MemoEntry *e, const char *name, const char *file)
{
    if (!e->dir[0])
        return -1;
    size_t len = 0;
    char *bytes = kit_load_file(file, MEMO_FILE_MAX, &len);
    if (!bytes)
        return -1;
    int status = put(e->dir, name, bytes, len);
    free(bytes);
    return status;
}

int memo_keep_text(const MemoEntry *e, const char *name, const char *text)
{
    return e->dir[0] ? put(e->dir, name, text, strlen(text)) : -1;
}

void memo_use(const MemoEntry *e)
{
    char path[1200];
    memo_path(e, "uses", path, sizeof path);
    FILE *f = e->dir[0] ? fopen(path, "ab") : NULL;
    if (f) {
        fputc('+', f);
        fclose(f);
        utimensat(AT_FDCWD, e->dir, NULL, 0);   /* a kept memo prunes by it */
    }
}

char *memo_read_text(const MemoEntry *e, const char *name)
{
    char path[1200];
    size_t len = 0;
    memo_path(e, name, path, sizeof path);
    return e->dir[0] ? kit_load_file(path, MEMO_FILE_MAX, &len) : NULL;
}
