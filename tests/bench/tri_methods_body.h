/*
 * tri_methods_body.h - Moller-Trumbore's test written once for double and
 * float (tri_methods.c includes it twice), so the two cannot drift apart.
 * Before including: REAL, VEC, TRI, RAY, SUB, CROSS, DOT and NAME; it
 * undefines them at its end.
 */
bool NAME(const TRI *tri, const RAY *ray, REAL *t)
{
    VEC e1 = SUB(tri->b, tri->a), e2 = SUB(tri->c, tri->a);
    VEC s = SUB(ray->origin, tri->a), q = CROSS(ray->direction, e2);
    REAL det = DOT(e1, q);
    if (det == 0)
        return false;
    REAL inv = 1 / det, beta = DOT(s, q) * inv;
    if (beta < 0 || beta > 1)
        return false;
    VEC sx = CROSS(s, e1);
    REAL gamma = DOT(ray->direction, sx) * inv;
    if (gamma < 0 || beta + gamma > 1)
        return false;
    REAL tt = DOT(e2, sx) * inv;
    if (!(tt > 0 && tt < INFINITY))
        return false;
    *t = tt;
    return true;
}

#undef REAL
#undef VEC
#undef TRI
#undef RAY
#undef SUB
#undef CROSS
#undef DOT
#undef NAME
