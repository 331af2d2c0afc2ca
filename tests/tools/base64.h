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

/* Decodes the n characters of text into a malloc'd buffer (NUL-terminated,
 * for convenience) and its length in *len.  The text must be canonical
 * base64: a multiple of 4 characters of the alphabet, "=" only as the last
 * one or two, and no bits set past the data.  Returns NULL for any other
 * text (and when memory runs out), with the reason in err. */
unsigned char *base64_decode(const char *text, size_t n, size_t *len, char *err, size_t errlen);

#endif
