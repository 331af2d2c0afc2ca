/*
 * lookalike.h - characters that look like C's but are not, found in a
 * stage file that did not compile: what code copied from a web page, a PDF
 * or a word processor brings (a non-breaking space, curly quotes, a minus
 * sign, a multiplication sign...).  The compiler says only "stray '\302'
 * in program" or "unexpected character <U+201C>"; this names the
 * character, its line, and what to type instead.
 */
#ifndef LOOKALIKE_H
#define LOOKALIKE_H

#include <stdbool.h>
#include <stddef.h>

/* What comes before lookalike_explain's lines, and after a file's name
 * when it is UTF-16: the grader (build.c) and make render (lookalike_main.c)
 * say the same. */
#define LOOKALIKE_INTRO "The file has characters that look like C's but are not (code copied " \
                        "from a web page, a PDF or a word processor brings them):"
#define LOOKALIKE_UTF16 "is saved as UTF-16 (what some Windows editors call \"Unicode\"), " \
                        "which C compilers do not read: save it as UTF-8"

/* Writes into out (of size outlen) one line per lookalike character that
 * text[0 .. len-1] has outside comments and string or character literals,
 * "FILE:LINE: what it is (U+XXXX): type what instead", with ", N times"
 * when it is there more than once on the line: at most three such lines,
 * then how many more characters.  Returns how many characters it found
 * (0: out is ""). */
int lookalike_explain(const char *text, size_t len, const char *file, char *out, size_t outlen);

/* Whether the n bytes of text are UTF-16 (what some Windows editors save
 * as "Unicode"): a byte-order mark FF FE or FE FF, or, without one, every
 * other byte of the first 512 a 0, as in ASCII text so saved. */
bool lookalike_utf16(const char *text, size_t n);

#endif
