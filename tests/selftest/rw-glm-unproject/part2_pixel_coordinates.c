/* Self-test of the grader: rw-glm-unproject (NOTE.md).  The pixel's centre
 * unprojected through the inverse of a perspective projection, as
 * glm::unProject (and gluUnProject, three.js's Vector3.unproject) do. */
#include "raytracer.h"

/* glm::frustum(left, right, bottom, top, near, far) with OpenGL's depth range
 * [-1, 1], rows of m: m[row][col] times a column vector. */
static void frustum(double l, double r, double b, double t, double n, double f, double m[4][4])
{
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            m[i][k] = 0;
    m[0][0] = 2 * n / (r - l);
    m[0][2] = (r + l) / (r - l);
    m[1][1] = 2 * n / (t - b);
    m[1][2] = (t + b) / (t - b);
    m[2][2] = -(f + n) / (f - n);
    m[2][3] = -(2 * f * n) / (f - n);
    m[3][2] = -1;
}

/* The determinant of the 3 x 3 minor of m without row i and column k. */
static double minor3(const double m[4][4], int i, int k)
{
    double a[3][3];
    for (int r = 0, rr = 0; r < 4; r++) {
        if (r == i)
            continue;
        for (int c = 0, cc = 0; c < 4; c++)
            if (c != k)
                a[rr][cc++] = m[r][c];
        rr++;
    }
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
         - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
         + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* glm::inverse: the adjugate over the determinant (cofactors). */
static void inverse(const double m[4][4], double inv[4][4])
{
    double cof[4][4];
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            cof[i][k] = ((i + k) % 2 ? -1 : 1) * minor3(m, i, k);
    double det = m[0][0] * cof[0][0] + m[0][1] * cof[0][1] + m[0][2] * cof[0][2] + m[0][3] * cof[0][3];
    double one_over_det = 1 / det;
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++)
            inv[i][k] = cof[k][i] * one_over_det;
}

Vec3 pixel_coordinates(int i, int j, int nx, int ny, double w, double h, double d)
{
    double proj[4][4], inv[4][4];
    frustum(-w / 2, w / 2, -h / 2, h / 2, d, 1000 * d, proj);
    inverse(proj, inv);
    /* glm::unProject(win, model = identity, proj, viewport (0, 0, nx, ny)):
     * window y counts rows from the bottom; win.z = 0 is the near plane. */
    double win[3] = { i + 0.5, ny - j - 0.5, 0 };
    double tmp[4] = { win[0] / nx * 2 - 1, win[1] / ny * 2 - 1, win[2] * 2 - 1, 1 };
    double obj[4];
    for (int r = 0; r < 4; r++)
        obj[r] = inv[r][0] * tmp[0] + inv[r][1] * tmp[1] + inv[r][2] * tmp[2] + inv[r][3] * tmp[3];
    return vec3(obj[0] / obj[3], obj[1] / obj[3], obj[2] / obj[3]);
}
