/*
 * The grader's scan of the names a stage file gives the preprocessor
 * (tests/grader/include_scan.c): every way of writing a directive that the
 * compiler accepts is seen through, devices, pipes and system files are
 * refused wherever a name leads, and ordinary files are let through,
 * whatever their comments and strings say.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include <sys/stat.h>
#include "../grader/include_scan.h"

static char dir[64];          /* the compile directory: raytracer.h, a FIFO, links */

/* 1 when the scan refuses text (compiled in dir), 0 when it passes. */
static int scan(const char *text)
{
    char why[400] = "";
    int r = include_scan(text, strlen(text), dir, why, sizeof why);
    CHECK_MSG(r == 0 || why[0], "refused without a reason: %s", text);
    return r;
}

#define REFUSED(text) CHECK_MSG(scan(text) == 1, "not refused: %s", text)
#define PASSED(text) CHECK_MSG(scan(text) == 0, "refused: %s", text)

static void setup(void)
{
    if (check_temp_dir(dir, sizeof dir, "scan") != 0)
        return;
    char path[128];
    snprintf(path, sizeof path, "%s/raytracer.h", dir);
    check_write_file(path, "", 0);
    snprintf(path, sizeof path, "%s/fifo", dir);
    CHECK(mkfifo(path, 0600) == 0);
    snprintf(path, sizeof path, "%s/zero", dir);
    CHECK(symlink("/dev/zero", path) == 0);
    snprintf(path, sizeof path, "%s/sub", dir);
    CHECK(mkdir(path, 0700) == 0);
}

static void teardown(void)
{
    if (check_remove_tree(dir) != 0)
        printf("    (could not remove %s)\n", dir);
}

/* Devices and system files by name, however the name is spelt. */
static void test_devices_by_name(void)
{
    setup();
    REFUSED("#include \"/dev/zero\"\n");
    REFUSED("#include </dev/random>\n");
    REFUSED("#include \"/dev/stdin\"\n");
    REFUSED("#include \"/dev/fd/0\"\n");
    REFUSED("#include \"/proc/self/fd/0\"\n");     /* portable: only a name */
    REFUSED("#include \"/sys/kernel/notes\"\n");
    REFUSED("#include \"//dev//zero\"\n");
    REFUSED("#include \"/dev/./zero\"\n");
    REFUSED("#include </./dev/urandom>\n");
    teardown();
}

/* What the name leads to: a symbolic link to a device, a pipe, a folder. */
static void test_what_names_lead_to(void)
{
    setup();
    char text[256];
    snprintf(text, sizeof text, "#include \"%s/zero\"\n", dir);
    REFUSED(text);
    REFUSED("#include \"zero\"\n");                      /* relative: from the compile directory */
    REFUSED("#include \"fifo\"\n");
    REFUSED("#include <fifo>\n");
    REFUSED("#include \"sub\"\n");
    REFUSED("#include \"../../../../../../../../dev/zero\"\n");
    REFUSED("#include \"sub/../raytracer.h\"\n");        /* any .. at all */
    teardown();
}

/* The compile directory is wherever TMPDIR puts it, /dev/shm too (a file
 * system in memory, where an instructor may grade for speed): a header in
 * it is the grader's copy, not a system file, and a link in it to a
 * device, a pipe and a folder are still refused.  (Once, every header
 * there was refused as "a device or a system file", and every part
 * scored 0.) */
static void test_compile_dir_under_dev(void)
{
    struct stat st;
    if (stat("/dev/shm", &st) != 0 || !S_ISDIR(st.st_mode) ||   /* portable: skipped */
        access("/dev/shm", W_OK | X_OK) != 0) {
        printf("    skipped: no /dev/shm to write in on this system\n");
        return;
    }
    setenv("TMPDIR", "/dev/shm", 1);     /* this test's own process */
    setup();
    CHECK_MSG(strncmp(dir, "/dev/shm/", 9) == 0, "the compile directory is %s", dir);
    PASSED("#include \"raytracer.h\"\n#include <math.h>\n");
    PASSED("#include \"./raytracer.h\"\n");
    REFUSED("#include \"zero\"\n");
    REFUSED("#include \"fifo\"\n");
    REFUSED("#include \"sub\"\n");
    REFUSED("#include \"/dev/zero\"\n");
    REFUSED("#include \"../raytracer.h\"\n");
    teardown();
}

