/* Reading UTF-8 (tests/tools/utf8.h): every code point against an encoder
 * written from RFC 3629's table, every two- and three-byte sequence and the
 * four-byte sequences' boundaries against RFC 3629's definition (a sequence
 * is valid when it is the shortest encoding of a code point that is not a
 * surrogate and not past U+10FFFF), and the maximal subparts against the
 * examples of the Unicode Standard, chapter 3 (tables 3-8 to 3-11). */
#include "check.h"            /* first: it sets the POSIX feature level */

#include "../tools/utf8.h"

/* RFC 3629, section 3: the bytes of code point cp; returns their number. */
static int encode(unsigned long cp, unsigned char out[4])
{
    if (cp < 0x80) {
        out[0] = (unsigned char)cp;
        return 1;
    }
    if (cp < 0x800) {
        out[0] = (unsigned char)(0xC0 | cp >> 6);
        out[1] = (unsigned char)(0x80 | (cp & 0x3F));
        return 2;
    }
    if (cp < 0x10000) {
        out[0] = (unsigned char)(0xE0 | cp >> 12);
        out[1] = (unsigned char)(0x80 | (cp >> 6 & 0x3F));
        out[2] = (unsigned char)(0x80 | (cp & 0x3F));
        return 3;
    }
    out[0] = (unsigned char)(0xF0 | cp >> 18);
    out[1] = (unsigned char)(0x80 | (cp >> 12 & 0x3F));
    out[2] = (unsigned char)(0x80 | (cp >> 6 & 0x3F));
    out[3] = (unsigned char)(0x80 | (cp & 0x3F));
    return 4;
}

/* Whether the n bytes of s are the shortest encoding of a code point that
 * is not a surrogate and at most U+10FFFF (RFC 3629, sections 3 and 4):
 * their bits read as the lead byte says, encoded again, give s back. */
static int well_formed(const unsigned char *s, int n)
{
    static const unsigned char mark[5] = { 0, 0, 0xC0, 0xE0, 0xF0 }, mask[5] = { 0, 0, 0xE0, 0xF0, 0xF8 };
    if ((s[0] & mask[n]) != mark[n])
        return 0;
    unsigned long cp = s[0] & (unsigned char)~mask[n];
    for (int k = 1; k < n; k++) {
        if ((s[k] & 0xC0) != 0x80)
            return 0;
        cp = cp << 6 | (s[k] & 0x3F);
    }
    unsigned char again[4];
    if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) || encode(cp, again) != n)
        return 0;
    return memcmp(again, s, (size_t)n) == 0;
}

/* Every code point from U+0080 up, surrogates left out, is read back whole,
 * with or without bytes after it; cut short it is not. */
static void test_every_code_point(void)
{
    int wrong = 0;
    for (unsigned long cp = 0x80; cp <= 0x10FFFF; cp++) {
        if (cp >= 0xD800 && cp <= 0xDFFF)
            continue;
        unsigned char s[5];
        int n = encode(cp, s);
        s[n] = 'z';
        int ok = utf8_sequence(s, (size_t)n) == n && utf8_sequence(s, (size_t)n + 1) == n
                 && utf8_code_point(s, n) == cp && utf8_sequence(s, (size_t)n - 1) == -(n - 1);
        if (!ok && wrong++ < 5)
            CHECK_MSG(0, "U+%04lX: length %d, read as U+%04lX, cut short %d", cp,
                      utf8_sequence(s, (size_t)n), utf8_code_point(s, n), utf8_sequence(s, (size_t)n - 1));
    }
    CHECK_EQ_INT(wrong, 0);
}

/* Every sequence of two bytes with a lead of 0x80 to 0xDF, every one of
 * three with a lead of 0xE0 to 0xEF, and four-byte sequences at the
 * boundaries of each byte's ranges: valid exactly when RFC 3629 says so. */
