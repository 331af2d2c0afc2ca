/*
 * terminal.h - text the student chose, written so that a terminal shows it
 * and obeys none of it.
 *
 * What a student's code printed, the compiler's words about it, a
 * submission folder's name and the files' names in a class's download are
 * the students' to choose, escape sequences and all (which set the
 * window's title, write the clipboard, move the cursor...).  Here a
 * control character other than newline and tab is shown as ^X (ESC as ^[,
 * DEL as ^?), and a C1 control (U+0080 to U+009F, which some terminals
 * obey too), or a stretch of bytes that is not valid UTF-8 (each maximal
 * subpart, tests/tools/utf8.h), as '?'.
 */
#ifndef GRADER_TERMINAL_H
#define GRADER_TERMINAL_H

#include <stddef.h>
#include <stdio.h>

/* Writes the n bytes at text to f, so shown. */
void term_put(FILE *f, const char *text, size_t n);

/* Appends the string text, so shown, to the string in buf (size bytes):
 * as many whole characters as fit. */
void term_append(char *buf, size_t size, const char *text);

#endif
