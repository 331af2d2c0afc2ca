/*
 * ccmemo_util.h - what the compile memo's two ways of finding an entry
 * share (tests/tools/ccmemo_main.c, ccmemo_direct.c).
 */
#ifndef CCMEMO_UTIL_H
#define CCMEMO_UTIL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* FNV-1a over n bytes, from h (14695981039346656037 to start): an entry's
 * name.  Entries are compared whole, never by their name alone. */
uint64_t ccmemo_fnv1a(const char *s, size_t n, uint64_t h);

/* Writes all len bytes to fd; 0, or -1. */
int ccmemo_write_all(int fd, const char *buf, size_t len);

/* Runs argv (argv[0] a path) with stdout to out_fd and stderr to err_fd
 * (-1: ours); its exit status, or -1. */
int ccmemo_run(char **argv, int out_fd, int err_fd);

/* All of fd in a malloc'd buffer with a NUL after it (*len set); NULL past
 * max bytes, on an error or out of memory. */
char *ccmemo_slurp_fd(int fd, size_t max, size_t *len);

/* Whether the file "key" of the entry directory holds key, compared whole
 * (max: the largest key read). */
bool ccmemo_same_key(const char *entry, const char *key, size_t keylen, size_t max);

/* Serves an entry: its file "object" copied to obj, all or nothing, and its
 * file "messages" written to stderr (and handed back in *messages,
 * malloc'd, with *mlen, when messages is not NULL).  0, or -1 with nothing
 * written. */
int ccmemo_serve(const char *entry, const char *obj, size_t max, char **messages, size_t *mlen);

#endif
