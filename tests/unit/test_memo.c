/*
 * What grade --all keeps of each distinct stage file (tests/grader/memo.c):
 * the same bytes find what was kept, other bytes never do, even when they
 * land on an entry of the same hash, and a kept file reads back whole.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include "../grader/memo.h"

static char dir[64];          /* the memo */
static char work[64];         /* the stage files */

static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static void setup(void)
{
    check_temp_dir(dir, sizeof dir, "memo");
    check_temp_dir(work, sizeof work, "memowork");
}

static void cleanup(void)
{
    if (check_remove_tree(dir) != 0 || check_remove_tree(work) != 0)
        printf("    (could not remove %s, %s)\n", dir, work);
}

static int entries(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += e->d_name[0] != '.';
    if (d)
        closedir(d);
    return n;
}

/* A file seen for the first time makes an empty entry; the same bytes
 * again (another path) find it, with what was kept; other bytes, or the
 * same bytes of another stage or kind, do not. */
static void test_same_bytes_found(void)
{
    setup();
    char a[128], b[128], c[128], obj[128], got[1200];
    snprintf(a, sizeof a, "%s/a.c", work);
    snprintf(b, sizeof b, "%s/b.c", work);
    snprintf(c, sizeof c, "%s/c.c", work);
    snprintf(obj, sizeof obj, "%s/a.o", work);
    write_file(a, "int f(void) { return 1; }\n");
    write_file(b, "int f(void) { return 1; }\n");
    write_file(c, "int f(void) { return 2; }\n");
    write_file(obj, "OBJECT BYTES\n");

    MemoEntry e;
    CHECK(memo_find(dir, "part1_image_plane", "pic", a, &e));
    CHECK(!e.found);
    CHECK_EQ_INT(memo_keep_text(&e, "messages", "a.c:1: warning: hello\n"), 0);
    CHECK_EQ_INT(memo_keep(&e, "object.o", obj), 0);

    MemoEntry again;
    CHECK(memo_find(dir, "part1_image_plane", "pic", b, &again));
    CHECK(again.found);
    CHECK(strcmp(again.dir, e.dir) == 0);
    char *said = memo_read_text(&again, "messages");
    CHECK(said && strcmp(said, "a.c:1: warning: hello\n") == 0);
    free(said);
    memo_path(&again, "object.o", got, sizeof got);
    char *bytes = NULL;
    FILE *f = fopen(got, "rb");
    if (f) {
        bytes = calloc(1, 64);
        if (fread(bytes, 1, 63, f) == 0)
            CHECK_MSG(0, "empty object");
        fclose(f);
    }
    CHECK(bytes && strcmp(bytes, "OBJECT BYTES\n") == 0);
    free(bytes);

    MemoEntry other;
    CHECK(memo_find(dir, "part1_image_plane", "pic", c, &other));
    CHECK(!other.found);
    CHECK(strcmp(other.dir, e.dir) != 0);
    CHECK(memo_find(dir, "part2_pixel_coordinates", "pic", b, &other));
    CHECK(!other.found);
    CHECK(memo_find(dir, "part1_image_plane", "o", b, &other));
    CHECK(!other.found);
    CHECK_EQ_INT(entries(), 4);
    cleanup();
}

/* Two files whose hashes agree are still told apart: an entry whose kept
 * bytes differ from the file's (as a file of the same hash would have
 * left it) is passed over for the next. */
static void test_same_hash_other_bytes(void)
{
    setup();
    char a[128], path[1300];
    snprintf(a, sizeof a, "%s/a.c", work);
    write_file(a, "int g(void) { return 3; }\n");
    MemoEntry e;
    CHECK(memo_find(dir, "part2_pixel_coordinates", "o", a, &e));
    CHECK(!e.found);
    snprintf(path, sizeof path, "%s/source", e.dir);
    write_file(path, "int g(void) { return 4; }\n");    /* another file, the same hash */
    MemoEntry next;
    CHECK(memo_find(dir, "part2_pixel_coordinates", "o", a, &next));
    CHECK(!next.found);
    CHECK(strcmp(next.dir, e.dir) != 0);
    size_t n = strlen(e.dir);
    CHECK(n > 2 && strncmp(next.dir, e.dir, n - 1) == 0 && e.dir[n - 1] == '0' && next.dir[n - 1] == '1');
    MemoEntry third;
    CHECK(memo_find(dir, "part2_pixel_coordinates", "o", a, &third));
    CHECK(third.found);
    CHECK(strcmp(third.dir, next.dir) == 0);
    cleanup();
}

