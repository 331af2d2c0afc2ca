/*
 * base64.h - base64 (RFC 4648, section 4: the standard alphabet, with "="
 * padding, no line breaks), for GitHub Classroom's grading reporter, whose
 * runner results are base64 JSON.
 */
#ifndef TOOLS_BASE64_H
#define TOOLS_BASE64_H

#include <stddef.h>

/* The length of the encoding of n bytes, without the terminating NUL. */
size_t base64_encoded_length(size_t n);

/* Encodes n bytes into out, which holds base64_encoded_length(n) + 1 bytes;
 * out is NUL-terminated.  Returns the length written. */
size_t base64_encode(const void *data, size_t n, char *out);

#endif
