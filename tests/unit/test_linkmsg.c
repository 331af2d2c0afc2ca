/*
 * The undefined functions read from each linker's own words
 * (tests/grader/linkmsg.c): the messages below are as GNU ld, gold, LLVM's
 * lld and Apple's ld print them for a call to an undefined function (the
 * first three as run here; Apple's written from its known form, not run
 * here).
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/linkmsg.h"

static void test_gnu(void)
{
    char names[3][LINKMSG_NAME_MAX];
    const char *text = "/usr/bin/ld: part3b_ray_color.o: in function `ray_color':\n"
                       "part3b_ray_color.c:(.text+0x1cc): undefined reference to `my_helper'\n"
                       "/usr/bin/ld: part3b_ray_color.c:(.text+0x2a0): undefined reference to `my_helper'\n"
                       "/usr/bin/ld: part3b_ray_color.c:(.text+0x2b8): undefined reference to `other_one'\n"
                       "collect2: error: ld returned 1 exit status\n";
    CHECK_EQ_INT(linkmsg_undefined(text, names, 3), 2);
    CHECK(strcmp(names[0], "my_helper") == 0);
    CHECK(strcmp(names[1], "other_one") == 0);
    /* The grader's loader says it the same way. */
    CHECK_EQ_INT(linkmsg_undefined("the linker: undefined reference to `twice' (no file of the "
                                   "program defines it)", names, 3), 1);
    CHECK(strcmp(names[0], "twice") == 0);
}

static void test_gold(void)
{
    char names[3][LINKMSG_NAME_MAX];
    const char *text = "/tmp/ccad1z6P.o:part3b_ray_color.c:function ray_color: error: undefined "
                       "reference to 'twice'\n"
                       "collect2: error: ld returned 1 exit status\n";
    CHECK_EQ_INT(linkmsg_undefined(text, names, 3), 1);
    CHECK(strcmp(names[0], "twice") == 0);
}

static void test_lld(void)
{
    char names[3][LINKMSG_NAME_MAX];
    const char *text = "ld.lld: error: undefined symbol: twice\n"
                       ">>> referenced by part3b_ray_color.c\n"
                       ">>>               part3b_ray_color.o:(ray_color)\n"
                       "clang: error: linker command failed with exit code 1 (use -v to see invocation)\n";
    CHECK_EQ_INT(linkmsg_undefined(text, names, 3), 1);
    CHECK(strcmp(names[0], "twice") == 0);
}

static void test_apple(void)
{
    char names[3][LINKMSG_NAME_MAX];
    const char *text = "Undefined symbols for architecture arm64:\n"
                       "  \"_twice\", referenced from:\n"
                       "      _ray_color in part3b_ray_color.o\n"
                       "  \"_my_helper\", referenced from:\n"
                       "      _ray_color in part3b_ray_color.o\n"
                       "ld: symbol(s) not found for architecture arm64\n";
    CHECK_EQ_INT(linkmsg_undefined(text, names, 3), 2);
    CHECK(strcmp(names[0], "twice") == 0);
    CHECK(strcmp(names[1], "my_helper") == 0);
}

/* Nothing undefined, at most max, and nothing that is not a name. */
static void test_limits(void)
{
    char names[2][LINKMSG_NAME_MAX];
    CHECK_EQ_INT(linkmsg_undefined("part1_image_plane.c:3:1: error: expected ';'\n", names, 2), 0);
    CHECK_EQ_INT(linkmsg_undefined("", names, 2), 0);
    CHECK_EQ_INT(linkmsg_undefined("undefined reference to `a'\nundefined reference to `b'\n"
                                   "undefined reference to `c'\n", names, 2), 2);
    CHECK_EQ_INT(linkmsg_undefined("undefined reference to `a b'\n", names, 2), 0);
    CHECK_EQ_INT(linkmsg_undefined("  \"twice\", referenced from:\n", names, 2), 0);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_gnu), CHECK_TEST(test_gold), CHECK_TEST(test_lld), CHECK_TEST(test_apple),
    CHECK_TEST(test_limits),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
