/*
 * zlib.h - checksums, a growable byte buffer, and DEFLATE compression.
 *
 *     kit_crc32, kit_adler32     the checksums of gzip/ZIP/PNG and of zlib
 *     KitBuf                     a byte buffer that grows as it is appended to
 *     kit_put_be32, kit_get_be32 4-byte big-endian numbers
 *     kit_deflate, kit_inflate   raw DEFLATE streams (RFC 1951)
 *     kit_zlib_compress,         the same inside the zlib wrapper (RFC 1950):
 *     kit_zlib_uncompress        a 2-byte header and an Adler-32 trailer
 *
 * The compressor finds repeats with hash chains over a 32 KiB window and codes
 * them with the fixed Huffman codes, falling back to stored blocks for data
 * that does not shrink.  The decompressor reads stored, fixed and dynamic
 * blocks, checks every bound and never produces more than a given limit, so
 * corrupt, truncated or hostile input is an error, never a crash.
 */
#ifndef KIT_ZLIB_H
#define KIT_ZLIB_H

#include <stddef.h>
#include <stdint.h>

/* A growable byte buffer.  Zero-initialised (or kit_buf_init) it is empty;
 * data is NULL or malloc'd; kit_buf_free releases it. */
typedef struct {
    unsigned char *data;
    size_t len;                 /* bytes in use          */
    size_t cap;                 /* bytes allocated       */
} KitBuf;

void kit_buf_init(KitBuf *b);
void kit_buf_free(KitBuf *b);
/* Makes room for extra more bytes.  Returns 0, or -1 (nothing changed) if
 * memory runs out or the size would overflow. */
int kit_buf_reserve(KitBuf *b, size_t extra);
/* Appends n bytes (data may be NULL when n is 0).  Returns 0 or -1 as above. */
int kit_buf_append(KitBuf *b, const void *data, size_t n);
/* Appends one byte.  Returns 0 or -1 as above. */
int kit_buf_push(KitBuf *b, unsigned char byte);

/* Stores v at p[0 .. 3], and reads it back, most significant byte first
 * (the order of zlib's trailer and of PNG's numbers). */
void kit_put_be32(unsigned char *p, uint32_t v);
uint32_t kit_get_be32(const unsigned char *p);

/* CRC-32 (ISO-HDLC: reflected polynomial 0xEDB88320, as in gzip, ZIP and
 * PNG).  Start with crc = 0; pass the previous result to continue. */
uint32_t kit_crc32(uint32_t crc, const void *data, size_t n);

/* Adler-32 (RFC 1950).  Start with adler = 1; pass the previous result to
 * continue. */
uint32_t kit_adler32(uint32_t adler, const void *data, size_t n);

/* Appends the raw DEFLATE stream of in[0 .. n-1] to out.  Returns 0, or -1
 * if memory runs out or n is 4 GiB or more (out keeps its old length). */
int kit_deflate(const void *in, size_t n, KitBuf *out);

/* Decodes the raw DEFLATE stream at the start of in[0 .. n-1] and appends
 * the data to out, refusing to append more than max_out bytes.  If consumed
 * is not NULL it receives the number of input bytes the stream occupies
 * (any bytes after it are left alone).  Returns 0, or -1 with a reason in
 * err (the stream is corrupt or truncated, the output would exceed max_out,
 * or memory ran out); on error out keeps its old length. */
int kit_inflate(const void *in, size_t n, size_t max_out, KitBuf *out,
                size_t *consumed, char *err, size_t errlen);

/* Appends in[0 .. n-1] compressed as a zlib stream (RFC 1950) to out.
 * Returns 0, or -1 as kit_deflate (out keeps its old length). */
int kit_zlib_compress(const void *in, size_t n, KitBuf *out);

/* Decodes the zlib stream in[0 .. n-1] (which must hold nothing after the
 * trailer), checks its header and Adler-32, and appends the data to out,
 * at most max_out bytes.  Returns 0, or -1 with a reason in err; on error
 * out keeps its old length. */
int kit_zlib_uncompress(const void *in, size_t n, size_t max_out, KitBuf *out,
                        char *err, size_t errlen);

#endif
