/*
 * textfile.h - the line-by-line reading shared by the scene reader
 * (scene.c) and the OBJ reader (obj.c): a whole file into memory, a line
 * split into words, a word read as a finite number, and messages that name
 * the file and the line (or, kit_fail, nothing but the reason).
 */
#ifndef KIT_TEXTFILE_H
#define KIT_TEXTFILE_H

#include <stddef.h>

#define TEXT_MAX_LINE   4096                  /* characters, without the newline */
#define TEXT_MAX_BYTES  (64L * 1024 * 1024)   /* a larger file is not a text file we read */
#define TEXT_MAX_WORDS  16                    /* words kept of a line (all are counted) */
#define TEXT_QUOTE_SIZE 44                    /* a word quoted in a message, with its NUL */

/* One line, once split: its words and where it came from. */
typedef struct {
    const char *name;              /* the file's name, for messages */
    int line;                      /* 1-based line number           */
    char *words[TEXT_MAX_WORDS];   /* the first words of the line  */
    int nwords;                    /* all of them, the keyword too  */
} TextLine;

/* The length of the UTF-8 byte-order mark (EF BB BF) that some Windows
 * editors write first in a file, when s[0 .. n-1] begins with one: 3, or
 * 0.  Compilers skip it, and so does every reader of the kit. */
size_t text_bom_length(const char *s, size_t n);

/* Writes "name:line: message" (or "name: message" when line is 0) into err.
 * Returns -1 for the caller to pass on; a NULL err or errlen 0 writes
 * nothing. */
int text_error(char *err, size_t errlen, const char *name, int line, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/* Writes the message alone into err, for the kit's other modules (no file
 * and line to name).  Returns -1 for the caller to pass on; a NULL err or
 * errlen 0 writes nothing. */
int kit_fail(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Copies word into buf (TEXT_QUOTE_SIZE bytes) for a message: at most 40
 * characters, "..." after a cut, '?' for a byte that is not printable
 * ASCII.  Returns buf. */
const char *text_quote(const char *word, char *buf);

/* Splits buf (one line, NUL-terminated, modified in place) into words,
 * dropping everything from '#' on; stores the first TEXT_MAX_WORDS in
 * words.  Returns how many words there are in all. */
int text_split(char *buf, char **words);

/* Reads word k (k >= 1) of the line as a finite number into *value.
 * Returns 0, or -1 with a message "name:line: KEYWORD: 'word' is ..." when
 * it is not a number, has trailing characters, is NaN or infinite, or
 * overflows. */
int text_number(const TextLine *ln, int k, double *value, char *err, size_t errlen);

/* Reads the whole file at path into a fresh NUL-terminated buffer *text.
 * Returns 0, or -1 with "path: reason" or "path:line: reason" in err (it
 * cannot be opened, is a directory, is larger than TEXT_MAX_BYTES, holds a
 * NUL byte, or memory runs out); *text is then NULL. */
int text_read_file(const char *path, char **text, char *err, size_t errlen);

/* Walks text line by line: *pos is where the next line starts (set it to
 * text first).  Copies the line, cut at '#' and split, into buf (at least
 * TEXT_MAX_LINE + 1 bytes) and ln.  Returns 1 for a line, 0 at the end, -1
 * with a message for a line longer than TEXT_MAX_LINE.  A byte-order mark
 * (EF BB BF) before the first line is skipped. */
int text_next_line(const char **pos, char *buf, TextLine *ln, char *err, size_t errlen);

#endif
