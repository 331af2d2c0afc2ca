/*
 * csv.h - the fields of the kit's CSV files (gradebook.csv, causes.csv),
 * written so that a spreadsheet reads them as text, and read back.
 */
#ifndef CSV_H
#define CSV_H

#include <stdio.h>

/* Writes one field, quoted when it holds a comma or a quote.  A field
 * that starts with =, +, -, @, a tab or a carriage return is written after
 * an apostrophe, quoted: a spreadsheet would otherwise take a folder named
 * "=HYPERLINK(...)" for a formula (OWASP's advice on CSV injection).
 * Control bytes (a line break, an escape that would drive the terminal
 * that shows the file) and the backslash are written \xHH. */
void csv_field(FILE *f, const char *s);

/* Reads the field at *p (a line of text as csv_field writes them) into a
 * fresh string, undoing the quotes, the \xHH and the apostrophe csv_field
 * puts before a formula's first character; moves *p past the field and its
 * comma.  *end is set when the field ended the line (or the text).  NULL
 * when memory runs out. */
char *csv_read_field(const char **p, int *end);

#endif