/* No memo, or a file that cannot be read: nothing is kept or found. */
static void test_no_memo(void)
{
    setup();
    char a[128];
    snprintf(a, sizeof a, "%s/a.c", work);
    write_file(a, "int h;\n");
    MemoEntry e;
    CHECK(!memo_find(NULL, "part1_image_plane", "o", a, &e));
    CHECK(!memo_find("", "part1_image_plane", "o", a, &e));
    CHECK(!memo_find(dir, "part1_image_plane", "o", "/nonexistent/file.c", &e));
    CHECK_EQ_INT(e.dir[0], 0);
    CHECK(memo_keep_text(&e, "messages", "x") != 0);
    CHECK_EQ_INT(entries(), 0);
    cleanup();
}

/* Entries beginning with '.': the new entries' names before they are
 * renamed into place, which must not be left behind. */
static int dot_entries(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        n += e->d_name[0] == '.' && strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return n;
}

/* A grading that finds an entry another is still compiling waits for its
 * object (memo_wait); it stops waiting when the other says it is done
 * without one, or when the time is up. */
static void test_wait(void)
{
    setup();
    char a[128], obj[128];
    snprintf(a, sizeof a, "%s/a.c", work);
    snprintf(obj, sizeof obj, "%s/a.o", work);
    write_file(a, "int w(void) { return 5; }\n");
    write_file(obj, "OBJECT\n");
    MemoEntry maker, finder;
    CHECK(memo_find(dir, "part1_image_plane", "o", a, &maker) && !maker.found);
    CHECK(memo_find(dir, "part1_image_plane", "o", a, &finder) && finder.found);
    CHECK_EQ_INT(dot_entries(), 0);

    /* Nothing yet, nothing coming: false once the time is up. */
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    CHECK(!memo_wait(&finder, 0.05));
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double waited = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    CHECK_MSG(waited >= 0.04 && waited < 2, "waited %g s for 0.05", waited);

    /* The object kept by another process a little later: true. */
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        struct timespec pause = { 0, 60000000 };
        nanosleep(&pause, NULL);
        _exit(memo_keep(&maker, "object.o", obj) == 0 ? 0 : 1);
    }
    CHECK(pid > 0);
    CHECK(memo_wait(&finder, 10));
    int status = 1;
    if (pid > 0)
        waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    CHECK(memo_wait(&finder, 0));            /* there now: at once */

    /* Done without an object (the file did not build): false at once. */
    char b[128];
    snprintf(b, sizeof b, "%s/b.c", work);
    write_file(b, "int w(void) { return; }\n");
    MemoEntry failed, later;
    CHECK(memo_find(dir, "part1_image_plane", "o", b, &failed) && !failed.found);
    CHECK_EQ_INT(memo_keep_text(&failed, "done", ""), 0);
    CHECK(memo_find(dir, "part1_image_plane", "o", b, &later) && later.found);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    CHECK(!memo_wait(&later, 10));
    clock_gettime(CLOCK_MONOTONIC, &t1);
    waited = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    CHECK_MSG(waited < 1, "waited %g s for a file that did not build", waited);
    CHECK_EQ_INT(dot_entries(), 0);
    cleanup();
}

static const CheckTest tests[] = {
    CHECK_TEST(test_same_bytes_found), CHECK_TEST(test_same_hash_other_bytes), CHECK_TEST(test_no_memo),
    CHECK_TEST(test_wait),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
