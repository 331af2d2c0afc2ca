/*
 * utf8.h - reading UTF-8 (RFC 3629; the Unicode Standard, chapter 3,
 * table 3-7), for every writer and reader of the kit's that takes text
 * it did not write: JSON, the report page, the terminal, the lookalike scan.
 */
#ifndef TOOLS_UTF8_H
#define TOOLS_UTF8_H

#include <stddef.h>

/* The sequence that starts s[0 .. n-1], whose first byte is 0x80 or more:
 * its length (2 to 4) when it is well formed (no overlong forms, no
 * surrogates, nothing past U+10FFFF); when it is not, minus the length of
 * its longest start that could begin a well-formed sequence (1 to 3: the
 * bytes one U+FFFD replaces, the Standard's "maximal subpart"). */
int utf8_sequence(const unsigned char *s, size_t n);

/* The code point of the well-formed sequence of len bytes (2 to 4) at s. */
unsigned long utf8_code_point(const unsigned char *s, int len);

#endif
