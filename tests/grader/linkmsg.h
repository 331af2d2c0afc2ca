/*
 * linkmsg.h - the functions a linker's message says are undefined, in the
 * words of the linkers students' machines have: GNU ld ("undefined
 * reference to `NAME'") and gold (the same with 'NAME'), LLVM's lld
 * ("undefined symbol: NAME")
 * and Apple's ld ("\"_NAME\", referenced from:", C names with their
 * leading underscore).
 */
#ifndef LINKMSG_H
#define LINKMSG_H

#define LINKMSG_NAME_MAX 128

/* Fills names with the distinct undefined names text gives, in the order
 * it gives them, at most max; returns how many.  Names longer than
 * LINKMSG_NAME_MAX - 1 are passed over. */
int linkmsg_undefined(const char *text, char names[][LINKMSG_NAME_MAX], int max);

#endif
