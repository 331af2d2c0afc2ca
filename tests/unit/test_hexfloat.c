/* The runner protocol's hex floats (tests/grader/hexfloat.h): the text of
 * values worked out by hand, strtod reading every text back to the same
 * bits, and, with the GNU C library, printf's "%a" text itself.  And the
 * two fast readers, hexfloat_read and the test files' decimal_read
 * (tests/grader/decimal.h), each against strtod itself: the same bits and
 * the same end, for every text, theirs and others.  And the kit's shortest
 * decimal text (labs/kit/numtext.c), in which the grader shows students
 * their cases' numbers and writes the test files and JSON. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include "../grader/hexfloat.h"
#include "../grader/decimal.h"
#include "kit/numtext.h"

#include <float.h>

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
    for (int k = 0; k < CHECK_COUNT(known); k++) {
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
        uint64_t bits = check_xorshift64(&s);
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

/* reader(text) against strtod(text): the same bits (any NaN for a NaN,
 * with its sign) and the same end.  1 when they agree. */
static int same_as_strtod(double (*reader)(const char *, char **), const char *text, char *why,
                          size_t len)
{
    char *end_fast = NULL, *end_libc = NULL;
    double fast = reader(text, &end_fast), libc = strtod(text, &end_libc);
    int same = isnan(libc) ? isnan(fast) && signbit(fast) == signbit(libc)
                           : memcmp(&fast, &libc, sizeof fast) == 0;
    if (same && end_fast == end_libc)
        return 1;
    snprintf(why, len, "\"%s\": read %a ending at %td, strtod %a ending at %td", text, fast,
             end_fast - text, libc, end_libc - text);
    return 0;
}

#define SAME(reader, text)                                                      \
    do {                                                                        \
        char why_[300];                                                         \
        CHECK_MSG(same_as_strtod(reader, text, why_, sizeof why_), "%s", why_); \
    } while (0)

/* hexfloat_read: every text hexfloat_format writes, and texts it never
 * writes (left to strtod), each read as strtod reads it. */
static void test_hexfloat_read(void)
{
    static const char *const texts[] = {
        "0x0p+0", "-0x0p+0", "0x1p+0", "0x1.8p+1", "0x1.999999999999ap-4", "0x1.fffffffffffffp+1023",
        "-0x1.fffffffffffffp+1023", "0x1p-1022", "0x0.8p-1022", "0x0.0000000000001p-1022",
        "0x0.fffffffffffffp-1022", "inf", "-inf", "nan", "-nan", "0x1p+0 1", "0x1.8p+1\n",
        "  0x1p+3", "\t-0x1p+3", "0x1p+0|", "0x1p+0x", "0x1p+0.5",
        /* not its text: strtod's answer */
        "0x1.8P+1", "0X1p+0", "0x1.8p1", "0x1.8", "0x1.8p", "0x1.8p+", "0x1.p+0", "0x2p+0",
        "0x1.00000000000000p+0", "0x1.0000000000000p+0", "0x1p+1024", "0x1p-1023", "0x0.8p-1021",
        "0x0p+1", "0x0.0p-1022", "0x1p+00001", "0x1p+99999", "0x1.gp+0", "0x1.Ap+0", "+0x1p+0",
        "\n0x1p+0", "infinity", "-Infinity", "INF", "NAN", "nan(1)", "1.5", "", "-", "x", "0x",
        "-0x", "0xp+0",
    };
    for (int k = 0; k < CHECK_COUNT(texts); k++)
        SAME(hexfloat_read, texts[k]);
    /* Random values, each in its own text and in a line of three. */
    uint64_t s = 0x2545f4914f6cdd1du;
    int wrong = 0;
    char first[300] = "";
    for (long i = 0; i < 200000; i++) {
        check_xorshift64(&s);
        uint64_t bits = i % 3 == 1 ? s & ~(UINT64_C(0x7ff) << 52) : s;
        double x;
        memcpy(&x, &bits, sizeof x);
        char line[3 * HEXFLOAT_MAX + 4];
        size_t n = hexfloat_format(line, x);
        line[n++] = ' ';
        n += hexfloat_format(line + n, -x);
        line[n++] = ' ';
        hexfloat_format(line + n, x / 3);
        char *end = line;
        for (int j = 0; j < 3; j++) {
            char why[300];
            if (!same_as_strtod(hexfloat_read, end, why, sizeof why) && wrong++ == 0)
                snprintf(first, sizeof first, "%s", why);
            strtod(end, &end);
        }
    }
    CHECK_MSG(wrong == 0, "%d texts read unlike strtod: the first, %s", wrong, first);
}

/* decimal_read: the test files' numbers ("%.17g"), short decimals of every
 * form, and texts it leaves to strtod, each read as strtod reads it. */
