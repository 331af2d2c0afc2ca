/*
 * fuzz.h - what the kit's fuzz targets (tests/fuzz/fuzz_*.c) share.  Each
 * target feeds one reader of untrusted or hand-written input the bytes
 * libFuzzer makes up; the sanitizers report what goes wrong.  Built and run
 * by `make fuzz` (tests/fuzz/run.sh) with clang's libFuzzer; every reader
 * must refuse what it cannot read with a message, never crash, overflow or
 * do anything undefined.
 */
#ifndef FUZZ_H
#define FUZZ_H

#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp) */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The input as a string: a copy with a NUL after it (free it). */
static inline char *fuzz_text(const uint8_t *data, size_t size)
{
    char *s = malloc(size + 1);
    if (!s)
        abort();
    if (size)
        memcpy(s, data, size);
    s[size] = '\0';
    return s;
}

/* The input written to a file named name in a directory of this process's
 * own (made once, under TMPDIR: run.sh points it into FUZZ_OUT and clears
 * it); returns its path, the same each call. */
static inline const char *fuzz_file(const uint8_t *data, size_t size, const char *name)
{
    static char dir[256], path[512];
    if (!dir[0]) {
        const char *tmp = getenv("TMPDIR");
        snprintf(dir, sizeof dir, "%s/kitfuzz.XXXXXX", tmp && *tmp ? tmp : "/tmp");
        if (!mkdtemp(dir))
            abort();
    }
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0)
        abort();
    return path;
}

#endif
