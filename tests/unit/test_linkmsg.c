/*
 * The undefined functions read from each linker's own words
 * (tests/grader/linkmsg.c): the messages below are as GNU ld, gold, LLVM's
 * lld and Apple's ld print them for a call to an undefined function (the
 * first three as run here; Apple's written from its known form, not run
 * here).
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/linkmsg.h"

static const struct {
    const char *linker, *text;
    int n;
    const char *names[3];
} cases[] = {
    { "GNU ld",
      "/usr/bin/ld: part3b_ray_color.o: in function `ray_color':\n"
      "part3b_ray_color.c:(.text+0x1cc): undefined reference to `my_helper'\n"
      "/usr/bin/ld: part3b_ray_color.c:(.text+0x2a0): undefined reference to `my_helper'\n"
      "/usr/bin/ld: part3b_ray_color.c:(.text+0x2b8): undefined reference to `other_one'\n"
      "collect2: error: ld returned 1 exit status\n",
      2, { "my_helper", "other_one" } },
    { "the grader's loader, in GNU ld's words",
      "the linker: undefined reference to `twice' (no file of the program defines it)", 1, { "twice" } },
    { "gold",
      "/tmp/ccad1z6P.o:part3b_ray_color.c:function ray_color: error: undefined reference to 'twice'\n"
      "collect2: error: ld returned 1 exit status\n",
      1, { "twice" } },
    { "lld",
      "ld.lld: error: undefined symbol: twice\n"
      ">>> referenced by part3b_ray_color.c\n"
      ">>>               part3b_ray_color.o:(ray_color)\n"
      "clang: error: linker command failed with exit code 1 (use -v to see invocation)\n",
      1, { "twice" } },
    { "Apple's ld",
      "Undefined symbols for architecture arm64:\n"
      "  \"_twice\", referenced from:\n"
      "      _ray_color in part3b_ray_color.o\n"
      "  \"_my_helper\", referenced from:\n"
      "      _ray_color in part3b_ray_color.o\n"
      "ld: symbol(s) not found for architecture arm64\n",
      2, { "twice", "my_helper" } },
    { "a compiler's error, not the linker's", "part1_image_plane.c:3:1: error: expected ';'\n", 0, { NULL } },
    { "nothing", "", 0, { NULL } },
    { "at most max (2)",
      "undefined reference to `a'\nundefined reference to `b'\nundefined reference to `c'\n", 2, { "a", "b" } },
    { "no name", "undefined reference to `a b'\n", 0, { NULL } },
    { "Apple's words for a name with no underscore", "  \"twice\", referenced from:\n", 0, { NULL } },
};

static void test_each_linker(void)
{
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char names[2][LINKMSG_NAME_MAX];
        int n = linkmsg_undefined(cases[k].text, names, 2);
        CHECK_MSG(n == cases[k].n, "%s: %d names, want %d", cases[k].linker, n, cases[k].n);
        for (int q = 0; q < n && q < cases[k].n; q++)
            CHECK_MSG(strcmp(names[q], cases[k].names[q]) == 0, "%s: name %d is %s, want %s",
                      cases[k].linker, q, names[q], cases[k].names[q]);
    }
}

static const CheckTest tests[] = {
    CHECK_TEST(test_each_linker),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
