/* The runner protocol's hex floats (tests/grader/hexfloat.h): the text of
 * values worked out by hand, strtod reading every text back to the same
 * bits, and, with the GNU C library, printf's "%a" text itself. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include "../grader/hexfloat.h"

#include <float.h>
#include <math.h>
#include <stdint.h>

/* Values and their text, from the format's definition: sign, "0x", the
 * leading digit (1, or 0 for zero and subnormals), the 52-bit fraction in
 * 13 hex digits less trailing zeros, "p" and the binary exponent. */
static void test_known_values(void)
{
    static const struct {
        double x;
        const char *text;
    } known[] = {
        { 0.0, "0x0p+0" }, { -0.0, "-0x0p+0" }, { 1.0, "0x1p+0" }, { -1.0, "-0x1p+0" },
        { 0.5, "0x1p-1" }, { 3.0, "0x1.8p+1" }, { 0.1, "0x1.999999999999ap-4" },
        { 1.0 + DBL_EPSILON, "0x1.0000000000001p+0" }, { 1024.0, "0x1p+10" },
        { DBL_MAX, "0x1.fffffffffffffp+1023" }, { -DBL_MAX, "-0x1.fffffffffffffp+1023" },
        { DBL_MIN, "0x1p-1022" }, { DBL_MIN / 2, "0x0.8p-1022" },
        { DBL_MIN - DBL_MIN * DBL_EPSILON, "0x0.fffffffffffffp-1022" },
        { 4.9406564584124654e-324, "0x0.0000000000001p-1022" },
        { INFINITY, "inf" }, { -INFINITY, "-inf" },
    };
    for (size_t k = 0; k < sizeof known / sizeof known[0]; k++) {
        char out[HEXFLOAT_MAX];
        size_t n = hexfloat_format(out, known[k].x);
        CHECK_MSG(strcmp(out, known[k].text) == 0 && n == strlen(known[k].text),
                  "%.17g written \"%s\" (%zu), want \"%s\"", known[k].x, out, n, known[k].text);
    }
    char out[HEXFLOAT_MAX];
    hexfloat_format(out, NAN);
    CHECK_MSG(strcmp(out, "nan") == 0 || strcmp(out, "-nan") == 0, "NaN written \"%s\"", out);
    CHECK(isnan(strtod(out, NULL)));
}

/* Random bit patterns of every kind (normal, subnormal, zero, large), each
 * read back to the same bits; with glibc, the same text as printf's %a. */
static void test_random_round_trips(void)
{
    uint64_t s = 0x9e3779b97f4a7c15u;
    int wrong = 0, unlike_printf = 0;
    char first[200] = "";
    for (long i = 0; i < 400000; i++) {
        s ^= s << 13, s ^= s >> 7, s ^= s << 17;
        uint64_t bits = s;
        if (i % 4 == 1)
            bits &= ~(UINT64_C(0x7ff) << 52);                        /* subnormal or zero */
        else if (i % 4 == 2)
            bits &= UINT64_C(0xfff0000000000000) | (s >> 40);        /* trailing zeros */
        if (((bits >> 52) & 0x7ff) == 0x7ff)
            continue;                                                /* inf and NaN above */
        double x;
        memcpy(&x, &bits, sizeof x);
        char out[HEXFLOAT_MAX];
        size_t n = hexfloat_format(out, x);
        double back = strtod(out, NULL);
        if (n != strlen(out) || n >= HEXFLOAT_MAX || memcmp(&back, &x, sizeof x) != 0) {
            if (wrong++ == 0)
                snprintf(first, sizeof first, "%a written \"%s\", read back %a", x, out, back);
        }
#ifdef __GLIBC__
        char want[64];
        snprintf(want, sizeof want, "%a", x);
        if (strcmp(out, want) != 0 && unlike_printf++ == 0)
            snprintf(first, sizeof first, "\"%s\" where printf writes \"%s\"", out, want);
#endif
    }
    CHECK_MSG(wrong == 0, "%d values did not read back: the first, %s", wrong, first);
    CHECK_MSG(unlike_printf == 0, "%d texts unlike printf's: the first, %s", unlike_printf, first);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_known_values),
    CHECK_TEST(test_random_round_trips),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
