/*
 * linkmsg.h - what a linker's message says: the functions it finds
 * undefined, or defined twice, in the words of the linkers students'
 * machines have (GNU ld, gold, LLVM's lld, Apple's ld, whose C names carry
 * a leading underscore); which functions a source defines; and which stage
 * file the contract puts each of its functions in.
 */
#ifndef LINKMSG_H
#define LINKMSG_H

#include <stdbool.h>
#include <stddef.h>

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
 * word, then its parameters in parentheses, then a body's "{".  Comments
 * and string literals are passed over, and so are the groups under
 * "#if 0" (up to their #else, #elif or #endif); the rest is read as
 * written: a definition made by a macro is not seen, and one under any
 * other condition is, true or false. */
bool linkmsg_defines(const char *text, const char *name);

/* Fills names with the distinct functions text defines (as
 * linkmsg_defines sees a definition), in the order it defines them, at
 * most max; returns how many. */
int linkmsg_definitions(const char *text, char names[][LINKMSG_NAME_MAX], int max);

/* The same as words, into out: "a, b and c" (the first eight), or "none". */
void linkmsg_definitions_list(const char *text, char *out, size_t n);

/* The stage file, without ".c", that defines name, a function of the
 * contract (labs/raytracer.h); NULL when name is not one. */
const char *linkmsg_stage_of(const char *name);

#endif
