/*
 * Whole files written and read back (labs/kit/savefile.c): kit_save_file
 * leaves the bytes or nothing, with the mode asked for, kit_load_file gives
 * back any bytes, NULs included, and refuses what is not a regular file of
 * at most max bytes.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include <sys/stat.h>
#include "kit/savefile.h"

static char dir[64];

/* Bytes of every value, a NUL among them, written and read back exactly. */
static void test_round_trip(void)
{
    check_temp_dir(dir, sizeof dir, "savefile");
    unsigned char bytes[300];
    for (int k = 0; k < 300; k++)
        bytes[k] = (unsigned char)(k * 7);
    char path[128], err[200];
    snprintf(path, sizeof path, "%s/object.o", dir);
    CHECK_EQ_INT(kit_save_file(path, bytes, sizeof bytes, err, sizeof err), 0);
    size_t n = 0;
    char *got = kit_load_file(path, 1 << 20, &n);
    CHECK(got != NULL);
    if (got) {
        CHECK_EQ_INT(n, 300);
        CHECK(memcmp(got, bytes, sizeof bytes) == 0);
        CHECK_EQ_INT(got[n], 0);                    /* a NUL after them */
        free(got);
    }
    /* An empty file is a file: an empty buffer, not NULL. */
    CHECK_EQ_INT(kit_save_file(path, "", 0, err, sizeof err), 0);
    got = kit_load_file(path, 1 << 20, &n);
    CHECK(got != NULL && n == 0);
    free(got);
    CHECK(check_remove_tree(dir) == 0);
}

/* More than max bytes, a directory, a missing file: NULL. */
static void test_refused(void)
{
    check_temp_dir(dir, sizeof dir, "savefile");
    char path[128], err[200];
    snprintf(path, sizeof path, "%s/big", dir);
    CHECK_EQ_INT(kit_save_file(path, "0123456789", 10, err, sizeof err), 0);
    size_t n = 77;
    CHECK(kit_load_file(path, 9, &n) == NULL);
    CHECK_EQ_INT(n, 77);                            /* untouched */
    char *ten = kit_load_file(path, 10, &n);
    CHECK(ten != NULL && n == 10);
    free(ten);
    CHECK(kit_load_file(dir, 1 << 20, &n) == NULL);
    snprintf(path, sizeof path, "%s/missing", dir);
    CHECK(kit_load_file(path, 1 << 20, &n) == NULL);
    CHECK(check_remove_tree(dir) == 0);
}

/* A save that cannot be made says why and leaves nothing beside it. */
static void test_save_fails_cleanly(void)
{
    check_temp_dir(dir, sizeof dir, "savefile");
    char path[128], err[200] = "";
    snprintf(path, sizeof path, "%s/no/such/dir/file", dir);
    CHECK(kit_save_file(path, "x", 1, err, sizeof err) != 0);
    CHECK_MSG(strstr(err, path) != NULL, "the message '%s' names the file", err);
    char cmd[200];
    snprintf(cmd, sizeof cmd, "[ -z \"$(ls -A %s)\" ]", dir);
    CHECK(system(cmd) == 0);
    CHECK(check_remove_tree(dir) == 0);
}

/* A file gets the mode asked for, less the umask: 0666 unless told. */
static void test_mode(void)
{
    check_temp_dir(dir, sizeof dir, "savefile");
    char path[128], err[200];
    snprintf(path, sizeof path, "%s/file", dir);
    CHECK_EQ_INT(kit_save_file(path, "x", 1, err, sizeof err), 0);
    CHECK(check_file_is(path, "x", 1, -1));
    mode_t mask = umask(022);
    CHECK_EQ_INT(kit_save_file_mode(path, "y", 1, 0640, err, sizeof err), 0);
    umask(mask);
    CHECK(check_file_is(path, "y", 1, 0640));
    CHECK(check_remove_tree(dir) == 0);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_round_trip), CHECK_TEST(test_refused), CHECK_TEST(test_save_fails_cleanly),
    CHECK_TEST(test_mode),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