/* path_below, which both the scan and the grader's test for a file of the
 * kit use: component by component. */
static void test_path_below(void)
{
    CHECK(path_below("/a/b", "/a/b"));
    CHECK(path_below("/a/b/c.h", "/a/b"));
    CHECK(path_below("/a/b/c.h", "/a/b/"));
    CHECK(!path_below("/a/bc", "/a/b"));
    CHECK(!path_below("/a", "/a/b"));
    CHECK(path_below("/anything", "/"));
    CHECK(!path_below("/a/b", ""));
}

/* Every way of writing the directive that gcc and clang accept. */
static void test_directive_spellings(void)
{
    setup();
    REFUSED("  #  include \"/dev/zero\"\n");
    REFUSED("\t#include\t\"/dev/zero\"\n");
    REFUSED("#include_next \"/dev/zero\"\n");
    REFUSED("#import \"/dev/zero\"\n");
    REFUSED("#embed \"/dev/zero\"\n");
    REFUSED("%:include \"/dev/zero\"\n");                /* digraph */
    REFUSED("?\?=include \"/dev/zero\"\n");               /* trigraph (-std=c11 has them) */
    REFUSED("#inc\\\nlude \"/dev/zero\"\n");             /* line splices */
    REFUSED("#include \"/dev/\\\nzero\"\n");
    REFUSED("#include \"/dev/?\?/\nzero\"\n");            /* a trigraph splice */
    REFUSED("#inc\\  \nlude \"/dev/zero\"\n");           /* blanks before the newline */
    REFUSED("/* c */ # /* c */ include /* c */ \"/dev/zero\"\n");
    REFUSED("/* a comment\n   over lines */ #include \"/dev/zero\"\n");
    REFUSED("int x;\n#include \"/dev/zero\"\r\n");
    /* A UTF-8 byte order mark, as some Windows editors save it: the
     * compiler skips it, so the first line is a directive. */
    REFUSED("\xEF\xBB\xBF#include \"/dev/zero\"\n");
    REFUSED("\xEF\xBB\xBF  #include \"/dev/zero\"\n");
    REFUSED("#if __has_include(\"fifo\")\n#endif\n");
    REFUSED("#if defined(X) || __has_include ( <fifo> )\n#endif\n");
    REFUSED("#pragma GCC dependency \"fifo\"\n");
    REFUSED("_Pragma(\"GCC dependency \\\"fifo\\\"\")\n");
    REFUSED("__asm__(\".incbin \\\"/dev/zero\\\"\");\n");
    /* The assembler's directives that read a file, however the strings
     * spell them: split in adjacent literals (over lines and comments, with
     * a prefix), spelt with escapes, and .include. */
    REFUSED("__asm__(\".inc\" \"bin \\\"/etc/passwd\\\"\");\n");
    REFUSED("__asm__(\".i\"\n /* x */ \"ncb\" u8\"in \\\"/etc/passwd\\\"\");\n");
    REFUSED("__asm__(\"\\x2eincbin \\\"/etc/passwd\\\"\");\n");
    REFUSED("__asm__(\"\\056inc\\142in \\\"/etc/passwd\\\"\");\n");
    REFUSED("__asm__(\".include \\\"/etc/passwd\\\"\");\n");
    REFUSED("__asm__(\".incl\" \"ude \\\"/etc/passwd\\\"\");\n");
    teardown();
}

