/*
 * Headers a stage file includes that the grader's build of it will not have
 * (tests/grader/own_headers.c): files beside it, or in a folder given as an
 * include path, named with their line; the kit's raytracer.h and vec3.h,
 * system headers, names in comments and names that are no file are not.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/own_headers.h"

static char dir[512], other[600];

/* A folder with myvec.h, util.h, a.h ... d.h and raytracer.h, vec3.h;
 * another, as -Ilabs is, with kit/scene.h. */
static void make_folders(void)
{
    static const char *const names[] = { "myvec.h", "util.h", "a.h", "b.h", "c.h", "d.h",
                                         "raytracer.h", "vec3.h" };
    CHECK(check_temp_dir(dir, sizeof dir, "own_headers") == 0);
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        char path[700];
        snprintf(path, sizeof path, "%s/%s", dir, names[k]);
        check_write_file(path, "", 0);
    }
    snprintf(other, sizeof other, "%s/inc", dir);
    CHECK(mkdir(other, 0700) == 0);
    char kit[700];
    snprintf(kit, sizeof kit, "%s/kit", other);
    CHECK(mkdir(kit, 0700) == 0);
    snprintf(kit, sizeof kit, "%s/kit/scene.h", other);
    check_write_file(kit, "", 0);
}

static const struct {
    const char *what, *text;
    int found;
    const char *says;           /* in the explanation, or NULL */
} cases[] = {
    { "a header of one's own, beside the file",
      "/* part 3a */\n#include \"raytracer.h\"\n#include \"myvec.h\"\n", 1,
      "f.c:3: #include \"myvec.h\": the grader will not have myvec.h\n"
      "The grader builds each stage file alone, with only raytracer.h, vec3.h and the system's "
      "headers beside it: put what myvec.h holds into f.c itself" },
    { "in angle brackets, and with blanks after the #",
      "#  include <util.h>\n", 1, "f.c:1: #include \"util.h\": the grader will not have util.h\n" },
    { "a file of the other folder (the kit's, through -Ilabs)",
      "#include \"kit/scene.h\"\n", 1, "f.c:1: #include \"kit/scene.h\": the grader will not have kit/scene.h\n" },
    { "the kit's two headers and the system's: nothing to say",
      "#include \"raytracer.h\"\n#include \"vec3.h\"\n#include <math.h>\n#include \"stdio.h\"\n", 0, NULL },
    { "a name that is no file (a typo): the compiler says so",
      "#include \"myvec2.h\"\n", 0, NULL },
    { "in a comment, and in a string: not included",
      "// #include \"myvec.h\"\n/* #include \"util.h\" */\nconst char *s = \"#include <a.h>\";\n", 0, NULL },
    { "named twice: said once, at its first line",
      "int x;\n#include \"myvec.h\"\n#include \"myvec.h\"\n", 1,
      "f.c:2: #include \"myvec.h\": the grader will not have myvec.h\nThe grader" },
    { "two headers: both, and the advice for them together",
      "#include \"myvec.h\"\n#include \"util.h\"\n", 2,
      "f.c:2: #include \"util.h\": the grader will not have util.h\nThe grader builds each stage "
      "file alone, with only raytracer.h, vec3.h and the system's headers beside it: put what "
      "those headers hold into f.c itself" },
    { "more than three: the first three, and how many more",
      "#include \"a.h\"\n#include \"b.h\"\n#include \"c.h\"\n#include \"d.h\"\n#include \"util.h\"\n", 5,
      "f.c:3: #include \"c.h\": the grader will not have c.h\n(and 2 more such headers)\n" },
};

static void test_cases(void)
{
    make_folders();
    const char *dirs[] = { dir, other };
    for (int k = 0; k < CHECK_COUNT(cases); k++) {
        char out[1400];
        int n = own_headers_explain(cases[k].text, strlen(cases[k].text), dirs, 2, "f.c", out, sizeof out);
        CHECK_MSG(n == cases[k].found, "%s: found %d, not %d", cases[k].what, n, cases[k].found);
        if (cases[k].says)
            CHECK_MSG(strstr(out, cases[k].says) != NULL, "%s: said '%s'", cases[k].what, out);
        else
            CHECK_MSG(out[0] == '\0', "%s: said '%s'", cases[k].what, out);
    }
    /* Only the folders given count: the kit's header is not one of the
     * grader's own files' folder. */
    char out[1400];
    const char *text = "#include \"kit/scene.h\"\n";
    CHECK(own_headers_explain(text, strlen(text), dirs, 1, "f.c", out, sizeof out) == 0);
    /* An explanation longer than its room: cut, not written past (the
     * sanitizer build checks). */
    char small[30];
    text = "#include \"myvec.h\"\n#include \"util.h\"\n";
    CHECK(own_headers_explain(text, strlen(text), dirs, 1, "a-long-file-name.c", small, sizeof small) == 2);
    CHECK(strlen(small) < sizeof small);
    check_remove_tree(dir);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_cases),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
