/*
 * zlib.c - CRC-32, Adler-32, KitBuf, DEFLATE (RFC 1951) and the zlib
 * wrapper (RFC 1950).  See zlib.h.
 */
#include "zlib.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- growable byte buffer -------------------------------------------------- */

/* Makes b empty without freeing anything. */
void kit_buf_init(KitBuf *b)
{
    b->data = NULL;
    b->len = 0;
    b->cap = 0;
}

/* Frees b's memory and leaves it empty. */
void kit_buf_free(KitBuf *b)
{
    free(b->data);
    kit_buf_init(b);
}

/* Grows b so that extra more bytes fit.  Returns 0, or -1 on overflow or when
 * memory runs out (b unchanged). */
int kit_buf_reserve(KitBuf *b, size_t extra)
{
    if (extra <= b->cap - b->len)
        return 0;
    if (extra > SIZE_MAX - b->len)
        return -1;
    size_t need = b->len + extra;
    size_t cap = b->cap ? b->cap : 256;
    while (cap < need)
        cap = cap > SIZE_MAX / 2 ? need : 2 * cap;
    unsigned char *p = realloc(b->data, cap);
    if (!p)
        return -1;
    b->data = p;
    b->cap = cap;
    return 0;
}

/* Appends data[0 .. n-1].  Returns 0, or -1 when memory runs out. */
int kit_buf_append(KitBuf *b, const void *data, size_t n)
{
    if (n == 0)
        return 0;
    if (kit_buf_reserve(b, n) != 0)
        return -1;
    memcpy(b->data + b->len, data, n);
    b->len += n;
    return 0;
}

/* Appends one byte.  Returns 0, or -1 when memory runs out. */
int kit_buf_push(KitBuf *b, unsigned char byte)
{
    if (b->len == b->cap && kit_buf_reserve(b, 1) != 0)
        return -1;
    b->data[b->len++] = byte;
    return 0;
}

/* ---- big-endian numbers (zlib's trailer, PNG's lengths and CRCs) ---------- */

void kit_put_be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

