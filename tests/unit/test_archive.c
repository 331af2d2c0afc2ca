/* The ZIP archives of tests/tools/archive.h. */
#include "check.h"            /* first: it sets the POSIX feature level */


#include "../../labs/kit/zlib.h"
#include "../tools/archive.h"

/* ---- helpers -------------------------------------------------------------------- */

static uint32_t rng_state = 2463534242u;

static uint32_t le32(const unsigned char *p)
{
    return p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static unsigned le16(const unsigned char *p)
{
    return p[0] | (unsigned)p[1] << 8;
}

/* A path of exactly len bytes made of 9-letter directories and a file
 * name. */
static void long_path(char *out, size_t len)
{
    for (size_t k = 0; k < len; k++)
        out[k] = k % 10 == 9 ? '/' : (char)('a' + k % 10);
    out[len - 1] = 'z';                   /* never end on a '/' */
    out[len] = '\0';
}

typedef struct {
    char long_name[151];
    unsigned char *big;                  /* 300 kB, half random, half text */
    size_t big_size;
} Fixture;

/* Fills a with the standard entries: a directory, an empty file, a 300 kB
 * file, a 150-byte path, an executable, "123456789". */
static void add_standard_entries(Archive *a, Fixture *f)
{
    char err[300] = "";
    f->big_size = 300000;
    f->big = malloc(f->big_size);
    check_random_bytes(&rng_state, f->big, f->big_size / 2);
    for (size_t k = f->big_size / 2; k < f->big_size; k++)
        f->big[k] = (unsigned char)("abcab\n"[k % 6]);
    long_path(f->long_name, 150);
    CHECK_EQ_INT(archive_add_dir(a, "docs", 0755, err, sizeof err), 0);
    CHECK_EQ_INT(archive_add_file(a, "docs/empty.txt", "", 0, 0644, err, sizeof err), 0);
    CHECK_EQ_INT(archive_add_file(a, "data/big.bin", f->big, f->big_size, 0600, err, sizeof err), 0);
    CHECK_EQ_INT(archive_add_file(a, f->long_name, "deep", 4, 0644, err, sizeof err), 0);
    CHECK_EQ_INT(archive_add_file(a, "run_autograder", "#!/bin/sh\nexit 0\n", 17, 0755, err, sizeof err), 0);
    CHECK_EQ_INT(archive_add_file(a, "digits.txt", "123456789", 9, 0444, err, sizeof err), 0);
    CHECK_MSG(err[0] == '\0', "%s", err);
}

/* Checks that b holds exactly the standard entries, in order. */
static void check_standard_entries(const Archive *b, const Fixture *f)
{
    CHECK_EQ_INT(b->count, 6);
    if (b->count != 6)
        return;
    const ArchiveEntry *e = b->entries;
    CHECK(strcmp(e[0].path, "docs") == 0 && e[0].is_dir && e[0].mode == 0755);
    CHECK(strcmp(e[1].path, "docs/empty.txt") == 0 && !e[1].is_dir && e[1].size == 0 && e[1].mode == 0644);
    CHECK(strcmp(e[2].path, "data/big.bin") == 0 && e[2].size == f->big_size && e[2].mode == 0600);
    CHECK(e[2].size == f->big_size && memcmp(e[2].data, f->big, f->big_size) == 0);
    CHECK(strcmp(e[3].path, f->long_name) == 0 && e[3].size == 4 && memcmp(e[3].data, "deep", 4) == 0);
    CHECK(strcmp(e[4].path, "run_autograder") == 0 && e[4].mode == 0755 && e[4].size == 17);
    CHECK(strcmp(e[5].path, "digits.txt") == 0 && e[5].mode == 0444 &&
          e[5].size == 9 && memcmp(e[5].data, "123456789", 9) == 0);
}

/* Encodes a, decodes the bytes into b (which the caller frees). */
static void encode_decode(const Archive *a, KitBuf *bytes, Archive *b)
{
    char err[300] = "";
    CHECK_MSG(archive_encode(a, bytes, err, sizeof err) == 0, "encode: %s", err);
    int rc = archive_decode(b, bytes->data, bytes->len, err, sizeof err);
    CHECK_MSG(rc == 0, "decode: %s", err);
}

/* ---- round trips ------------------------------------------------------------------------ */

static void test_zip_round_trip(void)
{
    Archive a, b;
    Fixture f;
    KitBuf bytes = {0};
    archive_init(&a);
    add_standard_entries(&a, &f);
    encode_decode(&a, &bytes, &b);
    check_standard_entries(&b, &f);
    /* the same entries give the same bytes */
    KitBuf again = {0};
    char err[300];
    archive_encode(&a, &again, err, sizeof err);
    CHECK(again.len == bytes.len && memcmp(again.data, bytes.data, bytes.len) == 0);
    kit_buf_free(&again);
    archive_free(&b);
    archive_free(&a);
    kit_buf_free(&bytes);
    free(f.big);
}

static void test_empty_archive(void)
{
    Archive a, b;
    KitBuf bytes = {0};
    archive_init(&a);
    encode_decode(&a, &bytes, &b);
    CHECK_EQ_INT(b.count, 0);
    CHECK_EQ_INT(bytes.len, 22);         /* just the end record */
    archive_free(&b);
    kit_buf_free(&bytes);
}

/* ---- the bytes of a ZIP ------------------------------------------------------------- */

static void test_zip_layout(void)
{
    Archive a;
    Fixture f;
    KitBuf z = {0};
    char err[300];
    archive_init(&a);
    add_standard_entries(&a, &f);
    CHECK_EQ_INT(archive_encode(&a, &z, err, sizeof err), 0);
    const unsigned char *p = z.data;
    /* end of central directory: last 22 bytes */
    const unsigned char *end = p + z.len - 22;
    CHECK_EQ_INT(le32(end), 0x06054b50u);
    CHECK_EQ_INT(le16(end + 10), 6);
    uint32_t cd_size = le32(end + 12), cd_off = le32(end + 16);
    CHECK_EQ_INT(cd_off + cd_size, z.len - 22);
    /* walk the central directory */
    size_t at = cd_off;
    int found_digits = 0, found_exec = 0;
    for (int k = 0; k < 6 && at + 46 <= z.len; k++) {
        const unsigned char *c = p + at;
        CHECK_EQ_INT(le32(c), 0x02014b50u);
        CHECK_EQ_INT(le16(c + 4) >> 8, 3);              /* made by Unix */
        CHECK_EQ_INT(le16(c + 12), 0);                   /* 00:00:00 */
        CHECK_EQ_INT(le16(c + 14), (40 << 9) | (1 << 5) | 1);   /* 2020-01-01 */
        unsigned nlen = le16(c + 28), method = le16(c + 10);
        uint32_t local = le32(c + 42);
        /* the local header repeats the CRC and sizes */
        CHECK_EQ_INT(le32(p + local), 0x04034b50u);
        CHECK_EQ_INT(le32(p + local + 14), le32(c + 16));
        CHECK_EQ_INT(le32(p + local + 18), le32(c + 20));
        CHECK_EQ_INT(le32(p + local + 22), le32(c + 24));
        CHECK(memcmp(p + local + 30, c + 46, nlen) == 0);
        if (nlen == 10 && memcmp(c + 46, "digits.txt", 10) == 0) {
            found_digits = 1;
            CHECK_EQ_INT(le32(c + 16), 0xCBF43926u);     /* CRC-32 of "123456789" */
            CHECK_EQ_INT(le32(c + 24), 9);
            CHECK_EQ_INT(le32(c + 38) >> 16, 0100444);
        }
        if (nlen == 14 && memcmp(c + 46, "run_autograder", 14) == 0) {
            found_exec = 1;
            CHECK_EQ_INT(le32(c + 38) >> 16, 0100755);   /* a regular file, rwxr-xr-x */
        }
        if (nlen == 5 && memcmp(c + 46, "docs/", 5) == 0)
            CHECK_EQ_INT(le32(c + 38), (0040755u << 16) | 0x10u);
        if (nlen == 12 && memcmp(c + 46, "data/big.bin", 12) == 0) {
            CHECK_EQ_INT(method, 8);                     /* half of it compresses */
            CHECK(le32(c + 20) < 200000);
        }
        if (nlen == 14 && memcmp(c + 46, "docs/empty.txt", 14) == 0)
            CHECK(method == 0 && le32(c + 20) == 0 && le32(c + 16) == 0);
        at += 46 + nlen + le16(c + 30) + le16(c + 32);
    }
    CHECK_EQ_INT(at, cd_off + cd_size);
    CHECK(found_digits && found_exec);
    /* random data is stored, not deflated */
    Archive r;
    archive_init(&r);
    unsigned char noise[5000];
    check_random_bytes(&rng_state, noise, sizeof noise);
    archive_add_file(&r, "noise", noise, sizeof noise, 0644, err, sizeof err);
    KitBuf rz = {0};
    archive_encode(&r, &rz, err, sizeof err);
    CHECK_EQ_INT(le16(rz.data + 8), 0);
    CHECK_EQ_INT(rz.len, 30 + 5 + 5000 + 46 + 5 + 22);
    kit_buf_free(&rz);
    archive_free(&r);
    archive_free(&a);
    kit_buf_free(&z);
    free(f.big);
}

/* ---- refusing bad paths and bad data ---------------------------------------------------- */

static void test_bad_paths_refused_when_adding(void)
{
    static const char *bad[] = {"", "/abs", "a/../b", "..", "../a", "a/..", "a//b", "./a",
                                "a/.", "a/", "a\\b"};
    Archive a;
    char err[300];
    archive_init(&a);
    for (int k = 0; k < CHECK_COUNT(bad); k++) {
        CHECK_MSG(!archive_path_ok(bad[k]), "\"%s\" accepted", bad[k]);
        CHECK_EQ_INT(archive_add_file(&a, bad[k], "x", 1, 0644, err, sizeof err), -1);
        CHECK_EQ_INT(archive_add_dir(&a, bad[k], 0755, err, sizeof err), -1);
    }
    CHECK(archive_path_ok("a/b..c/..d/.e"));
    CHECK(archive_path_ok("x"));
    CHECK_EQ_INT(a.count, 0);
    CHECK_EQ_INT(archive_add_file(&a, "same", "x", 1, 0644, err, sizeof err), 0);
    CHECK_EQ_INT(archive_add_file(&a, "same", "y", 1, 0644, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "twice");
    archive_free(&a);
}

/* Replaces every occurrence of from by to (same length) in b. */
static int replace_bytes(KitBuf *b, const char *from, const char *to)
{
    size_t n = strlen(from);
    int count = 0;
    for (size_t k = 0; k + n <= b->len; k++)
        if (memcmp(b->data + k, from, n) == 0) {
            memcpy(b->data + k, to, n);
            count++;
        }
    return count;
}

static void test_zip_refuses_unsafe_paths(void)
{
    static const char *evil[] = {"../evil", "/x/evil", "x/../ev", "x//evil"};
    for (int k = 0; k < CHECK_COUNT(evil); k++) {
        Archive a, b;
        KitBuf z = {0};
        char err[300] = "";
        archive_init(&a);
        archive_add_file(&a, "xx/evil", "bad", 3, 0644, err, sizeof err);
        archive_encode(&a, &z, err, sizeof err);
        CHECK_EQ_INT(replace_bytes(&z, "xx/evil", evil[k]), 2);    /* local and central */
        CHECK_EQ_INT(archive_decode(&b, z.data, z.len, err, sizeof err), -1);
        CHECK_STR_CONTAINS(err, "unsafe");
        CHECK_EQ_INT(b.count, 0);
        archive_free(&a);
        kit_buf_free(&z);
    }
}

static void test_damaged_archive(void)
{
    Archive a, b;
    KitBuf bytes = {0};
    char err[300];
    archive_init(&a);
    archive_add_dir(&a, "d", 0755, err, sizeof err);
    archive_add_file(&a, "d/text", "hello hello hello hello hello", 29, 0644, err, sizeof err);
    archive_add_file(&a, "d/raw", "q", 1, 0755, err, sizeof err);
    archive_encode(&a, &bytes, err, sizeof err);
    /* every truncation is refused */
    for (size_t n = 0; n < bytes.len; n++) {
        CHECK_MSG(archive_decode(&b, bytes.data, n, err, sizeof err) == -1,
                  "%zu of %zu bytes accepted", n, bytes.len);
        CHECK_EQ_INT(b.count, 0);
    }
    /* random damage: an error or an archive, never a crash */
    for (int k = 0; k < 4000; k++) {
        unsigned char *bad = check_damaged(&rng_state, bytes.data, bytes.len, 1 + k % 3);
        if (archive_decode(&b, bad, bytes.len, err, sizeof err) == 0)
            archive_free(&b);
        free(bad);
    }
    archive_free(&a);
    kit_buf_free(&bytes);
}

/* A stored entry whose data changed: the CRC catches it; and bytes that are
 * no archive. */
static void test_changed_data(void)
{
    Archive a, b;
    KitBuf z = {0};
    char err[300];
    archive_init(&a);
    archive_add_file(&a, "f", "abcdefgh", 8, 0644, err, sizeof err);
    archive_encode(&a, &z, err, sizeof err);
    CHECK_EQ_INT(replace_bytes(&z, "abcdefgh", "abcdefgX"), 1);
    CHECK_EQ_INT(archive_decode(&b, z.data, z.len, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "CRC");
    CHECK_EQ_INT(archive_decode(&b, "hello", 5, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "not a ZIP");
    archive_free(&a);
    kit_buf_free(&z);
}

/* ---- on disk: add_tree, save, load, extract ---------------------------------------------- */

/* The tree below dir/src that add_tree reads: each path, what its file
 * holds (NULL: a directory) and its mode. */
static const struct { const char *path, *text; int mode; } tree[] = {
    { "run_autograder", "#!/bin/sh\necho ok\n", 0755 }, { "lib", NULL, 0750 },
    { "lib/b.h", "int b;\n", 0600 }, { "lib/a.c", "int a;\n", 0644 },
    { "empty", NULL, 0755 }, { "Zero.txt", "", 0644 },
};

/* Makes dir/src holding tree, each mode exactly. */
static void make_source_tree(const char *dir, char *src, size_t size)
{
    char p[1024];
    snprintf(src, size, "%s/src", dir);
    CHECK_EQ_INT(mkdir(src, 0755), 0);
    for (int k = 0; k < CHECK_COUNT(tree); k++) {
        snprintf(p, sizeof p, "%s/%s", src, tree[k].path);
        if (tree[k].text)
            check_write_file(p, tree[k].text, strlen(tree[k].text));
        else
            CHECK_EQ_INT(mkdir(p, 0700), 0);
        CHECK_EQ_INT(chmod(p, (mode_t)tree[k].mode), 0);
    }
}

/* Checks that the tree below root is tree. */
static void check_source_tree(const char *root)
{
    char p[1024];
    struct stat st;
    for (int k = 0; k < CHECK_COUNT(tree); k++) {
        snprintf(p, sizeof p, "%s/%s", root, tree[k].path);
        if (tree[k].text)
            CHECK_MSG(check_file_is(p, tree[k].text, strlen(tree[k].text), tree[k].mode), "%s", p);
        else
            CHECK_MSG(stat(p, &st) == 0 && S_ISDIR(st.st_mode) && (int)(st.st_mode & 0777) == tree[k].mode,
                      "%s", p);
    }
}

static void test_tree_save_load_extract(void)
{
    char dir[512], src[600], out[700], dest[700], err[1500] = "";
    check_temp_dir(dir, sizeof dir, "archive");
    make_source_tree(dir, src, sizeof src);
    Archive a, b;
    archive_init(&a);
    CHECK_MSG(archive_add_tree(&a, src, err, sizeof err) == 0, "%s", err);
    /* sorted by name, directories before their contents */
    static const char *order[] = {"Zero.txt", "empty", "lib", "lib/a.c", "lib/b.h", "run_autograder"};
    CHECK_EQ_INT(a.count, 6);
    for (size_t k = 0; k < 6 && k < a.count; k++)
        CHECK_MSG(strcmp(a.entries[k].path, order[k]) == 0, "entry %zu is %s, want %s", k,
                  a.entries[k].path, order[k]);
    snprintf(out, sizeof out, "%s/out.zip", dir);
    CHECK_MSG(archive_save(&a, out, err, sizeof err) == 0, "%s", err);
    CHECK_MSG(archive_load(&b, out, err, sizeof err) == 0, "%s", err);
    CHECK_EQ_INT(b.count, a.count);
    snprintf(dest, sizeof dest, "%s/dest/deeper", dir);
    CHECK_MSG(archive_extract(&b, dest, err, sizeof err) == 0, "%s", err);
    check_source_tree(dest);
    /* extracting again over the same files works, read-only files included */
    CHECK_MSG(archive_extract(&b, dest, err, sizeof err) == 0, "%s", err);
    check_source_tree(dest);
    archive_free(&a);
    archive_free(&b);
    check_remove_tree(dir);
}

static void test_add_tree_refuses_links(void)
{
    char dir[512], p[700], q[700], err[1500] = "";
    check_temp_dir(dir, sizeof dir, "archive");
    snprintf(p, sizeof p, "%s/file", dir);
    check_write_file(p, "x", 1);
    snprintf(q, sizeof q, "%s/link", dir);
    CHECK_EQ_INT(symlink("file", q), 0);
    Archive a;
    archive_init(&a);
    CHECK_EQ_INT(archive_add_tree(&a, dir, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "link");
    CHECK_STR_CONTAINS(err, q);
    archive_free(&a);
    snprintf(p, sizeof p, "%s/missing", dir);
    CHECK_EQ_INT(archive_add_tree(&a, p, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, p);
    check_remove_tree(dir);
}

static void test_extract_refuses_symlinks_in_dest(void)
{
    char dir[512], dest[700], outside[700], link[800], err[1500] = "";
    check_temp_dir(dir, sizeof dir, "archive");
    snprintf(dest, sizeof dest, "%s/dest", dir);
    snprintf(outside, sizeof outside, "%s/outside", dir);
    CHECK_EQ_INT(mkdir(dest, 0755), 0);
    CHECK_EQ_INT(mkdir(outside, 0755), 0);
    snprintf(link, sizeof link, "%s/sub", dest);
    CHECK_EQ_INT(symlink(outside, link), 0);
    Archive a;
    archive_init(&a);
    archive_add_file(&a, "sub/planted", "x", 1, 0644, err, sizeof err);
    CHECK_EQ_INT(archive_extract(&a, dest, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, "symbolic link");
    archive_free(&a);
    /* a link in the place of the file itself is replaced, not followed */
    archive_init(&a);
    archive_add_file(&a, "sub", "data", 4, 0644, err, sizeof err);
    CHECK_EQ_INT(archive_extract(&a, dest, err, sizeof err), 0);
    struct stat st;
    CHECK(lstat(link, &st) == 0 && S_ISREG(st.st_mode));
    archive_free(&a);
    CHECK_EQ_INT(check_count_entries(outside), 0);
    check_remove_tree(dir);
}

static void test_save_failure_leaves_nothing(void)
{
    char dir[512], path[700], err[1500] = "";
    check_temp_dir(dir, sizeof dir, "archive");
    Archive a;
    archive_init(&a);
    archive_add_file(&a, "f", "x", 1, 0644, err, sizeof err);
    snprintf(path, sizeof path, "%s/no/such/out.zip", dir);
    CHECK_EQ_INT(archive_save(&a, path, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, path);
    snprintf(path, sizeof path, "%s/taken", dir);
    CHECK_EQ_INT(mkdir(path, 0755), 0);
    CHECK_EQ_INT(archive_save(&a, path, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, path);
    CHECK_EQ_INT(check_count_entries(dir), 1);     /* just "taken" */
    snprintf(path, sizeof path, "%s/missing.zip", dir);
    Archive b;
    CHECK_EQ_INT(archive_load(&b, path, err, sizeof err), -1);
    CHECK_STR_CONTAINS(err, path);
    archive_free(&a);
    check_remove_tree(dir);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_zip_round_trip),
    CHECK_TEST(test_empty_archive),
    CHECK_TEST(test_zip_layout),
    CHECK_TEST(test_bad_paths_refused_when_adding),
    CHECK_TEST(test_zip_refuses_unsafe_paths),
    CHECK_TEST(test_damaged_archive),
    CHECK_TEST(test_changed_data),
    CHECK_TEST(test_tree_save_load_extract),
    CHECK_TEST(test_add_tree_refuses_links),
    CHECK_TEST(test_extract_refuses_symlinks_in_dest),
    CHECK_TEST(test_save_failure_leaves_nothing),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
