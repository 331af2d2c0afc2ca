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

/* Texts the scan refuses.  Devices and system files by name, however the
 * name is spelt; what a name leads to (a symbolic link to a device, a
 * pipe, a folder, any ..); and every way of writing the directive that gcc
 * and clang accept. */
static const char *const refused[] = {
    "#include \"/dev/zero\"\n",
    "#include </dev/random>\n",
    "#include \"/dev/stdin\"\n",
    "#include \"/dev/fd/0\"\n",
    "#include \"/proc/self/fd/0\"\n",     /* portable: only a name */
    "#include \"/sys/kernel/notes\"\n",
    "#include \"//dev//zero\"\n",
    "#include \"/dev/./zero\"\n",
    "#include </./dev/urandom>\n",
    "#include \"zero\"\n",                 /* relative: from the compile directory */
    "#include \"fifo\"\n",
    "#include <fifo>\n",
    "#include \"sub\"\n",
    "#include \"../../../../../../../../dev/zero\"\n",
    "#include \"sub/../raytracer.h\"\n",   /* any .. at all */
    "#include \"../raytracer.h\"\n",
    "  #  include \"/dev/zero\"\n",
    "\t#include\t\"/dev/zero\"\n",
    "#include_next \"/dev/zero\"\n",
    "#import \"/dev/zero\"\n",
    "#embed \"/dev/zero\"\n",
    "%:include \"/dev/zero\"\n",           /* digraph */
    "?\?=include \"/dev/zero\"\n",          /* trigraph (-std=c11 has them) */
    "#inc\\\nlude \"/dev/zero\"\n",        /* line splices */
    "#include \"/dev/\\\nzero\"\n",
    "#include \"/dev/?\?/\nzero\"\n",       /* a trigraph splice */
    "#inc\\  \nlude \"/dev/zero\"\n",      /* blanks before the newline */
    "/* c */ # /* c */ include /* c */ \"/dev/zero\"\n",
    "/* a comment\n   over lines */ #include \"/dev/zero\"\n",
    "int x;\n#include \"/dev/zero\"\r\n",
    /* A UTF-8 byte order mark, as some Windows editors save it: the
     * compiler skips it, so the first line is a directive. */
    "\xEF\xBB\xBF#include \"/dev/zero\"\n",
    "\xEF\xBB\xBF  #include \"/dev/zero\"\n",
    "#if __has_include(\"fifo\")\n#endif\n",
    "#if defined(X) || __has_include ( <fifo> )\n#endif\n",
    "#pragma GCC dependency \"fifo\"\n",
    "_Pragma(\"GCC dependency \\\"fifo\\\"\")\n",
    "__asm__(\".incbin \\\"/dev/zero\\\"\");\n",
    /* The assembler's directives that read a file, however the strings
     * spell them: split in adjacent literals (over lines and comments, with
     * a prefix), spelt with escapes, and .include. */
    "__asm__(\".inc\" \"bin \\\"/etc/passwd\\\"\");\n",
    "__asm__(\".i\"\n /* x */ \"ncb\" u8\"in \\\"/etc/passwd\\\"\");\n",
    "__asm__(\"\\x2eincbin \\\"/etc/passwd\\\"\");\n",
    "__asm__(\"\\056inc\\142in \\\"/etc/passwd\\\"\");\n",
    "__asm__(\".include \\\"/etc/passwd\\\"\");\n",
    "__asm__(\".incl\" \"ude \\\"/etc/passwd\\\"\");\n",
};

/* What only looks like a directive, and ordinary headers, pass. */
static const char *const passed[] = {
    "#include \"raytracer.h\"\n#include <math.h>\n#include <stdio.h>\n",
    "#include \"raytracer.h\"\n#include <math.h>\n",
    "#include \"./raytracer.h\"\n",
    "// #include \"/dev/zero\"\n",
    "/* #include \"/dev/zero\" */\n",
    "const char *s = \"#include \\\"/dev/zero\\\"\";\n",
    "#define Z \"/dev/zero\"\n",               /* names only in #include are read */
    "#error \"/dev/zero\"\n",
    /* Strings that are not joined (a token between them) spell nothing. */
    "const char *a = \".inc\", *b = \"bin\";\n",
    "const char *a[] = { \".incl\", \"ude\" };\n",
    "#include \"no-such-header.h\"\n",         /* the compiler says it is missing */
    "#include Z\n",                            /* a macro: left to the compiler's limits */
    "char c = '\"'; /* \" */\n#include \"raytracer.h\"\n",
    "",
    /* not a directive: something comes before the # */
    "int a; # include \"/dev/zero\"\n",
    "x /* c */ #include \"/dev/zero\"\n",
};

/* In a compile directory made under $TMPDIR (raytracer.h, a FIFO, a link
 * to a device and a folder in it), every text of refused is refused and
 * every one of passed passes, and so does the link named by its full path;
 * a kit header named by a path from the student's folders is refused with
 * the way to name it. */
static void scan_all(void)
{
    if (check_temp_dir(dir, sizeof dir, "scan") != 0)
        return;
    char path[128], why[400] = "";
    snprintf(path, sizeof path, "%s/raytracer.h", dir);
    check_write_file(path, "", 0);
    snprintf(path, sizeof path, "%s/fifo", dir);
    CHECK(mkfifo(path, 0600) == 0);
    snprintf(path, sizeof path, "%s/zero", dir);
    CHECK(symlink("/dev/zero", path) == 0);
    snprintf(path, sizeof path, "%s/sub", dir);
    CHECK(mkdir(path, 0700) == 0);
    for (int k = 0; k < CHECK_COUNT(refused); k++)
        CHECK_MSG(scan(refused[k]) == 1, "not refused: %s", refused[k]);
    for (int k = 0; k < CHECK_COUNT(passed); k++)
        CHECK_MSG(scan(passed[k]) == 0, "refused: %s", passed[k]);
    char text[256];
    snprintf(text, sizeof text, "#include \"%s/zero\"\n", dir);
    CHECK_MSG(scan(text) == 1, "not refused: %s", text);
    const char *header = "#include \"../labs/raytracer.h\"\n";
    CHECK(include_scan(header, strlen(header), dir, why, sizeof why) == 1);
    CHECK_MSG(strstr(why, "write #include \"raytracer.h\", as the skeleton does") != NULL, "%s", why);
    header = "#include \"../secret.h\"\n";
    why[0] = '\0';
    CHECK(include_scan(header, strlen(header), dir, why, sizeof why) == 1);
    CHECK_MSG(strstr(why, "climbs out") && !strstr(why, "skeleton"), "%s", why);
    if (check_remove_tree(dir) != 0)
        printf("    (could not remove %s)\n", dir);
}

static void test_scan(void)
{
    scan_all();
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
    scan_all();
    CHECK_MSG(strncmp(dir, "/dev/shm/", 9) == 0, "the compile directory is %s", dir);
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

static const CheckTest tests[] = {
    CHECK_TEST(test_judge_every_spelling), CHECK_TEST(test_scan),
    CHECK_TEST(test_compile_dir_under_dev), CHECK_TEST(test_path_below),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
