/*
 * linkmsg.h - what a linker's message says: the functions it finds
 * undefined, or defined twice, in the words of the linkers students'
 * machines have (GNU ld, gold, LLVM's lld, Apple's ld, whose C names carry
 * a leading underscore); and which source defines such a function.
 */
#ifndef LINKMSG_H
#define LINKMSG_H

#include <stdbool.h>

#define LINKMSG_NAME_MAX 128

/* Fills names with the distinct undefined names text gives, in the order
 * it gives them, at most max; returns how many.  Names longer than
 * LINKMSG_NAME_MAX - 1 are passed over. */
int linkmsg_undefined(const char *text, char names[][LINKMSG_NAME_MAX], int max);

/* The same for the names a linker says are defined twice: GNU ld's
 * "multiple definition of `NAME'" (gold's with 'NAME'), lld's "duplicate
 * symbol: NAME" and Apple's "duplicate symbol '_NAME' in:" (older versions
 * without the quotes). */
int linkmsg_duplicate(const char *text, char names[][LINKMSG_NAME_MAX], int max);

/* Whether the C source text defines the function name: the name as a whole
 * word, then its parameters in parentheses, then a body's "{".  Read from
 * the text as written: a definition made by a macro is not seen. */
bool linkmsg_defines(const char *text, const char *name);

#endif
