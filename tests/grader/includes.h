/*
 * includes.h - the files a C source names in its #include directives, found
 * before the compiler runs, so that the grader can refuse an include of its
 * own files whether or not the compiler could read them.
 *
 * Only literal names are found ("name" and <name>); an include through a
 * macro is seen after compiling, in the compiler's list of dependencies.
 */
#ifndef INCLUDES_H
#define INCLUDES_H

#include <stdbool.h>
#include <stddef.h>

/* Called for each literal include, in order; a nonzero return stops the
 * scan.  angled is true for <name>. */
typedef int (*IncludeVisit)(const char *name, bool angled, void *ctx);

/* Scans len bytes of C source.  Returns the number of includes visited,
 * or -1 when out of memory. */
int includes_scan(const char *src, size_t len, IncludeVisit visit, void *ctx);

#endif
