/*
 * csv.h - the fields of the kit's CSV files (gradebook.csv, causes.csv),
 * written so that a spreadsheet reads them as text, and read back.
 */
#ifndef CSV_H
#define CSV_H

#include <stdio.h>

/* Writes one field, quoted when it holds a comma, a quote or a line
 * break.  A field that starts with =, +, -, @, a tab or a carriage return
 * is written after an apostrophe, quoted: a spreadsheet would otherwise
 * take a folder named "=HYPERLINK(...)" for a formula (OWASP's advice on
 * CSV injection). */
void csv_field(FILE *f, const char *s);

/* Reads the field at *p (a line of text as csv_field writes them) into a
 * fresh string, undoing the quotes and the apostrophe csv_field puts
 * before a formula's first character; moves *p past the field and its
 * comma.  *end is set when the field ended the line (or the text).  NULL
 * when memory runs out. */
char *csv_read_field(const char **p, int *end);

#endif
