/* The compressor's hash chains keep positions in 32 bits and move them
 * down every DF_REBASE bytes (labs/kit/zlib.c, DfMatcher).  At its real
 * value, a gigabyte, no test input reaches a move; here the compressor is
 * compiled again with moves every 32 KiB (the least that keeps every
 * dropped position outside the 32 KiB window) under other names, and its
 * output must be the kit's, byte for byte, and inflate back. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include <stdint.h>

#define DF_REBASE ((size_t)1 << 15)
#define kit_buf_init rebase_buf_init
#define kit_buf_free rebase_buf_free
#define kit_buf_reserve rebase_buf_reserve
#define kit_buf_append rebase_buf_append
#define kit_buf_push rebase_buf_push
#define kit_crc32 rebase_crc32
#define kit_adler32 rebase_adler32
#define kit_deflate rebase_deflate
#define kit_inflate rebase_inflate
#define kit_zlib_compress rebase_zlib_compress
#define kit_zlib_uncompress rebase_zlib_uncompress
#include "../../labs/kit/zlib.c"
#undef kit_buf_init
#undef kit_buf_free
#undef kit_buf_reserve
#undef kit_buf_append
#undef kit_buf_push
#undef kit_crc32
#undef kit_adler32
#undef kit_deflate
#undef kit_inflate
#undef kit_zlib_compress
#undef kit_zlib_uncompress
/* The kit's own, from its library: zlib.h's names again. */
int kit_deflate(const void *in, size_t n, KitBuf *out);
int kit_inflate(const void *in, size_t n, size_t max_out, KitBuf *out, size_t *used, char *err,
                size_t errlen);
void kit_buf_free(KitBuf *b);

static uint32_t rng_state = 2463534242u;

static uint32_t rng_next(void)
{
    return check_xorshift32(&rng_state);
}

/* n bytes of text with repeats near and far, random stretches and long
 * runs: matches at every distance up to the window's, across the moves. */
static unsigned char *mixed_input(size_t n)
{
    unsigned char *p = malloc(n);
    for (size_t k = 0; k < n;) {
        uint32_t r = rng_next();
        size_t len = 1 + r % 300;
        if (len > n - k)
            len = n - k;
        switch (r >> 29) {
        case 0: case 1:                                   /* a copy from up to 40 KiB back */
            if (k > 0) {
                size_t back = 1 + rng_next() % (k < 40000 ? k : 40000);
                for (size_t i = 0; i < len; i++)
                    p[k + i] = p[k + i - back];
                break;
            }
            /* fall through */
        case 2:                                           /* random bytes */
            for (size_t i = 0; i < len; i++)
                p[k + i] = (unsigned char)(rng_next() >> 24);
            break;
        case 3:                                           /* a run */
            memset(p + k, (int)(r & 0xFF), len);
            break;
        default: {                                        /* words */
            static const char *const words[] = { "ray ", "sphere ", "plane ", "pixel ", "eye " };
            for (size_t i = 0; i < len; i++)
                p[k + i] = (unsigned char)words[(k + i) / 7 % 5][(k + i) % 4];
            break;
        }
        }
        k += len;
    }
    return p;
}

static void test_moves_change_nothing(void)
{
    static const size_t sizes[] = { 1, 1000, 65535, 65536, 65537, 200000, 1000003 };
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        size_t n = sizes[s];
        unsigned char *in = mixed_input(n);
        KitBuf moved = {0}, kit = {0}, back = {0};
        char err[200] = "";
        CHECK_EQ_INT(rebase_deflate(in, n, &moved), 0);
        CHECK_EQ_INT(kit_deflate(in, n, &kit), 0);
        CHECK_MSG(moved.len == kit.len && memcmp(moved.data, kit.data, kit.len) == 0,
                  "%zu bytes: %zu compressed with moves, %zu without", n, moved.len, kit.len);
        int rc = kit_inflate(moved.data, moved.len, n, &back, NULL, err, sizeof err);
        CHECK_MSG(rc == 0 && back.len == n && memcmp(back.data, in, n) == 0, "%zu bytes: %s", n, err);
        kit_buf_free(&moved);
        kit_buf_free(&kit);
        kit_buf_free(&back);
        free(in);
    }
}

static const CheckTest tests[] = {
    CHECK_TEST(test_moves_change_nothing),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
