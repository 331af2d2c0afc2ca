/*
 * numtext.h - doubles as the shortest decimal text that reads back exactly.
 */
#ifndef KIT_NUMTEXT_H
#define KIT_NUMTEXT_H

#include <stddef.h>

/* Writes x into buf (at least 32 bytes) as the shortest text that strtod
 * reads back as x: whole numbers as integers ("100", not "1e+02"), others
 * with up to 17 significant digits; NaN and infinities as "nan", "inf",
 * "-inf".  Returns buf. */
char *kit_shortest_double(char *buf, size_t size, double x);

#endif
