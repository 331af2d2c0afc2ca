/* Base64 (tests/tools/base64.h): RFC 4648's own test vectors, round trips,
 * and the text the strict decoder must refuse. */
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
        char err[128];
        size_t len = 99;
        unsigned char *back = base64_decode(coded, strlen(coded), &len, err, sizeof err);
        CHECK_MSG(back != NULL, "decode(\"%s\"): %s", coded, err);
        if (back) {
            CHECK_EQ_INT(len, strlen(plain));
            CHECK(memcmp(back, plain, len) == 0);
            CHECK_EQ_INT(back[len], 0);
        }
        free(back);
    }
}

/* Every byte value, and every length from 0 to 300 of pseudo-random bytes,
 * comes back unchanged. */
static void test_round_trips(void)
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
        CHECK_EQ_INT(strlen(coded), clen);
        for (size_t k = 0; k < clen; k++)
            CHECK(strchr("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/=", coded[k]));
        char err[128];
        size_t len = 0;
        unsigned char *back = base64_decode(coded, clen, &len, err, sizeof err);
        CHECK_MSG(back && len == n && memcmp(back, data, n) == 0, "round trip of %zu bytes", n);
        free(back);
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

static void test_refuses_what_is_not_canonical(void)
{
    static const char *const bad[] = {
        "Zg=",          /* not a multiple of 4 */
        "Zg",           /* no padding */
        "Zh==",         /* bits set past the data (h = 100001) */
        "Zm9=",         /* bits set past the data (9 = 111101) */
        "Z===",         /* three padding characters */
        "=Zg=",         /* padding first */
        "Zg==Zg==",     /* padding before the end */
        "Zm 9",         /* a space */
        "Zm-9",         /* the URL alphabet's "-" */
        "Zm_9",         /* and its "_" */
        "Zm9v\n",       /* a line break */
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char err[128] = "";
        size_t len = 0;
        unsigned char *back = base64_decode(bad[k], strlen(bad[k]), &len, err, sizeof err);
        CHECK_MSG(back == NULL, "decode(\"%s\") was accepted", bad[k]);
        CHECK_MSG(err[0] != '\0', "decode(\"%s\") gave no reason", bad[k]);
        free(back);
    }
}

static const CheckTest tests[] = {
    CHECK_TEST(test_rfc4648_vectors),
    CHECK_TEST(test_round_trips),
    CHECK_TEST(test_bit_order),
    CHECK_TEST(test_refuses_what_is_not_canonical),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
