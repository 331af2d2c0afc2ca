/* Checksums, DEFLATE, the zlib wrapper, PNG and the image files of labs/kit. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include <errno.h>
#include <fcntl.h>

#include "../../labs/kit/image.h"
#include "../../labs/kit/png.h"
#include "../../labs/kit/zlib.h"

/* ---- helpers -------------------------------------------------------------------- */

static uint32_t rng_state = 12345u;

static uint32_t rng_next(void)
{
    return check_xorshift32(&rng_state);
}

/* n pseudo-random bytes, malloc'd. */
static unsigned char *random_bytes(size_t n)
{
    unsigned char *p = malloc(n ? n : 1);
    check_random_bytes(&rng_state, p, n);
    return p;
}

/* CRC-32 computed bit by bit from the definition, independent of the kit. */
static uint32_t slow_crc32(const unsigned char *p, size_t n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

static uint32_t be32(const unsigned char *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

static void put_be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* Deflates then inflates data; checks the round trip; returns the
 * compressed size. */
static size_t deflate_round_trip(const unsigned char *data, size_t n)
{
    KitBuf z = {0}, back = {0};
    char err[200] = "";
    size_t used = 0;
    CHECK_EQ_INT(kit_deflate(data, n, &z), 0);
    int rc = kit_inflate(z.data, z.len, n, &back, &used, err, sizeof err);
    CHECK_MSG(rc == 0, "inflate failed: %s", err);
    CHECK_EQ_INT(used, z.len);
    CHECK_EQ_INT(back.len, n);
    CHECK(n == 0 || (back.len == n && memcmp(back.data, data, n) == 0));
    /* the zlib wrapper too */
    KitBuf w = {0}, wback = {0};
    CHECK_EQ_INT(kit_zlib_compress(data, n, &w), 0);
    rc = kit_zlib_uncompress(w.data, w.len, n, &wback, err, sizeof err);
    CHECK_MSG(rc == 0, "zlib uncompress failed: %s", err);
    CHECK(wback.len == n && (n == 0 || memcmp(wback.data, data, n) == 0));
    size_t size = z.len;
    kit_buf_free(&z);
    kit_buf_free(&back);
    kit_buf_free(&w);
    kit_buf_free(&wback);
    return size;
}

/* Inflates in[0 .. n-1] with the given limit; returns inflate's result and
 * the output in out (which the caller frees). */
static int inflate_into(const unsigned char *in, size_t n, size_t limit, KitBuf *out,
                        char *err, size_t errlen)
{
    kit_buf_init(out);
    int rc = kit_inflate(in, n, limit, out, NULL, err, errlen);
    CHECK(rc == 0 || out->len == 0);
    CHECK(out->len <= limit);
    return rc;
}

/* ---- checksums ------------------------------------------------------------------ */

static void test_crc32_known(void)
{
    CHECK_EQ_INT(kit_crc32(0, "123456789", 9), 0xCBF43926u);
    CHECK_EQ_INT(kit_crc32(0, "", 0), 0);
    CHECK_EQ_INT(kit_crc32(0, NULL, 0), 0);
    CHECK_EQ_INT(kit_crc32(0, "a", 1), 0xE8B7BE43u);
    /* continuing across pieces, on both sides of the table threshold */
    unsigned char *data = random_bytes(100000);
    uint32_t whole = kit_crc32(0, data, 100000);
    CHECK_EQ_INT(whole, slow_crc32(data, 100000));
    uint32_t parts = 0;
    for (size_t at = 0; at < 100000; at += 777)
        parts = kit_crc32(parts, data + at, 100000 - at < 777 ? 100000 - at : 777);
    CHECK_EQ_INT(parts, whole);
    free(data);
}

static void test_adler32_known(void)
{
    CHECK_EQ_INT(kit_adler32(1, "Wikipedia", 9), 0x11E60398u);
    CHECK_EQ_INT(kit_adler32(1, "", 0), 1);
    /* long runs of 0xFF stress the modular reduction */
    size_t n = 1 << 20;
    unsigned char *ff = malloc(n);
    memset(ff, 0xFF, n);
    uint32_t a = 1, b = 0;
    for (size_t k = 0; k < n; k++) {
        a = (a + 0xFF) % 65521;
        b = (b + a) % 65521;
    }
    CHECK_EQ_INT(kit_adler32(1, ff, n), (b << 16) | a);
    CHECK_EQ_INT(kit_adler32(kit_adler32(1, ff, 1000), ff + 1000, n - 1000), (b << 16) | a);
    free(ff);
}

/* ---- deflate and inflate round trips --------------------------------------------- */

static void test_deflate_empty(void)
{
    CHECK(deflate_round_trip(NULL, 0) <= 5);
    KitBuf z = {0};
    kit_deflate("", 0, &z);
    CHECK_EQ_INT(z.len, 2);            /* a final fixed block holding only end-of-block */
    CHECK(z.len == 2 && z.data[0] == 0x03 && z.data[1] == 0x00);
    /* 4 GiB or more, past the 32-bit positions, is refused before a byte is read */
    CHECK_EQ_INT(kit_deflate("", (size_t)UINT32_MAX, &z), -1);
    CHECK_EQ_INT(z.len, 2);
    kit_buf_free(&z);
}

static void test_deflate_short(void)
{
    static const unsigned char a_stream[] = {0x4B, 0x04, 0x00};
    KitBuf z = {0};
    kit_deflate("a", 1, &z);
    CHECK(z.len == 3 && memcmp(z.data, a_stream, 3) == 0);
    kit_buf_free(&z);
    deflate_round_trip((const unsigned char *)"a", 1);
    deflate_round_trip((const unsigned char *)"ab", 2);
    deflate_round_trip((const unsigned char *)"hello hello hello hello", 23);
    deflate_round_trip((const unsigned char *)"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa", 36);
}

static void test_deflate_1mb(void)
{
    size_t n = 1 << 20;
    unsigned char *data = random_bytes(n);
    size_t size = deflate_round_trip(data, n);
    /* random data cannot shrink: the stored blocks keep it to 5 bytes a block */
    CHECK_MSG(size <= n + 5 * (n / 65000 + 1) + 8, "random data grew to %zu bytes", size);
    memset(data, 0, n);
    size = deflate_round_trip(data, n);
    CHECK_MSG(size < n / 100, "1 MiB of zeros compressed to %zu bytes", size);
    free(data);
}

static void test_deflate_repetitive_text(void)
{
    KitBuf text = {0};
    char line[100];
    for (int k = 0; text.len < 500000; k++) {
        int len = snprintf(line, sizeof line, "line %d: the quick brown fox jumps over the lazy dog\n", k % 97);
        kit_buf_append(&text, line, (size_t)len);
    }
    size_t size = deflate_round_trip(text.data, text.len);
    CHECK_MSG(size < text.len / 8, "%zu bytes of text compressed to %zu", text.len, size);
    /* text with some variety, and runs longer than the longest match */
    KitBuf mixed = {0};
    for (int k = 0; k < 4000; k++) {
        int len = snprintf(line, sizeof line, "%u %s\n", (unsigned)(rng_next() % 1000), k % 3 ? "red" : "green");
        kit_buf_append(&mixed, line, (size_t)len);
        if (k % 500 == 0)
            for (int r = 0; r < 1000; r++)
                kit_buf_push(&mixed, 'z');
    }
    size = deflate_round_trip(mixed.data, mixed.len);
    CHECK_MSG(size < mixed.len / 2, "%zu bytes of text compressed to %zu", mixed.len, size);
    kit_buf_free(&text);
    kit_buf_free(&mixed);
}

/* Data that repeats with period p, for p from 1 to 300: its matches copy
 * from p bytes back, over what they are writing themselves when p is less
 * than their length (up to 258).  Each compresses to a few matches of 258
 * bytes, which only such overlapping copies give for short periods. */
static void test_deflate_periodic(void)
{
    enum { N = 6000 };
    unsigned char *pattern = random_bytes(300), data[N];
    for (size_t p = 1; p <= 300; p++) {
        for (size_t k = 0; k < N; k++)
            data[k] = pattern[k % p];
        size_t size = deflate_round_trip(data, N);
        CHECK_MSG(p > 64 || size < N / 20, "period %zu: %d bytes compressed to %zu", p, N, size);
    }
    free(pattern);
}

static void test_deflate_all_sizes_small(void)
{
    unsigned char *data = random_bytes(300);
    for (size_t n = 0; n < 300; n++) {
        data[n] = (unsigned char)(n % 7 ? data[n] % 4 : data[n]);   /* partly compressible */
        deflate_round_trip(data, n);
    }
    free(data);
}

/* Inputs of the window's size (32768) and of a block's (65277), and a byte
 * either side: below them the compressor sizes its tables to the input,
 * so an entry past the input's end would be out of bounds (the sanitized
 * build sees it).  Random bytes give a literal per byte, the most symbols
 * a block can have; repeated, they give matches from as far back as the
 * window lets. */
static void test_deflate_sizes_at_the_window(void)
{
    static const size_t sizes[] = {32767, 32768, 32769, 65276, 65277, 65278};
    unsigned char *noise = random_bytes(65278), *repeated = malloc(65278);
    CHECK(repeated != NULL);
    if (!repeated)
        return;
    for (size_t k = 0; k < 65278; k++)
        repeated[k] = noise[k % 20000];
    for (int s = 0; s < CHECK_COUNT(sizes); s++) {
        deflate_round_trip(noise, sizes[s]);
        size_t size = deflate_round_trip(repeated, sizes[s]);
        CHECK_MSG(size < sizes[s] * 3 / 4, "%zu bytes, a 20000-byte pattern repeated: %zu bytes compressed",
                  sizes[s], size);
    }
    free(noise);
    free(repeated);
}

/* ---- inflate of hand-made streams --------------------------------------------------- */

/* Streams made by hand, and what each inflates to: out, or an error whose
 * message holds err. */
static void test_inflate_by_hand(void)
{
    static const struct {
        unsigned char in[10];
        size_t n;
        const char *out, *err;
    } streams[] = {
        /* BFINAL=1 BTYPE=00, padding, LEN=5, NLEN=~5, "hello" */
        { {0x01, 0x05, 0x00, 0xFA, 0xFF, 'h', 'e', 'l', 'l', 'o'}, 10, "hello", NULL },
        /* a complement that does not match */
        { {0x01, 0x05, 0x00, 0xFA, 0xFE, 'h', 'e', 'l', 'l', 'o'}, 10, NULL, "complement" },
        /*
         * RFC 1951 3.2.6: literal 0..143 is 8 bits 00110000 + value, end of block
         * (256) is 7 zero bits; Huffman codes go most significant bit first,
         * everything else least significant bit first.
         *   'a' = 97 -> 10010001, 'b' -> 10010010, 'c' -> 10010011.
         * "a":   1 10 | 10010001 | 0000000             -> 4B 04 00
         * "abc": 1 10 | 10010001 10010010 10010011 | 0000000 -> 4B 4C 4A 06 00
         */
        { {0x4B, 0x04, 0x00}, 3, "a", NULL },
        { {0x4B, 0x4C, 0x4A, 0x06, 0x00}, 5, "abc", NULL },
        /* length 3 (code 257 = 0000001), distance 1 (code 0 = 00000) with nothing
         * before it: 1 10 | 0000001 | 00000 | 0000000 -> 03 02 00 */
        { {0x03, 0x02, 0x00}, 3, NULL, "before its start" },
        /* 'a' then length 3 at distance 1 gives "aaaa": 1 10 | 10010001 | 0000001 | 00000 | 0000000 */
        { {0x4B, 0x04, 0x02, 0x00}, 4, "aaaa", NULL },
        /* block type 3 is invalid */
        { {0x07, 0x00}, 2, NULL, "block type" },
    };
    KitBuf out;
    char err[200] = "";
    for (int k = 0; k < CHECK_COUNT(streams); k++) {
        const char *want = streams[k].out;
        err[0] = '\0';
        int rc = inflate_into(streams[k].in, streams[k].n, 100, &out, err, sizeof err);
        if (want)
            CHECK_MSG(rc == 0 && out.len == strlen(want) && memcmp(out.data, want, out.len) == 0,
                      "stream %d: %d, %zu bytes (%s), not \"%s\"", k, rc, out.len, err, want);
        else
            CHECK_MSG(rc == -1 && strstr(err, streams[k].err), "stream %d: %d, \"%s\", not about %s", k,
                      rc, err, streams[k].err);
        kit_buf_free(&out);
    }
    /* the compressor makes the same bytes for "abc" */
    KitBuf z = {0};
    kit_deflate("abc", 3, &z);
    CHECK(z.len == 5 && memcmp(z.data, streams[3].in, 5) == 0);
    kit_buf_free(&z);
    /* two stored blocks, the first not final, followed by unrelated bytes */
    static const unsigned char two[] = {0x00, 0x02, 0x00, 0xFD, 0xFF, 'a', 'b',
                                        0x01, 0x01, 0x00, 0xFE, 0xFF, 'c', 0xEE, 0xEE};
    size_t used = 0;
    kit_buf_init(&out);
    CHECK_EQ_INT(kit_inflate(two, sizeof two, 100, &out, &used, err, sizeof err), 0);
    CHECK(out.len == 3 && memcmp(out.data, "abc", 3) == 0);
    CHECK_EQ_INT(used, sizeof two - 2);
    kit_buf_free(&out);
}

/* A raw DEFLATE stream with one dynamic-Huffman block (made by another
 * compressor, at its highest level) and the text it holds. */
static const char dynamic_text[] =
    "It was the best of times, it was the worst of times, it was the age of wisdom, "
    "it was the age of foolishness, it was the epoch of belief, it was the epoch of "
    "incredulity, it was the season of Light, it was the season of Darkness.";
static const unsigned char dynamic_stream[] = {
    0x75, 0xcd, 0xc1, 0x09, 0x80, 0x30, 0x10, 0x44, 0xd1, 0x56, 0xb6, 0x00,
    0xb1, 0x0a, 0x2f, 0x82, 0x4d, 0x24, 0x3a, 0x31, 0x8b, 0x31, 0x2b, 0xd9,
    0x95, 0x60, 0xf7, 0x92, 0x93, 0x08, 0x7a, 0x7e, 0x7f, 0x98, 0xd1, 0xa8,
    0x3a, 0x25, 0x8b, 0x20, 0x0f, 0x35, 0x92, 0x40, 0xc6, 0x3b, 0xb4, 0x23,
    0x7e, 0xa4, 0x4a, 0xf9, 0x23, 0xb7, 0xa2, 0x41, 0x65, 0x5d, 0x64, 0xff,
    0x92, 0x20, 0x92, 0x58, 0x63, 0x86, 0xbe, 0x87, 0x38, 0x64, 0x8e, 0x2d,
    0xf0, 0x48, 0x8c, 0xf0, 0x6d, 0x9c, 0xe7, 0x82, 0xe5, 0x4c, 0x6c, 0xd7,
    0x2b, 0x50, 0x38, 0x95, 0xdc, 0x8a, 0x89, 0xd7, 0x68, 0x3f, 0x36, 0xb8,
    0xb2, 0xb5, 0xdf, 0xfe, 0x06};

static void test_inflate_dynamic_block(void)
{
    KitBuf out;
    char err[200] = "";
    CHECK_EQ_INT((dynamic_stream[0] >> 1) & 3, 2);        /* it is a dynamic block */
    int rc = inflate_into(dynamic_stream, sizeof dynamic_stream, 1000, &out, err, sizeof err);
    CHECK_MSG(rc == 0, "inflate: %s", err);
    CHECK(out.len == strlen(dynamic_text) && memcmp(out.data, dynamic_text, out.len) == 0);
    kit_buf_free(&out);
    /* and a zlib stream from the same compressor: "hello, zlib" */
    static const unsigned char zstream[] = {0x78, 0xda, 0xcb, 0x48, 0xcd, 0xc9, 0xc9, 0xd7,
                                            0x51, 0xa8, 0xca, 0xc9, 0x4c, 0x02, 0x00, 0x18,
                                            0xb2, 0x04, 0x12};
    KitBuf z = {0};
    CHECK_EQ_INT(kit_zlib_uncompress(zstream, sizeof zstream, 100, &z, err, sizeof err), 0);
    CHECK(z.len == 11 && memcmp(z.data, "hello, zlib", 11) == 0);
    kit_buf_free(&z);
}

/* ---- inflate refuses bad input -------------------------------------------------------- */

static void test_inflate_truncated(void)
{
    KitBuf out, z = {0};
    char err[200];
    unsigned char *data = random_bytes(3000);
    for (int k = 0; k < 3000; k += 3)
        data[k] = 'x';
    kit_deflate(data, 3000, &z);
    /* every strict prefix of a valid stream is an error */
    const unsigned char *streams[2] = {dynamic_stream, z.data};
    size_t sizes[2] = {sizeof dynamic_stream, z.len};
    for (int k = 0; k < 2; k++)
        for (size_t n = 0; n < sizes[k]; n++) {
            CHECK_MSG(inflate_into(streams[k], n, 3000, &out, err, sizeof err) == -1,
                      "stream %d cut to %zu bytes was read", k, n);
            kit_buf_free(&out);
        }
    CHECK_STR_CONTAINS(err, "truncated");
    kit_buf_free(&z);
    free(data);
}

static void test_inflate_corrupt(void)
{
    KitBuf out;
    char err[200];
    unsigned char copy[sizeof dynamic_stream];
    int failures = 0;
    /* every single-bit flip: an error or some output, never a crash */
    for (size_t bit = 0; bit < 8 * sizeof copy; bit++) {
        memcpy(copy, dynamic_stream, sizeof copy);
        copy[bit / 8] ^= (unsigned char)(1u << (bit % 8));
        failures += inflate_into(copy, sizeof copy, 1000, &out, err, sizeof err) != 0;
        kit_buf_free(&out);
    }
    CHECK(failures > 100);
    /* random garbage of random lengths */
    for (int k = 0; k < 20000; k++) {
        size_t n = rng_next() % 200;
        unsigned char *junk = random_bytes(n);
        if (k % 3 == 0 && n > 0)
            junk[0] = (unsigned char)((junk[0] & ~6u) | 4u);    /* force a dynamic block */
        inflate_into(junk, n, 5000, &out, err, sizeof err);
        kit_buf_free(&out);
        free(junk);
    }
    /* a zlib stream with a wrong Adler-32, a bad header, trailing bytes */
    KitBuf z = {0}, back = {0};
    kit_zlib_compress("some text some text", 19, &z);
    z.data[z.len - 1] ^= 1;
    CHECK_EQ_INT(kit_zlib_uncompress(z.data, z.len, 100, &back, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "Adler-32");
    z.data[z.len - 1] ^= 1;
    CHECK_EQ_INT((z.data[0] * 256 + z.data[1]) % 31, 0);
    z.data[1] ^= 1;
    CHECK_EQ_INT(kit_zlib_uncompress(z.data, z.len, 100, &back, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "header");
    z.data[1] ^= 1;
    kit_buf_push(&z, 0);
    CHECK_EQ_INT(kit_zlib_uncompress(z.data, z.len, 100, &back, err, sizeof err), -1);
    z.len--;
    CHECK_EQ_INT(kit_zlib_uncompress(z.data, z.len, 100, &back, err, sizeof err), 0);
    CHECK_EQ_INT(back.len, 19);
    kit_buf_free(&z);
    kit_buf_free(&back);
}

static void test_inflate_output_limit(void)
{
    size_t n = 1 << 20;
    unsigned char *zeros = calloc(n, 1);
    KitBuf z = {0}, out;
    char err[200] = "";
    kit_deflate(zeros, n, &z);
    CHECK_EQ_INT(inflate_into(z.data, z.len, n - 1, &out, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "limit");
    kit_buf_free(&out);
    CHECK_EQ_INT(inflate_into(z.data, z.len, n, &out, err, sizeof err), 0);
    CHECK_EQ_INT(out.len, n);
    kit_buf_free(&out);
    CHECK_EQ_INT(inflate_into(z.data, z.len, 0, &out, err, sizeof err), -1);
    kit_buf_free(&out);
    /* appending after existing bytes: matches may not reach into them */
    KitBuf pre = {0};
    kit_buf_append(&pre, "abc", 3);
    static const unsigned char too_far[] = {0x03, 0x02, 0x00};
    CHECK_EQ_INT(kit_inflate(too_far, 3, 10, &pre, NULL, err, sizeof err), -1);
    CHECK_EQ_INT(pre.len, 3);
    kit_buf_free(&pre);
    kit_buf_free(&z);
    free(zeros);
}

/* ---- PNG -------------------------------------------------------------------------------- */

static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};

/* A random image (freed by the caller). */
static Image random_image(int w, int h)
{
    Image img;
    char err[200];
    CHECK_EQ_INT(image_alloc(&img, w, h, err, sizeof err), 0);
    check_random_bytes(&rng_state, img.rgb, 3 * (size_t)w * (size_t)h);
    return img;
}

/* Checks png[0 .. n-1] chunk by chunk with the test's own CRC: signature,
 * IHDR first with the given size, IDATs, IEND last.  Returns the number of
 * IDAT chunks. */
static int check_png_chunks(const unsigned char *png, size_t n, int w, int h)
{
    CHECK(n >= 8 && memcmp(png, sig, 8) == 0);
    size_t at = 8;
    int index = 0, idats = 0, ended = 0;
    while (at + 12 <= n && !ended) {
        uint32_t len = be32(png + at);
        CHECK(len <= n - at - 12);
        if (len > n - at - 12)
            return -1;
        const unsigned char *type = png + at + 4;
        CHECK_EQ_INT(be32(png + at + 8 + len), slow_crc32(type, 4 + (size_t)len));
        if (index == 0) {
            CHECK(memcmp(type, "IHDR", 4) == 0 && len == 13);
            CHECK_EQ_INT(be32(type + 4), w);
            CHECK_EQ_INT(be32(type + 8), h);
            CHECK_EQ_INT(type[12], 8);
            CHECK_EQ_INT(type[13], 2);
            CHECK_EQ_INT(type[16], 0);
        } else if (memcmp(type, "IDAT", 4) == 0) {
            idats++;
        } else {
            CHECK(memcmp(type, "IEND", 4) == 0 && len == 0);
            ended = 1;
        }
        at += 12 + (size_t)len;
        index++;
    }
    CHECK(ended);
    CHECK_EQ_INT(at, n);
    CHECK(idats >= 1);
    return idats;
}

/* Encodes img, checks the chunks, decodes and compares.  Returns the
 * number of IDAT chunks. */
static int png_round_trip(const Image *img)
{
    KitBuf png = {0};
    char err[200] = "";
    CHECK_EQ_INT(png_encode(img->width, img->height, img->rgb, &png, err, sizeof err), 0);
    int idats = check_png_chunks(png.data, png.len, img->width, img->height);
    Image back;
    int rc = png_decode(png.data, png.len, &back.width, &back.height, &back.rgb, err, sizeof err);
    CHECK_MSG(rc == 0, "decode: %s", err);
    if (rc == 0) {
        CHECK_EQ_INT(back.width, img->width);
        CHECK_EQ_INT(back.height, img->height);
        CHECK(memcmp(back.rgb, img->rgb, 3 * (size_t)img->width * img->height) == 0);
    }
    image_free(&back);
    kit_buf_free(&png);
    return idats;
}

static void test_png_round_trip_random(void)
{
    static const int sizes[][2] = {{1, 1}, {3, 7}, {257, 5}, {1, 300}, {300, 1}};
    for (int k = 0; k < CHECK_COUNT(sizes); k++) {
        Image img = random_image(sizes[k][0], sizes[k][1]);
        png_round_trip(&img);
        image_free(&img);
    }
    Image big = random_image(300, 200);        /* 180 kB: several IDAT chunks */
    CHECK(png_round_trip(&big) >= 2);
    image_free(&big);
}

static void test_png_round_trip_smooth(void)
{
    /* gradients and flat areas: the filters and matches make it small */
    Image img;
    char err[200];
    image_alloc(&img, 199, 101, err, sizeof err);
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++) {
            unsigned char *p = img.rgb + 3 * ((size_t)j * img.width + i);
            p[0] = (unsigned char)i;
            p[1] = (unsigned char)(j * 2);
            p[2] = (unsigned char)(i < 100 ? 40 : (i + j) / 2);
        }
    png_round_trip(&img);
    KitBuf png = {0};
    png_encode(img.width, img.height, img.rgb, &png, err, sizeof err);
    CHECK_MSG(png.len < 3 * 199 * 101 / 10, "smooth image took %zu bytes", png.len);
    kit_buf_free(&png);
    image_free(&img);
}

/* The predictor of filter type t (RFC 2083 6.2-6.6), written from the
 * standard apart from the kit's code. */
static int spec_predict(int t, int a, int b, int c)
{
    if (t == 1)
        return a;
    if (t == 2)
        return b;
    if (t == 3)
        return (a + b) / 2;
    if (t == 4) {
        int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
        if (pa <= pb && pa <= pc)
            return a;
        return pb <= pc ? b : c;
    }
    return 0;
}

/* Each row of the encoder's output carries the filter type the "minimum
 * sum of absolute differences" rule names (the lowest type on a tie) and
 * the bytes that filter gives: checked by inflating the image data and
 * redoing every row's five sums plainly, for widths on both sides of the
 * encoder's runs of 32 bytes and for noise, smooth, flat and two-tone
 * pixels. */
static void test_png_filter_choice(void)
{
    static const int widths[] = { 1, 2, 10, 11, 12, 13, 21, 22, 43, 64, 100, 331 };
    char err[200];
    for (int wi = 0; wi < CHECK_COUNT(widths); wi++)
        for (int kind = 0; kind < 4; kind++) {
            Image img;
            int w = widths[wi], h = 9;
            image_alloc(&img, w, h, err, sizeof err);
            size_t len = 3 * (size_t)w;
            for (size_t k = 0; k < len * (size_t)h; k++) {
                uint32_t r = rng_next();
                img.rgb[k] = (unsigned char)(kind == 0   ? r >> 24
                                             : kind == 1 ? (k % len) * 5 + (k / len) * 9
                                             : kind == 2 ? (r % 40 == 0 ? r >> 24 : 128)
                                                         : (r % 3 ? 0 : 255));
            }
            KitBuf png = {0}, idat = {0}, raw = {0};
            CHECK_EQ_INT(png_encode(img.width, img.height, img.rgb, &png, err, sizeof err), 0);
            for (size_t at = 8; at + 12 <= png.len;) {
                size_t n = be32(png.data + at);
                if (memcmp(png.data + at + 4, "IDAT", 4) == 0)
                    kit_buf_append(&idat, png.data + at + 8, n);
                at += 12 + n;
            }
            int rc = kit_zlib_uncompress(idat.data, idat.len, (len + 1) * h, &raw, err, sizeof err);
            CHECK_MSG(rc == 0 && raw.len == (len + 1) * h, "image data: %s", err);
            for (int j = 0; rc == 0 && j < h; j++) {
                const unsigned char *row = img.rgb + (size_t)j * len;
                const unsigned char *out = raw.data + (size_t)j * (len + 1);
                size_t sum[5] = { 0 };
                int best = 0;
                for (int t = 0; t < 5; t++) {
                    for (size_t k = 0; k < len; k++) {
                        int a = k >= 3 ? row[k - 3] : 0, b = j > 0 ? row[k - len] : 0;
                        int c = k >= 3 && j > 0 ? row[k - len - 3] : 0;
                        int v = (unsigned char)(row[k] - spec_predict(t, a, b, c));
                        sum[t] += v < 128 ? (size_t)v : (size_t)(256 - v);
                        if (t == out[0])
                            CHECK_MSG(out[1 + k] == v, "width %d kind %d row %d byte %zu: %d, not %d",
                                      w, kind, j, k, out[1 + k], v);
                    }
                    if (sum[t] < sum[best])
                        best = t;
                }
                CHECK_MSG(out[0] == best, "width %d kind %d row %d: filter %d, not %d", w, kind,
                          j, out[0], best);
            }
            kit_buf_free(&png);
            kit_buf_free(&idat);
            kit_buf_free(&raw);
            image_free(&img);
        }
}

/* ---- decoding PNGs built by the test itself -------------------------------------- */

/* Appends a chunk with the test's own CRC. */
static void add_chunk(KitBuf *out, const char *type, const unsigned char *data, size_t n)
{
    unsigned char head[8], crc[4];
    put_be32(head, (uint32_t)n);
    memcpy(head + 4, type, 4);
    kit_buf_append(out, head, 8);
    kit_buf_append(out, data, n);
    put_be32(crc, slow_crc32(out->data + out->len - n - 4, n + 4));      /* of the type and data */
    kit_buf_append(out, crc, 4);
}

/* Builds a PNG of w x h pixels of `channels` samples (colour type ctype)
 * from samples[], row j filtered with type j % 5, the zlib data split into
 * IDAT chunks of idat_size bytes.  interlace goes into IHDR as given. */
static void build_png(KitBuf *out, const unsigned char *samples, int w, int h, int ctype,
                      int channels, size_t idat_size, int interlace)
{
    size_t stride = (size_t)w * channels;
    KitBuf raw = {0}, z = {0};
    for (int j = 0; j < h; j++) {
        int type = j % 5;
        const unsigned char *row = samples + j * stride;
        const unsigned char *up = j ? row - stride : NULL;
        kit_buf_push(&raw, (unsigned char)type);
        for (size_t k = 0; k < stride; k++) {
            int a = k >= (size_t)channels ? row[k - channels] : 0;
            int b = up ? up[k] : 0;
            int c = up && k >= (size_t)channels ? up[k - channels] : 0;
            kit_buf_push(&raw, (unsigned char)(row[k] - spec_predict(type, a, b, c)));
        }
    }
    kit_zlib_compress(raw.data, raw.len, &z);
    unsigned char ihdr[13] = {0};
    put_be32(ihdr, (uint32_t)w);
    put_be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;
    ihdr[9] = (unsigned char)ctype;
    ihdr[12] = (unsigned char)interlace;
    kit_buf_append(out, sig, 8);
    add_chunk(out, "IHDR", ihdr, 13);
    add_chunk(out, "tEXt", (const unsigned char *)"Comment\0ignored", 15);
    for (size_t at = 0; at < z.len; at += idat_size)
        add_chunk(out, "IDAT", z.data + at, z.len - at < idat_size ? z.len - at : idat_size);
    add_chunk(out, "IEND", NULL, 0);
    kit_buf_free(&raw);
    kit_buf_free(&z);
}

static void test_png_decode_all_filters_and_types(void)
{
    static const struct { int ctype, channels; } kinds[] = {{2, 3}, {6, 4}, {0, 1}, {4, 2}};
    for (int k = 0; k < CHECK_COUNT(kinds); k++) {
        int w = 13, h = 11, ch = kinds[k].channels;
        unsigned char *samples = random_bytes((size_t)w * h * ch);
        for (size_t idat = 1; idat <= 1000; idat *= 1000) {   /* 1-byte IDATs, then one */
            KitBuf png = {0};
            build_png(&png, samples, w, h, kinds[k].ctype, ch, idat, 0);
            Image img;
            char err[200] = "";
            int rc = png_decode(png.data, png.len, &img.width, &img.height, &img.rgb, err,
                                sizeof err);
            CHECK_MSG(rc == 0, "colour type %d: %s", kinds[k].ctype, err);
            if (rc == 0) {
                CHECK_EQ_INT(img.width, w);
                CHECK_EQ_INT(img.height, h);
                int same = 1;
                for (int p = 0; p < w * h; p++) {
                    const unsigned char *s = samples + (size_t)p * ch;
                    for (int c = 0; c < 3; c++)
                        same &= img.rgb[3 * p + c] == (ch < 3 ? s[0] : s[c]);
                }
                CHECK_MSG(same, "colour type %d: pixels differ", kinds[k].ctype);
            }
            image_free(&img);
            kit_buf_free(&png);
        }
        free(samples);
    }
}

/* Decodes png, expecting failure with a message containing want; what
 * names the case. */
static void expect_png_error(const KitBuf *png, const char *want, const char *what)
{
    Image img = {5, 5, NULL};
    char err[300] = "";
    int rc = png_decode(png->data, png->len, &img.width, &img.height, &img.rgb, err, sizeof err);
    CHECK_MSG(rc == -1 && strstr(err, want), "%s: %d, \"%s\", not -1 about \"%s\"", what, rc, err, want);
    CHECK(img.rgb == NULL);
}

/* PNGs of 4 x 3 pixels built with ctype, channels and interlace, their
 * IHDR then given width w, height h and depth (its CRC made again). */
static void test_png_decode_refuses(void)
{
    static const struct {
        int ctype, channels, interlace;
        uint32_t w, h;
        unsigned char depth;
        const char *want;
    } bad[] = {
        { 2, 3, 1, 4, 3, 8, "interlaced" },
        { 3, 1, 0, 4, 3, 8, "palette" },
        { 2, 3, 0, PNG_MAX_SIDE + 1, 1, 8, "each side must be 1 to" },
        { 2, 3, 0, 1, PNG_MAX_SIDE + 1, 8, "each side must be 1 to" },
        { 2, 3, 0, 0, 5, 8, "each side must be 1 to" },
        { 2, 3, 0, 4, 3, 16, "bit depth 16" },
        { 2, 3, 0, 4, 4, 8, "corrupt" },    /* the image data holds too few bytes for the size */
    };
    unsigned char samples[4 * 3 * 3];
    memset(samples, 7, sizeof samples);
    KitBuf png = {0};
    char what[80];
    for (int k = 0; k < CHECK_COUNT(bad); k++) {
        build_png(&png, samples, 4, 3, bad[k].ctype, bad[k].channels, 1000, bad[k].interlace);
        put_be32(png.data + 16, bad[k].w);
        put_be32(png.data + 20, bad[k].h);
        png.data[24] = bad[k].depth;
        put_be32(png.data + 29, slow_crc32(png.data + 12, 17));
        snprintf(what, sizeof what, "IHDR %d", k);
        expect_png_error(&png, bad[k].want, what);
        kit_buf_free(&png);
    }
    build_png(&png, samples, 4, 3, 2, 3, 1000, 0);
    png.data[png.len - 20] ^= 0x10;              /* inside the IDAT data */
    expect_png_error(&png, "CRC", "a bit changed");
    png.data[png.len - 20] ^= 0x10;
    for (size_t n = 0; n < png.len; n++) {       /* every truncation */
        KitBuf cut = {png.data, n, n};
        snprintf(what, sizeof what, "cut to %zu bytes", n);
        expect_png_error(&cut, n < 8 ? "signature" : "truncated", what);
    }
    png.data[0] = 'x';
    expect_png_error(&png, "signature", "a signature changed");
    kit_buf_free(&png);
}

static void test_png_decode_random_damage(void)
{
    Image img = random_image(20, 9);
    KitBuf png = {0};
    char err[200];
    png_encode(img.width, img.height, img.rgb, &png, err, sizeof err);
    for (int k = 0; k < 3000; k++) {
        unsigned char *bad = check_damaged(&rng_state, png.data, png.len, 1 + k % 4);
        Image out;
        if (png_decode(bad, png.len, &out.width, &out.height, &out.rgb, err, sizeof err) == 0)
            image_free(&out);
        free(bad);
    }
    kit_buf_free(&png);
    image_free(&img);
}

/* ---- image files --------------------------------------------------------------------- */

static void test_image_channel(void)
{
    static const struct { double x; int want; } cases[] = {
        { 0, 0 }, { 1, 255 }, { 0.5, 128 }, { -1, 0 }, { 2, 255 }, { NAN, 0 }, { -NAN, 0 },
        { INFINITY, 255 }, { -INFINITY, 0 }, { -0.0, 0 }, { 1.0 / 255, 1 },
        { 0.5 / 255, 1 },                                   /* 0.5 rounds up */
        { 0.49 / 255, 0 }, { 254.5 / 255, 255 }, { 0x1.fffffffffffffp-1, 255 },
    };
    for (int k = 0; k < CHECK_COUNT(cases); k++)
        CHECK_MSG(image_channel(cases[k].x) == cases[k].want, "image_channel(%a) is %d, not %d", cases[k].x,
                  image_channel(cases[k].x), cases[k].want);
}

static void test_image_alloc(void)
{
    Image img;
    char err[200] = "";
    CHECK_EQ_INT(image_alloc(&img, 0, 5, err, sizeof err), -1);
    CHECK(img.rgb == NULL);
    CHECK_STR_CONTAINS(err, "out of range");
    CHECK_EQ_INT(image_alloc(&img, 5, IMAGE_MAX_SIDE + 1, err, sizeof err), -1);
    CHECK_EQ_INT(image_alloc(&img, 4, 2, err, sizeof err), 0);
    CHECK(img.width == 4 && img.height == 2 && img.rgb);
    int black = 1;
    for (int k = 0; k < 24; k++)
        black &= img.rgb[k] == 0;
    CHECK(black);
    image_free(&img);
    CHECK(img.rgb == NULL);
    image_free(&img);              /* twice is harmless */
}

static void test_image_write_read(void)
{
    char dir[512], path[600];
    check_temp_dir(dir, sizeof dir, "png");
    static const char *names[] = {"a.ppm", "b.png", "C.PNG", "d.PpM"};
    Image img = random_image(37, 23);
    for (int k = 0; k < 4; k++) {
        char err[700] = "";
        Image back;
        snprintf(path, sizeof path, "%s/%s", dir, names[k]);
        CHECK_MSG(image_write(&img, path, err, sizeof err) == 0, "%s", err);
        CHECK_MSG(image_read(&back, path, err, sizeof err) == 0, "%s", err);
        CHECK(back.width == 37 && back.height == 23 &&
              memcmp(back.rgb, img.rgb, 3 * 37 * 23) == 0);
        image_free(&back);
        /* overwriting an existing file works too */
        CHECK_MSG(image_write(&img, path, err, sizeof err) == 0, "%s", err);
    }
    CHECK_EQ_INT(check_count_entries(dir), 4);   /* the four, no temporary file */
    /* the file type is read from the content, not the name */
    char from[600], to[600];
    snprintf(from, sizeof from, "%s/b.png", dir);
    snprintf(to, sizeof to, "%s/b.ppm", dir);
    CHECK_EQ_INT(rename(from, to), 0);
    Image back;
    char err[700] = "";
    CHECK_MSG(image_read(&back, to, err, sizeof err) == 0, "%s", err);
    CHECK(back.width == 37 && memcmp(back.rgb, img.rgb, 3 * 37 * 23) == 0);
    image_free(&back);
    /* the PPM is exactly the usual header and the pixels, and a newly
     * written file has ordinary permissions, not mkstemp's 0600 */
    KitBuf ppm = {0};
    kit_buf_append(&ppm, "P6\n37 23\n255\n", 13);
    kit_buf_append(&ppm, img.rgb, 3 * 37 * 23);
    snprintf(path, sizeof path, "%s/a.ppm", dir);
    CHECK(check_file_is(path, ppm.data, ppm.len, -1));
    kit_buf_free(&ppm);
    image_free(&img);
    check_remove_tree(dir);
}

/* Writes bytes to dir/name and returns image_read's result. */
static int read_bytes_as_image(const char *dir, const char *name, const char *bytes, size_t n,
                               Image *img, char *err, size_t errlen)
{
    char path[600];
    if (check_write_in(path, sizeof path, dir, name, bytes, n) != 0)
        return -2;
    return image_read(img, path, err, errlen);
}

static void test_image_read_ppm_variants(void)
{
    char dir[512], err[700];
    check_temp_dir(dir, sizeof dir, "png");
    Image img;
    static const char ok[] = "P6\n# made by hand\n2 # width\n 1\n#maxval next\n255\nABCDEF";
    CHECK_EQ_INT(read_bytes_as_image(dir, "ok.ppm", ok, sizeof ok - 1, &img, err, sizeof err), 0);
    CHECK(img.width == 2 && img.height == 1 && memcmp(img.rgb, "ABCDEF", 6) == 0);
    image_free(&img);
    static const char crlf[] = "P6\r\n1 1\r\n255\n\r\n\t";
    CHECK_EQ_INT(read_bytes_as_image(dir, "crlf.ppm", crlf, sizeof crlf - 1, &img, err, sizeof err), 0);
    CHECK(img.width == 1 && img.rgb[0] == '\r' && img.rgb[1] == '\n' && img.rgb[2] == '\t');
    image_free(&img);
    static const struct { const char *bytes, *want; } bad[] = {
        {"P6\n2 1\n65535\nABCDEFABCDEF", "maximum value 65535"},
        {"P6\n2 1\n255\nABCDE", "truncated"},
        {"P6\n0 1\n255\n", "each side"},
        {"P6\n16385 1\n255\n", "each side"},
        {"P6\n99999999999999999999 1\n255\n", "each side"},
        {"P6\n2 x\n255\nABCDEF", "malformed"},
        {"P62 1\n255\nABCDEF", "malformed"},
        {"P6\n2 1\n255", "malformed"},
        {"P3\n1 1\n255\n1 2 3\n", "P3"},
        {"GIF89a", "not a PNG or binary PPM"},
        {"", "not a PNG or binary PPM"},
    };
    for (int k = 0; k < CHECK_COUNT(bad); k++) {
        err[0] = '\0';
        img.rgb = NULL;
        CHECK_EQ_INT(read_bytes_as_image(dir, "bad.ppm", bad[k].bytes, strlen(bad[k].bytes),
                                         &img, err, sizeof err), -1);
        CHECK_STR_CONTAINS(err, bad[k].want);
        CHECK_STR_CONTAINS(err, "bad.ppm");
        CHECK(img.rgb == NULL);
    }
    char path[600];
    snprintf(path, sizeof path, "%s/missing.png", dir);
    CHECK_EQ_INT(image_read(&img, path, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, path);
    CHECK_EQ_INT(image_read(&img, dir, err, sizeof err), -1);      /* a directory */
    CHECK_STR_CONTAINS(err, dir);
    check_remove_tree(dir);
}

/* image_write of img to dir/name fails, its message naming the path and
 * holding want. */
static void expect_write_error(const Image *img, const char *dir, const char *name, const char *want)
{
    char path[700], err[900] = "";
    snprintf(path, sizeof path, "%s/%s", dir, name);
    CHECK_MSG(image_write(img, path, err, sizeof err) == -1, "%s was written", path);
    CHECK_MSG(strstr(err, path) && strstr(err, want), "%s: the message is \"%s\", not about \"%s\"", path,
              err, want);
}

static void test_image_write_failures(void)
{
    char dir[512], path[700];
    check_temp_dir(dir, sizeof dir, "png");
    Image img = random_image(5, 4);
    /* a directory that does not exist */
    expect_write_error(&img, dir, "no/such/dir/out.png", strerror(ENOENT));
    CHECK_EQ_INT(check_count_entries(dir), 0);
    /* the name is taken by a directory: the rename fails, nothing stays */
    snprintf(path, sizeof path, "%s/taken.png", dir);
    CHECK_EQ_INT(mkdir(path, 0755), 0);
    expect_write_error(&img, dir, "taken.png", "");
    CHECK_EQ_INT(check_count_entries(dir), 1);
    /* unknown extensions */
    static const char *names[] = {"x.jpg", "x", "x.png.bak", "png", "x.pngg", "dir.png/x"};
    for (int k = 0; k < CHECK_COUNT(names); k++)
        expect_write_error(&img, dir, names[k], ".png or .ppm");
    CHECK_EQ_INT(check_count_entries(dir), 1);
    /* a directory we may not write into (skipped where permissions do not
     * apply, as for the superuser) */
    char ro[600];
    snprintf(ro, sizeof ro, "%s/readonly", dir);
    CHECK_EQ_INT(mkdir(ro, 0555), 0);
    snprintf(path, sizeof path, "%s/probe", ro);
    int probe = open(path, O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (probe >= 0) {
        close(probe);
        unlink(path);
    } else {
        expect_write_error(&img, ro, "out.ppm", strerror(EACCES));
        CHECK_EQ_INT(check_count_entries(ro), 0);
    }
    /* an invalid image */
    Image empty = {0, 0, NULL};
    expect_write_error(&empty, dir, "empty.png", "");
    CHECK_EQ_INT(check_count_entries(dir), 2);      /* readonly and taken.png */
    image_free(&img);
    check_remove_tree(dir);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_crc32_known),
    CHECK_TEST(test_adler32_known),
    CHECK_TEST(test_deflate_empty),
    CHECK_TEST(test_deflate_short),
    CHECK_TEST(test_deflate_1mb),
    CHECK_TEST(test_deflate_repetitive_text),
    CHECK_TEST(test_deflate_periodic),
    CHECK_TEST(test_deflate_all_sizes_small),
    CHECK_TEST(test_deflate_sizes_at_the_window),
    CHECK_TEST(test_inflate_by_hand),
    CHECK_TEST(test_inflate_dynamic_block),
    CHECK_TEST(test_inflate_truncated),
    CHECK_TEST(test_inflate_corrupt),
    CHECK_TEST(test_inflate_output_limit),
    CHECK_TEST(test_png_round_trip_random),
    CHECK_TEST(test_png_round_trip_smooth),
    CHECK_TEST(test_png_filter_choice),
    CHECK_TEST(test_png_decode_all_filters_and_types),
    CHECK_TEST(test_png_decode_refuses),
    CHECK_TEST(test_png_decode_random_damage),
    CHECK_TEST(test_image_channel),
    CHECK_TEST(test_image_alloc),
    CHECK_TEST(test_image_write_read),
    CHECK_TEST(test_image_read_ppm_variants),
    CHECK_TEST(test_image_write_failures),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
