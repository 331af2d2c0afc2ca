/* Base64 (tests/tools/base64.h): RFC 4648's own test vectors, and every
 * length checked against the encoding worked out a bit at a time. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include "../tools/base64.h"

/* RFC 4648, section 10: the encodings of "", "f", "fo", ..., "foobar". */
static const char *const vectors[][2] = {
    { "", "" }, { "f", "Zg==" }, { "fo", "Zm8=" }, { "foo", "Zm9v" },
    { "foob", "Zm9vYg==" }, { "fooba", "Zm9vYmE=" }, { "foobar", "Zm9vYmFy" },
};

static void test_rfc4648_vectors(void)
{
    for (size_t k = 0; k < sizeof vectors / sizeof vectors[0]; k++) {
        const char *plain = vectors[k][0], *coded = vectors[k][1];
        char out[32];
        CHECK_EQ_INT(base64_encoded_length(strlen(plain)), strlen(coded));
        CHECK_EQ_INT(base64_encode(plain, strlen(plain), out), strlen(coded));
        CHECK_MSG(strcmp(out, coded) == 0, "encode(\"%s\") is \"%s\", want \"%s\"", plain, out, coded);
    }
}

/* Character k of the encoding of data[0 .. n-1] as RFC 4648 section 4
 * defines it, bit by bit: the bits 6k .. 6k + 5 of the data, most
 * significant first and zero past its end; '=' once the data is used up. */
static char spec_char(const unsigned char *data, size_t n, size_t k)
{
    static const char abc[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    if (6 * k >= 8 * n)
        return '=';
    int v = 0;
    for (size_t bit = 6 * k; bit < 6 * k + 6; bit++)
        v = 2 * v + (bit < 8 * n && (data[bit / 8] >> (7 - bit % 8)) & 1);
    return abc[v];
}

/* Every byte value, and every length from 0 to 300 of pseudo-random bytes,
 * encoded as spec_char says. */
static void test_every_length(void)
{
    unsigned char data[300];
    unsigned long state = 12345;
    for (int k = 0; k < 300; k++) {
        state = state * 1103515245u + 12345u;
        data[k] = (unsigned char)(k < 256 ? (unsigned long)k : (state >> 16) & 0xFF);
    }
    for (size_t n = 0; n <= sizeof data; n++) {
        char coded[404];
        size_t clen = base64_encode(data, n, coded);
        CHECK_EQ_INT(clen, base64_encoded_length(n));
        /* whole groups of four, the fewest that hold 8n bits */
        CHECK(clen % 4 == 0 && 6 * clen >= 8 * n && (clen == 0 || 6 * (clen - 4) < 8 * n));
        CHECK_EQ_INT(strlen(coded), clen);
        size_t k = 0;
        while (k < clen && coded[k] == spec_char(data, n, k))
            k++;
        CHECK_MSG(k == clen, "%zu bytes: character %zu is '%c', want '%c'", n, k, coded[k],
                  spec_char(data, n, k));
    }
}

/* Six bits a character, most significant first: "TWFu" is "Man" (the
 * example of the encoding's usual description, worked by hand:
 * M = 77 = 010011 01, a = 97 = 0110 0001, n = 110 = 01 101110, so the
 * sextets are 19 22 5 46: T W F u). */
static void test_bit_order(void)
{
    char out[8];
    base64_encode("Man", 3, out);
    CHECK(strcmp(out, "TWFu") == 0);
    base64_encode("\xff\xff\xff", 3, out);
    CHECK(strcmp(out, "////") == 0);
    base64_encode("\xfb\xef", 2, out);        /* 111110 111110 1111(00) */
    CHECK(strcmp(out, "++8=") == 0);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_rfc4648_vectors),
    CHECK_TEST(test_every_length),
    CHECK_TEST(test_bit_order),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
