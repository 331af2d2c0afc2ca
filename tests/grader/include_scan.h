/*
 * include_scan.h - the files a stage file names to the preprocessor, looked
 * at before the compiler runs.
 *
 * A stage file needs only raytracer.h, vec3.h and the system's headers.
 * One that names a device (#include "/dev/zero"), a pipe or a directory
 * would make the compiler read forever or wait forever; such a file is
 * refused here, quickly, with a clear message.  The scan reads literal names
 * only: one built by a macro (#define F "/dev/zero" / #include F) reaches the
 * compiler, and the compiler's own limits (memory, CPU time, wall clock,
 * file size: build.c) stop it.  Kept apart from build.c so that other
 * checks of the same names can share the one scan.
 */
#ifndef INCLUDE_SCAN_H
#define INCLUDE_SCAN_H

#include <stdbool.h>
#include <stddef.h>

/* Scans the C source text[0 .. len-1], which will be compiled in directory
 * dir.  Looks at every name in #include, #include_next, #import, #embed,
 * __has_include, __has_embed and #pragma GCC dependency (also through
 * _Pragma), after trigraphs, line splices and comments are dealt with as the
 * compiler does.  Returns 0 when every name is acceptable, or 1 with a
 * one-line reason in why: a name with a ".." component, an absolute name
 * under /dev, /proc or /sys, a name that resolves (from dir when relative,
 * following symbolic links) to one of those outside dir or to anything but
 * a regular file, or the assembler's .incbin anywhere in the code.  dir
 * itself may be anywhere, /dev/shm too. */
int include_scan(const char *text, size_t len, const char *dir, char *why, size_t whylen);

/* The same, with one more judgement of each name: judge(name, ctx) returns
 * NULL to accept it, or the reason to refuse it ("which is part of the
 * grader"), said the same way. */
typedef const char *(*IncludeJudge)(const char *name, void *ctx);
int include_scan_judged(const char *text, size_t len, const char *dir, IncludeJudge judge, void *ctx,
                        char *why, size_t whylen);

/* True when path is dir or under it, component by component ("/a/bc" is
 * not under "/a/b"); both as realpath gives them. */
bool path_below(const char *path, const char *dir);

#endif
