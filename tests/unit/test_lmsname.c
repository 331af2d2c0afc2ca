/*
 * A downloaded file's submission and own name (tests/grader/lmsname.c), for
 * names as Canvas, Moodle and Blackboard write them (lmsname.h gives their forms: from
 * Canvas's documented renaming, the code that names the files in its zip
 * (anonymous grading's among them) and Moodle's download code), and names
 * that only look like them.
 */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../grader/lmsname.h"

static const char *const stages[] = { "part1_image_plane", "part2_pixel_coordinates",
                                      "part3a_sphere_intersect", "part3b_ray_color" };

static const struct {
    const char *path;
    Lms lms;                  /* 0: not a download's name */
    const char *who, *name;
    int again;
    bool late;
    const char *attempt;      /* Blackboard's, else NULL */
} cases[] = {
    { "smithbob_340934_208490284_part1_image_plane.c", LMS_CANVAS, "smithbob_340934",
      "part1_image_plane.c", 0, false, NULL },
    { "wellslane_LATE_334244_394803489_part3b_ray_color.c", LMS_CANVAS, "wellslane_334244",
      "part3b_ray_color.c", 0, true, NULL },
    /* uploaded again: Canvas's "-N" comes off a stage file's name ... */
    { "smithbob_340934_208490284_part1_image_plane-1.c", LMS_CANVAS, "smithbob_340934",
      "part1_image_plane.c", 1, false, NULL },
    { "smithbob_340934_208490284_part2_pixel_coordinates-12.c", LMS_CANVAS, "smithbob_340934",
      "part2_pixel_coordinates.c", 12, false, NULL },
    /* ... and stays on any other name */
    { "smithbob_340934_208490284_notes-2.txt", LMS_CANVAS, "smithbob_340934", "notes-2.txt", 0, false, NULL },
    { "smithbob_340934_208490284_part1_image_plane-v2.c", LMS_CANVAS, "smithbob_340934",
      "part1_image_plane-v2.c", 0, false, NULL },
    /* the student's own name, kept as it is (the grader then names it) */
    { "smithbob_340934_208490284_Part1_Image_Plane (1).c", LMS_CANVAS, "smithbob_340934",
      "Part1_Image_Plane (1).c", 0, false, NULL },
    /* an underscore in the name; the file's name has digits and underscores too */
    { "o_brien_77_88_part_1_2_3.c", LMS_CANVAS, "o_brien_77", "part_1_2_3.c", 0, false, NULL },
    /* anonymous grading: "anon_" and the submission's anonymous id (five
     * characters of base 58) where the name and user id were; LATE first */
    { "anon_Xy3Ab_208490284_part1_image_plane.c", LMS_CANVAS, "anon_Xy3Ab", "part1_image_plane.c", 0,
      false, NULL },
    { "LATE_anon_9kPqR_394803489_part3b_ray_color.c", LMS_CANVAS, "anon_9kPqR", "part3b_ray_color.c", 0,
      true, NULL },
    { "anon_Xy3Ab_208490284_part1_image_plane-2.c", LMS_CANVAS, "anon_Xy3Ab", "part1_image_plane.c", 2,
      false, NULL },
    /* re-zipped under a folder */
    { "submissions/smithbob_340934_208490284_part1_image_plane.c", LMS_CANVAS, "smithbob_340934",
      "part1_image_plane.c", 0, false, NULL },
    /* Moodle: the folder form (the default) and the flat form */
    { "Ann Lee_123456_assignsubmission_file_/part1_image_plane.c", LMS_MOODLE, "Ann Lee_123456",
      "part1_image_plane.c", 0, false, NULL },
    { "Ann Lee_123456_assignsubmission_file_part1_image_plane.c", LMS_MOODLE, "Ann Lee_123456",
      "part1_image_plane.c", 0, false, NULL },
    { "Team A-Ann Lee_123456_assignsubmission_onlinetext_/onlinetext.html", LMS_MOODLE,
      "Team A-Ann Lee_123456", "onlinetext.html", 0, false, NULL },
    /* not a download's name */
    { "part1_image_plane.c", 0, NULL, NULL, 0, false, NULL },
    { "smithbob/part1_image_plane.c", 0, NULL, NULL, 0, false, NULL },
    { "smithbob_340934_part1_image_plane.c", 0, NULL, NULL, 0, false, NULL },
    { "_340934_208490284_part1_image_plane.c", 0, NULL, NULL, 0, false, NULL },
    { "smithbob_340934_208490284_", 0, NULL, NULL, 0, false, NULL },
    { "smithbob_LATE_x_208490284_part1.c", 0, NULL, NULL, 0, false, NULL },
    { "anon__208490284_part1_image_plane.c", 0, NULL, NULL, 0, false, NULL },
    { "anon_Xy3Ab_part1_image_plane.c", 0, NULL, NULL, 0, false, NULL },
    { "anon_Xy-3b_208490284_part1_image_plane.c", 0, NULL, NULL, 0, false, NULL },
    { "LATE_anon_Xy3Ab_208490284_", 0, NULL, NULL, 0, false, NULL },
    { "Ann Lee_assignsubmission_file_part1.c", 0, NULL, NULL, 0, false, NULL },
    { "_123456_assignsubmission_file_part1.c", 0, NULL, NULL, 0, false, NULL },
    { "Ann Lee_123456_assignsubmission_file_", 0, NULL, NULL, 0, false, NULL },
    { "Ann Lee_123456_assignsubmission_file_/", 0, NULL, NULL, 0, false, NULL },
    { "Ann Lee_123456_assignsubmission_file_sub/part1.c", 0, NULL, NULL, 0, false, NULL },
    { "x/Ann Lee_123456_assignsubmission_file_/part1.c", 0, NULL, NULL, 0, false, NULL },
    /* Blackboard: ASSIGNMENT_USERNAME_attempt_DATE_FILE, and the attempt's
     * own text file; the username is the last "_"-separated part before
     * "_attempt_", the assignment's name may hold spaces and "_" */
    { "Lab 1_jsmith_attempt_2024-03-15-10-30-00_part1_image_plane.c", LMS_BLACKBOARD, "jsmith",
      "part1_image_plane.c", 0, false, "2024-03-15-10-30-00" },
    { "Lab 1_jsmith_attempt_2024-03-15-10-30-00.txt", LMS_BLACKBOARD, "jsmith",
      "attempt_2024-03-15-10-30-00.txt", 0, false, "2024-03-15-10-30-00" },
    { "Ray_Tracing_Lab_20103940_attempt_2024-03-16-09-05-59_part3a_sphere_intersect.c", LMS_BLACKBOARD,
      "20103940", "part3a_sphere_intersect.c", 0, false, "2024-03-16-09-05-59" },
    { "gradebook/Lab 1_a.b-c_attempt_2024-03-15-10-30-00_my_attempt_2.c", LMS_BLACKBOARD, "a.b-c",
      "my_attempt_2.c", 0, false, "2024-03-15-10-30-00" },
    /* not Blackboard's */
    { "jsmith_attempt_2024-03-15-10-30-00_part1.c", 0, NULL, NULL, 0, false, NULL },      /* no assignment */
    { "Lab 1__attempt_2024-03-15-10-30-00_part1.c", 0, NULL, NULL, 0, false, NULL },      /* no username */
    { "Lab 1_jsmith_attempt_2024_part1.c", 0, NULL, NULL, 0, false, NULL },               /* no date */
    { "Lab 1_jsmith_attempt_2024-03-15-10-30-00_", 0, NULL, NULL, 0, false, NULL },       /* no file */
    { "Lab 1_jsmith_attempt_2024-03-15-10-30-00.c", 0, NULL, NULL, 0, false, NULL },
};