uint32_t kit_get_be32(const unsigned char *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

/* ---- checksums --------------------------------------------------------------- */

#define CRC32_POLY 0xEDB88320u

/* One CRC-32 step over the 8 bits of byte: the bitwise definition. */
static uint32_t crc32_byte(uint32_t c, unsigned char byte)
{
    c ^= byte;
    for (int k = 0; k < 8; k++)
        c = (c >> 1) ^ (CRC32_POLY & (0u - (c & 1u)));
    return c;
}

/* CRC-32 of data, continuing from crc.  Short inputs go bit by bit; longer
 * ones through a 256-entry table built on the stack (no shared state, so it
 * is safe from any thread).  Cannot fail. */
uint32_t kit_crc32(uint32_t crc, const void *data, size_t n)
{
    const unsigned char *p = data;
    uint32_t c = ~crc;
    if (n < 512) {
        for (size_t i = 0; i < n; i++)
            c = crc32_byte(c, p[i]);
        return ~c;
    }
    uint32_t table[256];
    for (unsigned b = 0; b < 256; b++)
        table[b] = crc32_byte(0, (unsigned char)b);
    for (size_t i = 0; i < n; i++)
        c = table[(c ^ p[i]) & 0xFFu] ^ (c >> 8);
    return ~c;
}

#define ADLER_MOD 65521u
#define ADLER_RUN 5552      /* most bytes summed before the sums could overflow */

/* Adler-32 of data, continuing from adler.  Cannot fail. */
uint32_t kit_adler32(uint32_t adler, const void *data, size_t n)
{
    const unsigned char *p = data;
    uint32_t a = adler & 0xFFFFu, b = adler >> 16;
    while (n > 0) {
        size_t run = n < ADLER_RUN ? n : ADLER_RUN;
        n -= run;
        while (run--) {
            a += *p++;
            b += a;
        }
        a %= ADLER_MOD;
        b %= ADLER_MOD;
    }
    return (b << 16) | a;
}

/* ---- tables shared by the compressor and the decompressor (RFC 1951 3.2.5) -- */

static const uint16_t len_base[29] = {
    3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
    35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t len_extra[29] = {
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2,
    3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t dist_base[30] = {
    1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193,
    257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const uint8_t dist_extra[30] = {
    0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6,
    7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/* The order in which a dynamic block lists the code length code's lengths. */
static const uint8_t clen_order[19] = {
    16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

/* ---- compressor ------------------------------------------------------------- */

#define DF_WINDOW     32768u
#define DF_HASH_BITS  15
#define DF_HASH_SIZE  (1u << DF_HASH_BITS)
#define DF_MAX_CHAIN  128          /* candidates tried per position */
#define DF_MIN_MATCH  3
#define DF_MAX_MATCH  258
/* A block covers at most 65535 input bytes, so that the stored form of any
 * block is a single stored block. */
#define DF_BLOCK_INPUT (65535u - DF_MAX_MATCH)

typedef struct {
    uint16_t lit;       /* a literal byte, or a match length 3..258 */
    uint16_t dist;      /* 0 for a literal, else the distance 1..32768 */
} DfSymbol;

typedef struct {
    KitBuf *out;
    uint64_t bits;      /* pending bits, the first to go out in bit 0 */
    unsigned nbits;
    int failed;         /* memory ran out */
} DfWriter;

/* Positions are kept in 32 bits: half the memory of size_t entries, and
 * as many fewer pages for a short-lived process to fault in.  Every input
 * the kit compresses is well under 4 GiB (a PNG's rows of at most
 * PNG_MAX_SIDE pixels, a ZIP entry of at most ARCHIVE_MAX_SIZE bytes);
 * kit_deflate refuses a larger one. */
typedef struct {
    const unsigned char *in;
    size_t n;
    uint32_t *head;     /* per hash: 1 + the latest position, or 0      */
    uint32_t *prev;     /* per position mod the window (n entries when n
                           is shorter): 1 + the previous position, or 0 */
} DfMatcher;

/* Queues the low count bits of value (count <= 32), first bit first. */
static void df_put_bits(DfWriter *w, uint32_t value, unsigned count)
{
    w->bits |= (uint64_t)value << w->nbits;
    w->nbits += count;
    while (w->nbits >= 8) {
        if (kit_buf_push(w->out, (unsigned char)(w->bits & 0xFFu)) != 0)
            w->failed = 1;
        w->bits >>= 8;
        w->nbits -= 8;
    }
}

/* Sends a Huffman code of len bits, whose most significant bit goes first. */
static void df_put_code(DfWriter *w, uint32_t code, unsigned len)
{
    uint32_t rev = 0;
    for (unsigned k = 0; k < len; k++)
        rev |= ((code >> k) & 1u) << (len - 1 - k);
    df_put_bits(w, rev, len);
}

/* Pads the pending bits with zeros up to a byte boundary. */
static void df_align(DfWriter *w)
{
    if (w->nbits > 0)
        df_put_bits(w, 0, 8 - w->nbits);
}

/* The fixed literal/length code of symbol sym (0..287): its bits and length. */
static void df_fixed_litlen(unsigned sym, uint32_t *code, unsigned *len)
{
    if (sym < 144) {
        *code = 0x30 + sym;
        *len = 8;
    } else if (sym < 256) {
        *code = 0x190 + (sym - 144);
        *len = 9;
    } else if (sym < 280) {
        *code = sym - 256;
        *len = 7;
    } else {
        *code = 0xC0 + (sym - 280);
        *len = 8;
    }
}

/* The index (0..28) of the length code for a match length 3..258. */
static unsigned df_len_index(unsigned length)
{
    unsigned c = 28;
    while (len_base[c] > length)
        c--;
    return c;
}

/* The index (0..29) of the distance code for a distance 1..32768. */
static unsigned df_dist_index(unsigned dist)
{
    unsigned c = 29;
    while (dist_base[c] > dist)
        c--;
    return c;
}

/* Bits that symbol s costs in the fixed code. */
static size_t df_fixed_cost(DfSymbol s)
{
    if (s.dist == 0)
        return s.lit < 144 ? 8 : 9;
    unsigned li = df_len_index(s.lit), di = df_dist_index(s.dist);
    return (257 + li < 280 ? 7u : 8u) + len_extra[li] + 5u + dist_extra[di];
}

/* Hash of the 3 bytes at p. */
static unsigned df_hash(const unsigned char *p)
{
    uint32_t v = ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2];
    return (unsigned)((v * 2654435761u) >> (32 - DF_HASH_BITS));
}

/* Records position pos (which has 3 bytes after it) in the hash chains. */
static void df_insert(DfMatcher *m, size_t pos)
{
    if (pos + DF_MIN_MATCH > m->n)
        return;
    unsigned h = df_hash(m->in + pos);
    m->prev[pos & (DF_WINDOW - 1)] = m->head[h];
    m->head[h] = (uint32_t)(pos + 1);
}

/* The longest earlier match for the bytes at pos, within the window, found
 * along pos's hash chain.  Returns its length (0 if under 3) and sets *dist. */
static unsigned df_longest_match(const DfMatcher *m, size_t pos, unsigned *dist)
{
    size_t avail = m->n - pos;
    unsigned maxlen = avail < DF_MAX_MATCH ? (unsigned)avail : DF_MAX_MATCH;
    unsigned best = 0;
    if (maxlen < DF_MIN_MATCH)
        return 0;
    const unsigned char *cur = m->in + pos;
    size_t cand = m->head[df_hash(cur)];
    for (int chain = DF_MAX_CHAIN; cand != 0 && chain > 0; chain--) {
        size_t c = cand - 1;
        if (c >= pos || pos - c > DF_WINDOW)
            break;
        const unsigned char *old = m->in + c;
        if (old[best] == cur[best]) {
            unsigned len = 0;
            while (len < maxlen && old[len] == cur[len])
                len++;
            if (len > best) {
                best = len;
                *dist = (unsigned)(pos - c);
                if (len == maxlen)
                    break;
            }
        }
        size_t next = m->prev[c & (DF_WINDOW - 1)];
        if (next >= cand)       /* chains only go back in time */
            break;
        cand = next;
    }
    return best >= DF_MIN_MATCH ? best : 0;
}

/* Writes syms[0 .. count-1] as one block with the fixed codes. */
static void df_emit_fixed(DfWriter *w, const DfSymbol *syms, size_t count, int final)
{
    uint32_t code;
    unsigned len;
    df_put_bits(w, final ? 1u : 0u, 1);
    df_put_bits(w, 1, 2);
    for (size_t k = 0; k < count; k++) {
        DfSymbol s = syms[k];
        if (s.dist == 0) {
            df_fixed_litlen(s.lit, &code, &len);
            df_put_code(w, code, len);
            continue;
        }
        unsigned li = df_len_index(s.lit), di = df_dist_index(s.dist);
        df_fixed_litlen(257 + li, &code, &len);
        df_put_code(w, code, len);
        df_put_bits(w, s.lit - len_base[li], len_extra[li]);
        df_put_code(w, di, 5);
        df_put_bits(w, s.dist - dist_base[di], dist_extra[di]);
    }
    df_fixed_litlen(256, &code, &len);
    df_put_code(w, code, len);
}

/* Writes data[0 .. n-1] (n <= 65535) as one stored block. */
static void df_emit_stored(DfWriter *w, const unsigned char *data, size_t n, int final)
{
    df_put_bits(w, final ? 1u : 0u, 1);
    df_put_bits(w, 0, 2);
    df_align(w);
    df_put_bits(w, (uint32_t)n, 16);
    df_put_bits(w, (uint32_t)n ^ 0xFFFFu, 16);
    if (kit_buf_append(w->out, data, n) != 0)
        w->failed = 1;
}

/* Compresses in[] block by block: each block is parsed greedily into
 * literals and matches, then written with the fixed codes or stored,
 * whichever takes fewer bits.  Returns 0, or -1 if memory runs out. */
int kit_deflate(const void *in, size_t n, KitBuf *out)
{
    size_t old_len = out->len;
    /* The chains and a block's symbols need no more entries than there
     * are bytes: a small figure's PNG, or a test's, does not clear 384 KiB
     * it never uses (the hash heads stay whole: they decide the matches). */
    size_t nprev = n < DF_WINDOW ? (n ? n : 1) : DF_WINDOW;
    size_t nsyms = n < DF_BLOCK_INPUT ? (n ? n : 1) : DF_BLOCK_INPUT;
    DfMatcher m = {in, n, calloc(DF_HASH_SIZE, sizeof(uint32_t)), calloc(nprev, sizeof(uint32_t))};
    DfSymbol *syms = malloc(nsyms * sizeof *syms);
    DfWriter w = {out, 0, 0, 0};
    if (!m.head || !m.prev || !syms || n >= UINT32_MAX)
        w.failed = 1;
    size_t pos = 0;
    while (!w.failed) {
        size_t start = pos, count = 0, fixed_bits = 3 + 7;
        while (pos < n && pos - start < DF_BLOCK_INPUT) {
            unsigned dist = 0, len = df_longest_match(&m, pos, &dist);
            DfSymbol s = {m.in[pos], 0};
            if (len >= DF_MIN_MATCH) {
                s.lit = (uint16_t)len;
                s.dist = (uint16_t)dist;
            } else {
                len = 1;
            }
            for (unsigned k = 0; k < len; k++)
                df_insert(&m, pos + k);
            syms[count++] = s;
            fixed_bits += df_fixed_cost(s);
            pos += len;
        }
        int final = pos == n;
        size_t pad = (8 - (w.nbits + 3) % 8) % 8;
        size_t stored_bits = 3 + pad + 32 + 8 * (pos - start);
        if (stored_bits < fixed_bits)
            df_emit_stored(&w, m.in + start, pos - start, final);
        else
            df_emit_fixed(&w, syms, count, final);
        if (final)
            break;
    }
    df_align(&w);
    free(m.head);
    free(m.prev);
    free(syms);
    if (w.failed) {
        out->len = old_len;
        return -1;
    }
    return 0;
}

/* ---- decompressor ------------------------------------------------------------ */

#define INF_MAX_BITS 15
#define INF_MAX_LITLEN 288
#define INF_MAX_DIST 32

/* A canonical Huffman code: how many codes of each length, and the symbols
 * in code order (by length, then by symbol value). */
typedef struct {
    uint16_t count[INF_MAX_BITS + 1];
    uint16_t symbol[INF_MAX_LITLEN];
} InfHuffman;

typedef struct {
    const unsigned char *in;
    size_t n, pos;          /* input bytes read so far */
    uint32_t bits;          /* bits read but not used, the next in bit 0 */
    unsigned nbits;
    KitBuf *out;
    size_t base;            /* out->len when decoding started */
    size_t limit;           /* out->len may not grow past this */
    char *err;
    size_t errlen;
} Inflater;

/* Puts a reason in s->err.  Returns -1 for the caller to pass on. */
static int inf_fail(Inflater *s, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static int inf_fail(Inflater *s, const char *fmt, ...)
{
    if (s->err && s->errlen > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(s->err, s->errlen, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* Reads count (<= 16) bits into *value.  Returns 0, or -1 if the input ends. */
static int inf_bits(Inflater *s, unsigned count, unsigned *value)
{
    while (s->nbits < count) {
        if (s->pos >= s->n)
            return inf_fail(s, "deflate data is truncated");
        s->bits |= (uint32_t)s->in[s->pos++] << s->nbits;
        s->nbits += 8;
    }
    *value = s->bits & ((1u << count) - 1u);
    s->bits >>= count;
    s->nbits -= count;
    return 0;
}

/* Builds h from the code lengths of symbols 0 .. n-1.  Returns the number
 * of unused codes at the longest length (0 for a complete code), or -1 if
 * the lengths ask for more codes than exist. */
static int inf_build(InfHuffman *h, const uint8_t *lengths, unsigned n)
{
    uint16_t offset[INF_MAX_BITS + 1];
    memset(h->count, 0, sizeof h->count);
    for (unsigned k = 0; k < n; k++)
        h->count[lengths[k]]++;
    int left = 1;
    for (unsigned len = 1; len <= INF_MAX_BITS; len++) {
        left = 2 * left - h->count[len];
        if (left < 0)
            return -1;
    }
    offset[1] = 0;
    for (unsigned len = 1; len < INF_MAX_BITS; len++)
        offset[len + 1] = (uint16_t)(offset[len] + h->count[len]);
    for (unsigned k = 0; k < n; k++)
        if (lengths[k] != 0)
            h->symbol[offset[lengths[k]]++] = (uint16_t)k;
    return left;
}

/* Whether a code built by inf_build may be used: complete, empty, or a
 * single code of one bit (all the incomplete codes RFC 1951 allows). */
static int inf_usable(const InfHuffman *h, int left)
{
    if (left == 0)
        return 1;
    int total = 0;
    for (unsigned len = 1; len <= INF_MAX_BITS; len++)
        total += h->count[len];
    return total == 0 || (total == 1 && h->count[1] == 1);
}

/* Reads one symbol coded with h, a bit at a time: the code of each length
 * is compared with the first code of that length.  Returns the symbol, or
 * -1 if the input ends or the bits are no code of h. */
static int inf_decode(Inflater *s, const InfHuffman *h)
{
    int code = 0, first = 0, index = 0;
    for (unsigned len = 1; len <= INF_MAX_BITS; len++) {
        unsigned bit = 0;
        if (inf_bits(s, 1, &bit) != 0)
            return -1;
        code |= (int)bit;
        int count = h->count[len];
        if (code - first < count)
            return h->symbol[index + code - first];
        index += count;
        first = (first + count) << 1;
        code <<= 1;
    }
    return inf_fail(s, "invalid Huffman code in deflate data");
}

/* Makes room for count more output bytes.  Returns 0, or -1 past the limit
 * or when memory runs out. */
static int inf_room(Inflater *s, size_t count)
{
    if (count > s->limit - s->out->len)
        return inf_fail(s, "decompressed data exceeds the limit of %zu bytes",
                        s->limit - s->base);
    if (kit_buf_reserve(s->out, count) != 0)
        return inf_fail(s, "out of memory while decompressing");
    return 0;
}

/* Copies a stored block's bytes to the output.  Returns 0 or -1. */
static int inf_stored(Inflater *s)
{
    unsigned len = 0, nlen = 0;
    s->bits = 0;            /* skip to the byte boundary */
    s->nbits = 0;
    if (inf_bits(s, 16, &len) != 0 || inf_bits(s, 16, &nlen) != 0)
        return -1;
    if (len != (nlen ^ 0xFFFFu))
        return inf_fail(s, "stored block length does not match its complement");
    if (len > s->n - s->pos)
        return inf_fail(s, "deflate data is truncated");
    if (len == 0)
        return 0;
    if (inf_room(s, len) != 0)
        return -1;
    memcpy(s->out->data + s->out->len, s->in + s->pos, len);
    s->out->len += len;
    s->pos += len;
    return 0;
}

/* Decodes literals and matches with the codes lit and dist up to the end of
 * block code.  Returns 0 or -1. */
static int inf_codes(Inflater *s, const InfHuffman *lit, const InfHuffman *dist)
{
    for (;;) {
        int sym = inf_decode(s, lit);
        if (sym < 0)
            return -1;
        if (sym < 256) {
            if (inf_room(s, 1) != 0)
                return -1;
            s->out->data[s->out->len++] = (unsigned char)sym;
            continue;
        }
        if (sym == 256)
            return 0;
        sym -= 257;
        if (sym >= 29)
            return inf_fail(s, "invalid length code %d in deflate data", sym + 257);
        unsigned extra = 0, length, distance;
        if (inf_bits(s, len_extra[sym], &extra) != 0)
            return -1;
        length = len_base[sym] + extra;
        int dsym = inf_decode(s, dist);
        if (dsym < 0)
            return -1;
        if (dsym >= 30)
            return inf_fail(s, "invalid distance code %d in deflate data", dsym);
        if (inf_bits(s, dist_extra[dsym], &extra) != 0)
            return -1;
        distance = dist_base[dsym] + extra;
        if (distance > s->out->len - s->base)
            return inf_fail(s, "deflate data refers to %u bytes back, before its start", distance);
        if (inf_room(s, length) != 0)
            return -1;
        /* dst[k] = dst[k - distance] for k < length: the copy may overlap
         * itself.  What is copied repeats with period distance, and so with
         * any multiple p of it whose source is already written (p <= k +
         * distance); each memcpy of at most p bytes does not overlap, and p
         * about doubles each time. */
        unsigned char *dst = s->out->data + s->out->len;
        unsigned k = 0, p = distance;
        while (k < length) {
            unsigned n = length - k < p ? length - k : p;
            memcpy(dst + k, dst + k - p, n);
            k += n;
            p = (k + distance) / distance * distance;
        }
        s->out->len += length;
    }
}

/* Decodes a block with the fixed codes.  Returns 0 or -1. */
static int inf_fixed(Inflater *s)
{
    uint8_t lengths[INF_MAX_LITLEN];
    InfHuffman lit, dist;
    unsigned k = 0;
    for (; k < 144; k++) lengths[k] = 8;
    for (; k < 256; k++) lengths[k] = 9;
    for (; k < 280; k++) lengths[k] = 7;
    for (; k < 288; k++) lengths[k] = 8;
    inf_build(&lit, lengths, 288);
    for (k = 0; k < 30; k++) lengths[k] = 5;
    inf_build(&dist, lengths, 30);   /* codes 30 and 31 stay invalid */
    return inf_codes(s, &lit, &dist);
}

/* Reads the code lengths of a dynamic block's two codes (RFC 1951 3.2.7)
 * into lengths[0 .. nlit + ndist - 1].  Returns 0 or -1. */
static int inf_read_lengths(Inflater *s, uint8_t *lengths, unsigned nlit, unsigned ndist,
                            unsigned nclen)
{
    uint8_t clen[19] = {0};
    InfHuffman code;
    unsigned v = 0;
    for (unsigned k = 0; k < nclen; k++) {
        if (inf_bits(s, 3, &v) != 0)
            return -1;
        clen[clen_order[k]] = (uint8_t)v;
    }
    if (inf_build(&code, clen, 19) != 0)
        return inf_fail(s, "invalid code length code in deflate data");
    unsigned total = nlit + ndist, k = 0;
    while (k < total) {
        int sym = inf_decode(s, &code);
        if (sym < 0)
            return -1;
        if (sym < 16) {
            lengths[k++] = (uint8_t)sym;
            continue;
        }
        unsigned repeat;
        uint8_t value = 0;
        if (sym == 16) {
            if (k == 0)
                return inf_fail(s, "code length repeat with no previous length");
            value = lengths[k - 1];
            if (inf_bits(s, 2, &v) != 0)
                return -1;
            repeat = 3 + v;
        } else if (sym == 17) {
            if (inf_bits(s, 3, &v) != 0)
                return -1;
            repeat = 3 + v;
        } else {
            if (inf_bits(s, 7, &v) != 0)
                return -1;
            repeat = 11 + v;
        }
        if (repeat > total - k)
            return inf_fail(s, "code lengths run past their end in deflate data");
        while (repeat--)
            lengths[k++] = value;
    }
    if (lengths[256] == 0)
        return inf_fail(s, "deflate block has no end-of-block code");
    return 0;
}

/* Decodes a block with codes described in its header.  Returns 0 or -1. */
static int inf_dynamic(Inflater *s)
{
    unsigned hlit = 0, hdist = 0, hclen = 0;
    if (inf_bits(s, 5, &hlit) != 0 || inf_bits(s, 5, &hdist) != 0 ||
        inf_bits(s, 4, &hclen) != 0)
        return -1;
    unsigned nlit = hlit + 257, ndist = hdist + 1, nclen = hclen + 4;
    if (nlit > 286 || ndist > 30)
        return inf_fail(s, "too many length or distance codes in deflate data");
    uint8_t lengths[286 + 30];
    if (inf_read_lengths(s, lengths, nlit, ndist, nclen) != 0)
        return -1;
    InfHuffman lit, dist;
    int left = inf_build(&lit, lengths, nlit);
    if (left < 0 || !inf_usable(&lit, left))
        return inf_fail(s, "invalid literal/length code in deflate data");
    left = inf_build(&dist, lengths + nlit, ndist);
    if (left < 0 || !inf_usable(&dist, left))
        return inf_fail(s, "invalid distance code in deflate data");
    return inf_codes(s, &lit, &dist);
}

/* Decodes blocks until the final one.  Returns 0, or -1 with a reason in err
 * and out restored to its old length. */
int kit_inflate(const void *in, size_t n, size_t max_out, KitBuf *out,
                size_t *consumed, char *err, size_t errlen)
{
    Inflater s = {in, n, 0, 0, 0, out, out->len, 0, err, errlen};
    s.limit = max_out > SIZE_MAX - out->len ? SIZE_MAX : out->len + max_out;
    unsigned final = 0, type = 0;
    int rc = 0;
    while (rc == 0 && !final) {
        if (inf_bits(&s, 1, &final) != 0 || inf_bits(&s, 2, &type) != 0) {
            rc = -1;
            break;
        }
        if (type == 0)
            rc = inf_stored(&s);
        else if (type == 1)
            rc = inf_fixed(&s);
        else if (type == 2)
            rc = inf_dynamic(&s);
        else
            rc = inf_fail(&s, "invalid deflate block type 3");
    }
    if (rc != 0) {
        out->len = s.base;
        return -1;
    }
    if (consumed)
        *consumed = s.pos;
    return 0;
}

/* ---- zlib wrapper (RFC 1950) ---------------------------------------------------- */

/* Header 0x78 0x01 (deflate, 32 KiB window, no dictionary), the stream, and
 * the Adler-32 of the data.  Returns 0, or -1 if memory runs out. */
int kit_zlib_compress(const void *in, size_t n, KitBuf *out)
{
    size_t old_len = out->len;
    static const unsigned char header[2] = {0x78, 0x01};
    unsigned char trailer[4];
    kit_put_be32(trailer, kit_adler32(1, in, n));
    if (kit_buf_append(out, header, 2) != 0 || kit_deflate(in, n, out) != 0 ||
        kit_buf_append(out, trailer, 4) != 0) {
        out->len = old_len;
        return -1;
    }
    return 0;
}

/* Puts why in err and gives out back its old length.  Returns -1 for the
 * caller to pass on. */
static int zl_fail(KitBuf *out, size_t old_len, char *err, size_t errlen, const char *why)
{
    out->len = old_len;
    snprintf(err, errlen, "%s", why);
    return -1;
}

/* Checks the header, inflates, checks the Adler-32 and that nothing follows.
 * Returns 0, or -1 with a reason in err (out restored). */
int kit_zlib_uncompress(const void *in, size_t n, size_t max_out, KitBuf *out,
                        char *err, size_t errlen)
{
    const unsigned char *p = in;
    size_t old_len = out->len, used = 0;
    if (n < 6)
        return zl_fail(out, old_len, err, errlen, "zlib data is truncated");
    unsigned cmf = p[0], flg = p[1];
    if ((cmf & 0x0Fu) != 8 || (cmf >> 4) > 7)
        return zl_fail(out, old_len, err, errlen,
                       "zlib header: not deflate with a window of at most 32 KiB");
    if ((cmf * 256 + flg) % 31 != 0)
        return zl_fail(out, old_len, err, errlen, "zlib header check failed");
    if (flg & 0x20u)
        return zl_fail(out, old_len, err, errlen,
                       "zlib data needs a preset dictionary (not supported)");
    if (kit_inflate(p + 2, n - 2, max_out, out, &used, err, errlen) != 0)
        return -1;
    const unsigned char *t = p + 2 + used;
    size_t rest = n - 2 - used;
    if (rest < 4)
        return zl_fail(out, old_len, err, errlen, "zlib data is truncated (no Adler-32 trailer)");
    size_t got_len = out->len - old_len;
    uint32_t got = kit_adler32(1, got_len ? out->data + old_len : NULL, got_len);
    if (got != kit_get_be32(t))
        return zl_fail(out, old_len, err, errlen, "zlib data is corrupt (Adler-32 mismatch)");
    if (rest > 4)
        return zl_fail(out, old_len, err, errlen,
                       "unexpected bytes after the end of the zlib data");
    return 0;
}
