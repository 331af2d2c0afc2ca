/*
 * The undefined and the twice-defined functions read from each linker's
 * own words, and which sources define them (tests/grader/linkmsg.c): the messages below are as GNU ld, gold, LLVM's
 * lld and Apple's ld print them for a call to an undefined function (the
 * first three as run here; Apple's written from its known form, not run
 * here).
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/linkmsg.h"
#include "kit/savefile.h"

/* A linker's message and the names read from it. */
typedef struct {
    const char *linker, *text;
    int n;
    const char *names[2];
} Message;

static const Message cases[] = {
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

/* The same for a function defined twice (GNU ld with and without
 * link-time optimisation, gold and lld as run here; Apple's ld in its
 * current and its older words, written from their known forms). */
static const Message duplicates[] = {
    { "GNU ld",
      "/usr/bin/ld: /tmp/ccKyolGa.o: in function `dot':\n"
      "b.c:(.text+0x0): multiple definition of `dot'; /tmp/cchz7paw.o:a.c:(.text+0x0): first defined here\n"
      "collect2: error: ld returned 1 exit status\n",
      1, { "dot" } },
    { "GNU ld, link-time optimisation",
      "/usr/bin/ld: out/build/sub/labs/lto/part3b_ray_color.o (symbol from plugin): in function `dot':\n"
      "(.text+0x0): multiple definition of `dot'; out/build/sub/labs/lto/part3a_sphere_intersect.o "
      "(symbol from plugin):(.text+0x0): first defined here\n",
      1, { "dot" } },
    { "gold",
      "/usr/bin/ld.gold: error: /tmp/cczVFqDt.o: multiple definition of 'dot'\n"
      "/usr/bin/ld.gold: /tmp/cc6uppXj.o: previous definition here\n",
      1, { "dot" } },
    { "lld",
      "ld.lld: error: duplicate symbol: dot\n"
      ">>> defined at a.c\n"
      ">>>            /tmp/ccYVhCnk.o:(dot)\n"
      ">>> defined at b.c\n"
      ">>>            /tmp/ccimabXs.o:(.text+0x0)\n",
      1, { "dot" } },
    { "Apple's ld",
      "duplicate symbol '_dot' in:\n"
      "    /var/folders/xy/part3a_sphere_intersect.o\n"
      "    /var/folders/xy/part3b_ray_color.o\n"
      "duplicate symbol '_sq' in:\n"
      "    a.o\n"
      "    b.o\n"
      "ld: 2 duplicate symbols for architecture arm64\n",
      2, { "dot", "sq" } },
    { "Apple's older ld", "duplicate symbol _dot in:\n    a.o\n    b.o\n", 1, { "dot" } },
    { "an undefined function is not a duplicate", "undefined reference to `dot'\n", 0, { NULL } },
};

/* read (linkmsg_undefined or linkmsg_duplicate) gives each of the count
 * messages' names, at most 2. */
static void check_messages(const Message *m, int count,
                           int (*read)(const char *, char[][LINKMSG_NAME_MAX], int))
{
    for (int k = 0; k < count; k++) {
        char names[2][LINKMSG_NAME_MAX];
        int n = read(m[k].text, names, 2);
        CHECK_MSG(n == m[k].n, "%s: %d names, want %d", m[k].linker, n, m[k].n);
        for (int q = 0; q < n && q < m[k].n; q++)
            CHECK_MSG(strcmp(names[q], m[k].names[q]) == 0, "%s: name %d is %s, want %s", m[k].linker, q,
                      names[q], m[k].names[q]);
    }
}

static void test_each_linker(void)
{
    check_messages(cases, CHECK_COUNT(cases), linkmsg_undefined);
}

static void test_duplicates(void)
{
    check_messages(duplicates, CHECK_COUNT(duplicates), linkmsg_duplicate);
    char names[1][LINKMSG_NAME_MAX];
    CHECK_MSG(linkmsg_undefined(duplicates[0].text, names, 1) == 0,
              "GNU ld's duplicate read as an undefined function");
}

/* Which sources define a function: a definition, with its body's brace on
 * the next line or its parameters over two lines; not a prototype, a call,
 * a longer name, a name inside a longer one, or a definition under #if 0. */
static void test_defines(void)
{
    static const struct {
        const char *text;
        bool defines;
    } texts[] = {
        { "double sq(double x) { return x * x; }", true },
        { "static double\nsq (double x)\n{\n    return x * x;\n}\n", true },
        { "double sq(double x,\n          double y) { return x * y; }", true },
        { "double sq(double x);\n", false },
        { "double f(double x) { return sq(x) + 1; }", false },
        { "double sqr(double x) { return x * x; }", false },
        { "double my_sq(double x) { return x * x; }", false },
        { "double sq(double x)", false },
        { "", false },
        { "/* double sq(double x) { return x * x; } */\n", false },
        { "// double sq(double x) { return x * x; }\n", false },
        { "const char *s = \"sq(x) {\";\n", false },
        { "/* sq */ double sq(double x) /* ) { */ { return x * x; }", true },
        { "const char *s = \"\\\" sq(\";\ndouble sq(double x) { return x * x; }", true },
        { "char c = '\\'';\ndouble sq(double x) { return x * x; }", true },
        /* an old version kept under #if 0 is not code; its #else is */
        { "#if 0\ndouble sq(double x) { return x * x; }\n#endif\n", false },
        { "  #  if 0 /* old */\ndouble sq(double x) { return x * x; }\n#endif\n", false },
        { "#if 0\n#ifdef X\n#endif\ndouble sq(double x) { return x * x; }\n#endif\n", false },
        { "#if 0\nold();\n#else\ndouble sq(double x) { return x * x; }\n#endif\n", true },
        { "#if 0\n#if 1\n#else\n#endif\ndouble sq(double x) { return x * x; }\n#endif\n", false },
        { "#if 0\n#endif\ndouble sq(double x) { return x * x; }\n", true },
        { "#if 01\ndouble sq(double x) { return x * x; }\n#endif\n", true },
        { "#if 0 || 1\ndouble sq(double x) { return x * x; }\n#endif\n", true },
        { "#if 1\ndouble sq(double x) { return x * x; }\n#endif\n", true },
    };
    for (size_t k = 0; k < sizeof texts / sizeof texts[0]; k++)
        CHECK_MSG(linkmsg_defines(texts[k].text, "sq") == texts[k].defines, "text %zu: %s", k,
                  texts[k].text);
}

/* The functions a source defines, in order, each once: not the
 * statements whose parentheses a brace follows, not a prototype, a call or
 * a definition in a comment. */
static void test_definitions(void)
{
    static const char text[] =
        "#include \"raytracer.h\"\n"
        "static double sq(double x);\n"
        "/* bool old_intersect(const Sphere *s) { return false; } */\n"
        "static double\nsq(double x)\n{\n    return x * x;\n}\n"
        "bool hit_sphere(const Sphere *sphere, const Ray *ray, double *t)\n{\n"
        "    if (sq(1) < 0) {\n        return false;\n    }\n"
        "    for (int k = 0; k < 2; k++) {\n    }\n"
        "    while (0) {\n    }\n"
        "    switch (0) {\n    }\n"
        "    return (void)sphere, (void)ray, *t = 1, true;\n}\n"
        "double sq(double x);\n";
    char names[4][LINKMSG_NAME_MAX];
    int n = linkmsg_definitions(text, names, 4);
    CHECK_MSG(n == 2, "%d functions, want 2 (sq and hit_sphere)", n);
    CHECK_MSG(n >= 1 && strcmp(names[0], "sq") == 0, "the first is %s, want sq", n >= 1 ? names[0] : "none");
    CHECK_MSG(n >= 2 && strcmp(names[1], "hit_sphere") == 0, "the second is %s, want hit_sphere",
              n >= 2 ? names[1] : "none");
    CHECK(linkmsg_definitions(text, names, 1) == 1);
    char list[200];
    linkmsg_definitions_list(text, list, sizeof list);
    CHECK_MSG(strcmp(list, "sq and hit_sphere") == 0, "the list is '%s', want 'sq and hit_sphere'", list);
    linkmsg_definitions_list("int a(void) { return 0; }\nint b(void) { return 1; }\nint c(void) { return 2; }\n",
                             list, sizeof list);
    CHECK_MSG(strcmp(list, "a, b and c") == 0, "the list is '%s', want 'a, b and c'", list);
    linkmsg_definitions_list("int a(void);\n", list, sizeof list);
    CHECK_MSG(strcmp(list, "none") == 0, "the list is '%s', want 'none'", list);
    CHECK(linkmsg_definitions("", names, 4) == 0);
    CHECK(linkmsg_definitions("double sq(double x);\nint main(void);\n", names, 4) == 0);
}

/* Each function the contract's header declares is given the stage file
 * that defines it in the kit's reference (the header and the files read
 * here, not a list written again); a name not in the contract is given
 * none. */
static void test_stage_of(void)
{
    static const char *const names[] = { "image_plane_size", "pixel_coordinates", "sphere_intersect",
                                         "camera_ray", "ray_color", "plane_intersect", "triangle_intersect" };
    size_t n = 0;
    char *header = kit_load_file("labs/raytracer.h", 1 << 20, &n);
    CHECK_MSG(header != NULL, "labs/raytracer.h could not be read");
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        char declared[LINKMSG_NAME_MAX + 2];
        snprintf(declared, sizeof declared, " %s(", names[k]);
        CHECK_MSG(header && strstr(header, declared), "labs/raytracer.h does not declare %s", names[k]);
        const char *stage = linkmsg_stage_of(names[k]);
        CHECK_MSG(stage != NULL, "%s has no stage file", names[k]);
        if (!stage)
            continue;
        char path[200];
        snprintf(path, sizeof path, "solutions/%s.c", stage);
        char *text = kit_load_file(path, 1 << 20, &n);
        if (!text) {                              /* the student kit has no solutions/ */
            snprintf(path, sizeof path, "labs/%s.c", stage);
            text = kit_load_file(path, 1 << 20, &n);
        }
        CHECK_MSG(text && linkmsg_defines(text, names[k]), "%s does not define %s", path, names[k]);
        free(text);
    }
    free(header);
    CHECK(linkmsg_stage_of("hit_sphere") == NULL);
    CHECK(linkmsg_stage_of("sphere_intersects") == NULL);
    CHECK(linkmsg_stage_of("") == NULL);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_each_linker),
    CHECK_TEST(test_duplicates),
    CHECK_TEST(test_defines),
    CHECK_TEST(test_definitions),
    CHECK_TEST(test_stage_of),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