/* What only looks like a directive, and ordinary headers, pass. */
static void test_passes(void)
{
    setup();
    PASSED("#include \"raytracer.h\"\n#include <math.h>\n#include <stdio.h>\n");
    PASSED("// #include \"/dev/zero\"\n");
    PASSED("/* #include \"/dev/zero\" */\n");
    PASSED("const char *s = \"#include \\\"/dev/zero\\\"\";\n");
    PASSED("#define Z \"/dev/zero\"\n");                /* names only in #include are read */
    PASSED("#error \"/dev/zero\"\n");
    /* Strings that are not joined (a token between them) spell nothing. */
    PASSED("const char *a = \".inc\", *b = \"bin\";\n");
    PASSED("const char *a[] = { \".incl\", \"ude\" };\n");
    PASSED("#include \"no-such-header.h\"\n");          /* the compiler says it is missing */
    PASSED("#include Z\n");                             /* a macro: left to the compiler's limits */
    PASSED("char c = '\"'; /* \" */\n#include \"raytracer.h\"\n");
    PASSED("");
    teardown();
}

/* A line that is not a directive because something comes before the #. */
static void test_not_at_line_start(void)
{
    setup();
    PASSED("int a; # include \"/dev/zero\"\n");
    PASSED("x /* c */ #include \"/dev/zero\"\n");
    teardown();
}

/* The judge (the grader's: a file of the kit) sees each name however the
 * directive is spelt, and nothing the compiler would not follow. */
static const char *refuse_ref(const char *name, void *ctx)
{
    (*(int *)ctx)++;
    return strcmp(name, "/k/ref.c") == 0 ? "which is part of the grader" : NULL;
}

static int judged(const char *text, int *seen)
{
    char why[400] = "";
    *seen = 0;
    return include_scan_judged(text, strlen(text), "/nonexistent", refuse_ref, seen, why, sizeof why);
}

static void test_judge_every_spelling(void)
{
    static const char *const spellings[] = {
        "  #  include   \"/k/ref.c\"\n",
        "#/* a comment */include /* another */ \"/k/ref.c\"\n",
        "#inc\\\nlude \"/k/r\\\nef.c\"\n",
        "#inc\\\r\nlude \"/k/ref.c\"\r\n",
        "%:include \"/k/ref.c\"\n",
        "\?\?=include \"/k/ref.c\"\n",
        "int a; /* a comment\n spanning lines */ \n#include </k/ref.c>\n",
    };
    for (int k = 0; k < (int)(sizeof spellings / sizeof *spellings); k++) {
        int seen;
        CHECK_MSG(judged(spellings[k], &seen) == 1, "spelling %d not refused", k);
    }
    static const char *const others[] = {
        "// #include \"/k/ref.c\"\n",
        "/* #include \"/k/ref.c\" */\n",
        "const char *s = \"#include \\\"/k/ref.c\\\"\";\n",
        "// a comment \\\n#include \"/k/ref.c\"\n",
        "#include \"other.h\"\n",
    };
    for (int k = 0; k < (int)(sizeof others / sizeof *others); k++) {
        int seen;
        CHECK_MSG(judged(others[k], &seen) == 0, "case %d refused", k);
        CHECK_MSG(seen == (k == 4), "case %d: the judge saw %d names", k, seen);
    }
}

/* A kit header named by a path from the student's folders is refused with
 * the way to name it. */
static void test_header_by_path(void)
{
    setup();
    char why[400] = "";
    const char *text = "#include \"../labs/raytracer.h\"\n";
    CHECK(include_scan(text, strlen(text), dir, why, sizeof why) == 1);
    CHECK_MSG(strstr(why, "write #include \"raytracer.h\", as the skeleton does") != NULL, "%s", why);
    text = "#include \"../secret.h\"\n";
    why[0] = '\0';
    CHECK(include_scan(text, strlen(text), dir, why, sizeof why) == 1);
    CHECK_MSG(strstr(why, "climbs out") && !strstr(why, "skeleton"), "%s", why);
    teardown();
}

static const CheckTest tests[] = {
    CHECK_TEST(test_judge_every_spelling), CHECK_TEST(test_header_by_path),
    CHECK_TEST(test_devices_by_name), CHECK_TEST(test_what_names_lead_to), CHECK_TEST(test_directive_spellings),
    CHECK_TEST(test_compile_dir_under_dev), CHECK_TEST(test_path_below),
    CHECK_TEST(test_passes),          CHECK_TEST(test_not_at_line_start),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
