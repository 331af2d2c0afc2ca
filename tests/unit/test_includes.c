/* The grader's scan of #include lines (tests/grader/includes.c): it must
 * find every literal include the compiler would follow, however it is
 * spelled, and nothing the compiler would not. */
#include "check.h"            /* first: it sets the POSIX feature level */

#include "../grader/includes.c"

typedef struct {
    char names[8][64];
    bool angled[8];
    int n;
} Found;

static int collect(const char *name, bool angled, void *ctx)
{
    Found *f = ctx;
    if (f->n < 8) {
        snprintf(f->names[f->n], sizeof f->names[f->n], "%s", name);
        f->angled[f->n] = angled;
        f->n++;
    }
    return 0;
}

static Found scan(const char *src)
{
    Found f = { 0 };
    includes_scan(src, strlen(src), collect, &f);
    return f;
}

static void test_plain_includes(void)
{
    Found f = scan("#include \"raytracer.h\"\n#include <math.h>\nint x;\n");
    CHECK_EQ_INT(f.n, 2);
    CHECK(strcmp(f.names[0], "raytracer.h") == 0 && !f.angled[0]);
    CHECK(strcmp(f.names[1], "math.h") == 0 && f.angled[1]);
}

/* Each spelling the compiler accepts in -std=c11 names /k/ref.c. */
static void test_every_spelling(void)
{
    static const char *const spellings[] = {
        "  #  include   \"/k/ref.c\"\n",
        "#\tinclude\t\"/k/ref.c\"\n",
        "#/* a comment */include /* another */ \"/k/ref.c\"\n",
        "#inc\\\nlude \"/k/r\\\nef.c\"\n",                 /* backslash-newline splices */
        "#inc\\\r\nlude \"/k/ref.c\"\r\n",                  /* the same with CR LF */
        "%:include \"/k/ref.c\"\n",                          /* the digraph for # */
        "\?\?=include \"/k/ref.c\"\n",                     /* the trigraph for # */
        "int a; /* a comment\n spanning lines */ \n#include \"/k/ref.c\"\n",
    };
    for (int k = 0; k < (int)(sizeof spellings / sizeof *spellings); k++) {
        Found f = scan(spellings[k]);
        CHECK_MSG(f.n == 1 && strcmp(f.names[0], "/k/ref.c") == 0,
                  "spelling %d: found %d includes, first '%s'", k, f.n, f.n ? f.names[0] : "");
    }
}

/* What is not an include directive is not reported. */
static void test_not_includes(void)
{
    static const char *const others[] = {
        "// #include \"/k/ref.c\"\n",
        "/* #include \"/k/ref.c\" */\n",
        "const char *s = \"#include \\\"/k/ref.c\\\"\";\n",
        "int include = 1; x = y # include;\n",
        "#define F \"/k/ref.c\"\n#include F\n",          /* a macro: seen after compiling */
        "#includes \"/k/ref.c\"\n#include \"/k/ref.c\n",
    };
    for (int k = 0; k < (int)(sizeof others / sizeof *others); k++) {
        Found f = scan(others[k]);
        CHECK_MSG(f.n == 0, "case %d: found %d includes, first '%s'", k, f.n,
                  f.n ? f.names[0] : "");
    }
}

/* A //-comment's line ends the comment only at a newline that is not
 * spliced: the include below is inside the comment. */
static void test_spliced_line_comment(void)
{
    Found f = scan("// a comment \\\n#include \"/k/ref.c\"\n#include \"ok.h\"\n");
    CHECK_EQ_INT(f.n, 1);
    CHECK(f.n == 1 && strcmp(f.names[0], "ok.h") == 0);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_plain_includes),
    CHECK_TEST(test_every_spelling),
    CHECK_TEST(test_not_includes),
    CHECK_TEST(test_spliced_line_comment),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