static void test_every_short_sequence(void)
{
    int wrong = 0;
    for (unsigned a = 0x80; a <= 0xEF; a++)
        for (unsigned b = 0; b <= 0xFF; b++)
            for (unsigned c = 0; c <= (a < 0xE0 ? 0 : 0xFF); c++) {
                unsigned char s[3] = { (unsigned char)a, (unsigned char)b, (unsigned char)c };
                int n = a < 0xE0 ? 2 : 3, got = utf8_sequence(s, (size_t)n);
                int want = well_formed(s, n) ? n : 0;
                if ((got > 0 ? got : 0) != want && wrong++ < 5)
                    CHECK_MSG(0, "%02X %02X %02X: %d, want %d", a, b, c, got, want);
            }
    static const unsigned char edge[] = { 0x00, 0x41, 0x7F, 0x80, 0x8F, 0x90, 0x9F, 0xA0, 0xBF, 0xC0, 0xFF };
    for (unsigned a = 0xF0; a <= 0xFF; a++)
        for (size_t i = 0; i < sizeof edge; i++)
            for (size_t j = 0; j < sizeof edge; j++)
                for (size_t k = 0; k < sizeof edge; k++) {
                    unsigned char s[4] = { (unsigned char)a, edge[i], edge[j], edge[k] };
                    int got = utf8_sequence(s, 4), want = well_formed(s, 4) ? 4 : 0;
                    if ((got > 0 ? got : 0) != want && wrong++ < 5)
                        CHECK_MSG(0, "%02X %02X %02X %02X: %d, want %d", a, edge[i], edge[j], edge[k], got, want);
                }
    CHECK_EQ_INT(wrong, 0);
}

/* The code points a byte string is read as, one U+FFFD for each maximal
 * subpart; returns their number. */
static int read_all(const unsigned char *s, size_t n, unsigned long *out)
{
    int count = 0;
    for (size_t k = 0; k < n;) {
        int len = s[k] < 0x80 ? 1 : utf8_sequence(s + k, n - k);
        out[count++] = len == 1 ? s[k] : len > 0 ? utf8_code_point(s + k, len) : 0xFFFD;
        k += (size_t)(len > 0 ? len : -len);
    }
    return count;
}

/* The Unicode Standard, chapter 3, section 3.9: the examples of U+FFFD
 * substitution of maximal subparts (tables 3-8 to 3-11). */
static void test_standard_examples(void)
{
    static const struct {
        const char *what, *bytes;
        int nwant;
        unsigned long want[10];
    } ex[] = {
        { "non-shortest forms (3-8)", "\xC0\xAF\xE0\x80\xBF\xF0\x81\x82\x41", 9,
          { 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0x41 } },
        { "surrogates (3-9)", "\xED\xA0\x80\xED\xBF\xBF\xED\xAF\x41", 9,
          { 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0x41 } },
        { "other ill-formed sequences (3-10)", "\xF4\x91\x92\x93\xFF\x41\x80\xBF\x42", 9,
          { 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0x41, 0xFFFD, 0xFFFD, 0x42 } },
        { "truncated sequences (3-11)", "\xE1\x80\xE2\xF0\x91\x92\xF1\xBF\x41", 5,
          { 0xFFFD, 0xFFFD, 0xFFFD, 0xFFFD, 0x41 } },
        { "the section's first example", "\x61\xF1\x80\x80\xE1\x80\xC2\x62\x80\x63\x80\xBF\x64", 10,
          { 0x61, 0xFFFD, 0xFFFD, 0xFFFD, 0x62, 0xFFFD, 0x63, 0xFFFD, 0xFFFD, 0x64 } },
    };
    for (size_t e = 0; e < sizeof ex / sizeof ex[0]; e++) {
        unsigned long got[16];
        int n = read_all((const unsigned char *)ex[e].bytes, strlen(ex[e].bytes), got);
        int same = n == ex[e].nwant;
        for (int k = 0; same && k < n; k++)
            same = got[k] == ex[e].want[k];
        CHECK_MSG(same, "%s: read as %d code points", ex[e].what, n);
    }
}

static const CheckTest tests[] = {
    CHECK_TEST(test_every_code_point),
    CHECK_TEST(test_every_short_sequence),
    CHECK_TEST(test_standard_examples),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
