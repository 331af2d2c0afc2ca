/* The vector helpers of labs/vec3.h, on values whose answers are exact. */
#include "check.h"            /* first: it sets the POSIX feature level */
#include "../../labs/raytracer.h"

static void test_add_sub_scale(void)
{
    Vec3 a = vec3(1, 2, 3), b = vec3(4, -5, 6.5);
    Vec3 s = vec3_add(a, b), d = vec3_sub(a, b), k = vec3_scale(a, -2);
    CHECK_EQ_DOUBLE(s.x, 5); CHECK_EQ_DOUBLE(s.y, -3); CHECK_EQ_DOUBLE(s.z, 9.5);
    CHECK_EQ_DOUBLE(d.x, -3); CHECK_EQ_DOUBLE(d.y, 7); CHECK_EQ_DOUBLE(d.z, -3.5);
    CHECK_EQ_DOUBLE(k.x, -2); CHECK_EQ_DOUBLE(k.y, -4); CHECK_EQ_DOUBLE(k.z, -6);
    Vec3 n = vec3_negate(b);
    CHECK_EQ_DOUBLE(n.x, -4); CHECK_EQ_DOUBLE(n.y, 5); CHECK_EQ_DOUBLE(n.z, -6.5);
}

static void test_dot_cross(void)
{
    Vec3 a = vec3(1, 2, 3), b = vec3(4, 5, 6);
    CHECK_EQ_DOUBLE(vec3_dot(a, b), 32);
    Vec3 c = vec3_cross(a, b);                   /* (-3, 6, -3) */
    CHECK_EQ_DOUBLE(c.x, -3); CHECK_EQ_DOUBLE(c.y, 6); CHECK_EQ_DOUBLE(c.z, -3);
    Vec3 z = vec3_cross(vec3(1, 0, 0), vec3(0, 1, 0));   /* right-handed: x cross y = z */
    CHECK_EQ_DOUBLE(z.x, 0); CHECK_EQ_DOUBLE(z.y, 0); CHECK_EQ_DOUBLE(z.z, 1);
    CHECK_EQ_DOUBLE(vec3_dot(c, a), 0);
}

static void test_length_normalize(void)
{
    /* 3-4-5 and 2-3-6-7 triangles: exact in binary floating point. */
    CHECK_EQ_DOUBLE(vec3_length(vec3(3, 4, 0)), 5);
    CHECK_EQ_DOUBLE(vec3_length(vec3(2, -3, 6)), 7);
    Vec3 u = vec3_normalize(vec3(0, -8, 0));
    CHECK_EQ_DOUBLE(u.x, 0); CHECK_EQ_DOUBLE(u.y, -1); CHECK_EQ_DOUBLE(u.z, 0);
    Vec3 v = vec3_normalize(vec3(3, 0, -4));
    CHECK_NEAR(v.x, 0.6, 0x1p-52); CHECK_NEAR(v.z, -0.8, 0x1p-52);
    CHECK_NEAR(vec3_length(vec3_normalize(vec3(1e-3, 7, -2e5))), 1, 4 * 0x1p-53);
}

static void test_normalize_zero_stays_zero(void)
{
    Vec3 z = vec3_normalize(vec3(0, 0, 0));
    CHECK_EQ_DOUBLE(z.x, 0); CHECK_EQ_DOUBLE(z.y, 0); CHECK_EQ_DOUBLE(z.z, 0);
}

static void test_m_pi(void)
{
    CHECK_EQ_DOUBLE(M_PI, 0x1.921fb54442d18p+1);
}

static const CheckTest tests[] = {
    CHECK_TEST(test_add_sub_scale),
    CHECK_TEST(test_dot_cross),
    CHECK_TEST(test_length_normalize),
    CHECK_TEST(test_normalize_zero_stays_zero),
    CHECK_TEST(test_m_pi),
};

int main(int argc, char **argv)
{
    return check_main(argc, argv, tests, CHECK_COUNT(tests));
}
