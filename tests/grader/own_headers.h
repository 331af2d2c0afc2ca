/*
 * own_headers.h - headers a stage file includes that the grader's build of
 * it will not have.
 *
 * The grader copies each stage file alone into a folder of its own, beside
 * the kit's raytracer.h and vec3.h, and compiles it there: a header of the
 * student's own (#include "myvec.h"), or one of the kit's other files
 * (#include "kit/scene.h"), is not there, though make render, compiling the
 * file where it lies with -Ilabs, finds it.  This names such headers, so
 * that make render refuses what the grader would not build
 * (stagecheck_main.c), and the grader says why a build failed (build.c).
 */
#ifndef OWN_HEADERS_H
#define OWN_HEADERS_H

#include <stddef.h>

/* Writes into out (of size outlen) one line for each name that the C
 * source text[0 .. len-1] includes (the names include_scan.h reads) which
 * is a regular file in one of the folders dirs[0 .. ndirs-1] and is not
 * raytracer.h or vec3.h: "FILE:LINE: #include "NAME": the grader will not
 * have NAME" (at most three, then how many more), and then one sentence on
 * what to do.  Returns how many names it found (0: out is ""). */
int own_headers_explain(const char *text, size_t len, const char *const *dirs, int ndirs,
                        const char *file, char *out, size_t outlen);

#endif