static void test_decimal_read(void)
{
    static const char *const texts[] = {
        "0", "-0", "0.53", "-1", "0.1", "1e22", "-1e22", "1e-22", "1e23", "1e-23", "4e22",
        "9007199254740992", "9007199254740993", "9007199254740991e-22", "12345678901234567",
        "123456789012345678", "0.000000000000000000000000001", "00012", "1e-0", "1E5", "1e+5",
        "  7", "\t-7.5e-3", "+5", ".5", "5.", "-.5e1", "1e", "1e+", "1e-", "1ex", "0x10", "-0x10",
        "inf", "nan", "", "-", ".", "-.", "+", "1.5e99999", "0e99999", "-0.000", "1.5.5", "1..5",
        "0.4811252243246881", "-0.6735753140545633", "0.32092845501278366", "2e-09", "1 2",
        "3|4", "\n5", "5\n", "1e308", "1e-308", "4.9406564584124654e-324", "1.7976931348623157e308",
        "0.30000000000000004", "100000000000000000000000", "1000000000000000000000",
    };
    for (int k = 0; k < CHECK_COUNT(texts); k++)
        SAME(decimal_read, texts[k]);
    /* Random numbers in the forms a test file may hold. */
    static const char *const forms[] = { "%.17g", "%.15g", "%.6g", "%.3f", "%.1e", "%g", "%.0f" };
    uint64_t s = 0x9e3779b97f4a7c15u;
    int wrong = 0;
    char first[300] = "";
    for (long i = 0; i < 200000; i++) {
        check_xorshift64(&s);
        double x;
        if (i % 2) {                    /* any finite double */
            uint64_t bits = s;
            if (((bits >> 52) & 0x7ff) == 0x7ff)
                continue;
            memcpy(&x, &bits, sizeof x);
        } else {                        /* an ordinary size: a scene's numbers */
            x = ldexp((double)(s >> 11), -53) * pow(10, (double)((int)(s & 31) - 12));
            if (s & 32)
                x = -x;
        }
        char text[400];
        snprintf(text, sizeof text, forms[i % 7], x);
        char why[300];
        if (!same_as_strtod(decimal_read, text, why, sizeof why) && wrong++ == 0)
            snprintf(first, sizeof first, "%s", why);
    }
    CHECK_MSG(wrong == 0, "%d texts read unlike strtod: the first, %s", wrong, first);
}

/* kit_shortest_double (labs/kit/numtext.c), in which the grader shows
 * students their cases' numbers: values whose text is known, then random
 * doubles, short decimals among them: each text reads back as the same
 * double, and, for a normal double, no %g of fewer digits does (every
 * precision from 1 up is tried here, where the function halves the range). */
static void test_shortest(void)
{
    static const struct {
        double x;
        const char *text;
    } known[] = {
        { 0.48, "0.48" }, { 0.6, "0.6" }, { -0.64, "-0.64" }, { 3.0, "3" }, { 0.0, "0" },
        { -0.0, "-0" }, { 0.1 + 0.2, "0.30000000000000004" }, { 1.0 / 3, "0.3333333333333333" },
        { 1e300, "1e+300" }, { DBL_MAX, "1.7976931348623157e+308" }, { 5e-324, "5e-324" },
        { INFINITY, "inf" }, { -INFINITY, "-inf" }, { NAN, "nan" },
    };
    char b[40];
    for (int k = 0; k < CHECK_COUNT(known); k++)
        CHECK_MSG(strcmp(kit_shortest_double(b, sizeof b, known[k].x), known[k].text) == 0,
                  "%a: \"%s\", not \"%s\"", known[k].x, b, known[k].text);
    uint64_t s = 0x2545f4914f6cdd1du;
    int wrong = 0, longer = 0;
    char first[600] = "";
    for (long i = 0; i < 200000; i++) {
        check_xorshift64(&s);
        double x;
        if (i % 2) {                                   /* a decimal of 1 to 12 digits */
            snprintf(b, sizeof b, "%.*e", (int)(s % 12), ldexp((double)(s >> 11), -53) * 10);
            x = strtod(b, NULL) * pow(10, (double)((int)((s >> 5) % 40) - 20));
        } else {
            uint64_t bits = s;
            memcpy(&x, &bits, sizeof x);
            if (!isfinite(x) || fpclassify(x) == FP_SUBNORMAL)
                continue;
        }
        kit_shortest_double(b, sizeof b, x);
        if (strtod(b, NULL) != x && wrong++ == 0)
            snprintf(first, sizeof first, "%a written \"%s\"", x, b);
        char sig[40];                        /* its digits, the zeros around them off */
        int digits = 0;
        for (const char *c = b; *c && *c != 'e'; c++)
            if ((*c >= '1' && *c <= '9') || (*c == '0' && digits > 0))
                sig[digits++] = *c;
        while (digits > 0 && sig[digits - 1] == '0')
            digits--;
        char fewer[400];
        for (int p = 1; p < digits; p++) {
            snprintf(fewer, sizeof fewer, "%.*g", p, x);
            if (strtod(fewer, NULL) == x && longer++ == 0)
                snprintf(first, sizeof first, "%a written \"%s\", but \"%s\" reads back too", x, b,
                         fewer);
        }
    }
    CHECK_MSG(wrong == 0 && longer == 0, "%d not read back, %d longer than needed; the first: %s", wrong,
              longer, first);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_known_values),
    CHECK_TEST(test_random_round_trips),
    CHECK_TEST(test_hexfloat_read),
    CHECK_TEST(test_decimal_read),
    CHECK_TEST(test_shortest),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