static void test_names(void)
{
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        LmsName n;
        bool got = lms_name(cases[k].path, stages, 4, &n);
        CHECK_MSG(got == (cases[k].lms != 0), "%s: read %s", cases[k].path,
                  got ? "as a download's name" : "as no download's name");
        if (!got || !cases[k].lms)
            continue;
        CHECK_MSG(n.lms == cases[k].lms, "%s: the platform", cases[k].path);
        CHECK_MSG(strcmp(n.who, cases[k].who) == 0, "%s: whose: '%s', not '%s'", cases[k].path, n.who,
                  cases[k].who);
        CHECK_MSG(strcmp(n.name, cases[k].name) == 0, "%s: the name: '%s', not '%s'", cases[k].path,
                  n.name, cases[k].name);
        CHECK_MSG(n.again == cases[k].again, "%s: uploaded again %d, not %d", cases[k].path, n.again,
                  cases[k].again);
        CHECK_MSG(n.late == cases[k].late, "%s: late", cases[k].path);
        CHECK_MSG(strcmp(n.attempt, cases[k].attempt ? cases[k].attempt : "") == 0, "%s: attempt '%s'",
                  cases[k].path, n.attempt);
    }
    /* where Blackboard's username begins, in the path's last component */
    LmsName n;
    CHECK(lms_name("gradebook/Lab 1_a.b-c_attempt_2024-03-15-10-30-00_x.c", stages, 4, &n) && n.user_at == 6);
}

/* Names too long for the result are refused, not cut. */
static void test_long(void)
{
    char path[3 * LMS_NAME_MAX];
    memset(path, 'a', sizeof path);
    memcpy(path + LMS_NAME_MAX, "_1_2_", 5);
    path[sizeof path - 1] = '\0';
    LmsName n;
    CHECK(!lms_name(path, stages, 4, &n));          /* the name before it is too long */
    memcpy(path, "ab_1_2_", 7);
    CHECK(!lms_name(path, stages, 4, &n));          /* the file's name is too long */
    path[LMS_NAME_MAX] = '\0';
    CHECK(lms_name(path, stages, 4, &n) && strlen(n.name) == LMS_NAME_MAX - 7);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_names),
    CHECK_TEST(test_long),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
