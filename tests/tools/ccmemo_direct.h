/*
 * ccmemo_direct.h - the compile memo's direct way: an entry found from the
 * source's bytes and the files its first compile read, without running the
 * preprocessor.
 *
 * The preprocessed key (ccmemo_main.c) costs a run of the compiler, cc -E:
 * about 45 ms of a 50 ms served compile here.  Next to each entry it makes
 * or serves, the memo keeps a direct entry "direct-HASH" whose key is the
 * compiler, the arguments, the environment variables the compiler reads and
 * the source's bytes.  It holds
 *   - every file the preprocessor read (the line markers of cc -E's text),
 *     with its bytes;
 *   - every place the preprocessor looks for a name that one of those files
 *     includes or asks for (__has_include): the file's own directory for a
 *     quoted name, then each directory of the compiler's search list (cc -E
 *     -v); and whether a file was there;
 *   - the object and the messages.
 * It serves a compile only when the key is the same, compared whole, every
 * file read has the same bytes, and every place has a file or none as it
 * had: the preprocessor would then read the same files, so compiling would
 * give the same object.  (A new header that would shadow an old one from an
 * earlier directory is a file where there was none.)  Nothing is kept when
 * a file read uses __DATE__, __TIME__ or __TIMESTAMP__, or includes or asks
 * for a name not written out (#include MACRO).  As for the preprocessed
 * key, no file may change while its compile runs.
 */
#ifndef CCMEMO_DIRECT_H
#define CCMEMO_DIRECT_H

#include <stddef.h>

/* The direct key of a compile: the nargs arguments of args (the real
 * compiler, then every argument but -c and -o OBJ), the environment the
 * compiler reads, and the bytes of the source src.  NULL when there is
 * none: src cannot be read, or the environment asks the compiler to write
 * more than the object (DEPENDENCIES_OUTPUT, SUNPRO_DEPENDENCIES). */
char *direct_key(char *const *args, int nargs, const char *src, size_t *len);

/* Serves the compile from memo's direct entry for key: 0 with its object
 * written to obj and its messages to stderr, or -1 (nothing written). */
int direct_use(const char *memo, const char *key, size_t keylen, const char *obj);

/* Keeps the direct entry for key, from the preprocessed text of the
 * compile (text), its object (the file obj) and its messages; args and
 * nargs as for direct_key, src the source among them.  Best effort: a
 * direct entry that cannot be made is not made. */
void direct_keep(const char *memo, const char *key, size_t keylen, char *const *args, int nargs,
                 const char *src, const char *text, size_t textlen, const char *obj,
                 const char *messages, size_t mlen);

#endif
