/*
 * accuracy_main.c - how accurate the reference solutions are on the hard
 * families, next to the lecture's textbook formulas; Markdown tables for the
 * benchmark's page (tests/bench/README.md) and the handouts.
 *
 *     out/build/bin/accuracy [cases per family [seed]]     (default 2000, 1)
 *
 * Errors are in units of u = 2^-53: relative for Part 1 and for t in
 * Part 3a; for Part 2 absolute in units of u |w| (x) or u |h| (y), since a
 * pixel centre may be 0.  "worst/tol" is the largest error over tolerance
 * (the hard_check rules of hard.h: above 1 fails).  "fails" counts answers
 * the rule rejects, hit/miss included.  Medians and worsts of Part 3a are
 * over the cases both the oracle and the method call an unambiguous hit.
 * Parts 4 and 5 likewise (relative error of t in u, tolerance K u kappa),
 * next to the form p.n - e.n for planes and to Moller-Trumbore (the
 * skeleton's formula) for triangles; for closed meshes, the rays whose
 * first hit is not where they enter (shared edges and vertices).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "hard.h"
#include "textbook.h"

#define U ORACLE_U

/* ---- statistics per family ------------------------------------------------ */

typedef struct {
    double *err;        /* errors in u */
    int n;
    double worst_ratio; /* error / tolerance */
    int fails;
} Stat;

static void stat_add(Stat *s, double err_u, double ratio)
{
    s->err[s->n++] = err_u;
    if (ratio > s->worst_ratio || isnan(ratio))
        s->worst_ratio = isnan(ratio) ? INFINITY : ratio;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* "worst | median | worst/tol | fails" cells. */
static void stat_print(Stat *s)
{
    if (s->n == 0) {
        printf(" - | - | - | %d |", s->fails);
        return;
    }
    qsort(s->err, (size_t)s->n, sizeof *s->err, cmp_double);
    printf(" %.3g | %.3g | %.3g | %d |", s->err[s->n - 1], s->err[s->n / 2], s->worst_ratio, s->fails);
}

static Stat *stats_new(int nfam, int per)
{
    Stat *s = calloc((size_t)nfam, sizeof *s);
    for (int f = 0; f < nfam; f++)
        s[f].err = calloc((size_t)per + 1, sizeof *s[f].err);
    return s;
}

static void stats_free(Stat *s, int nfam)
{
    for (int f = 0; f < nfam; f++)
        free(s[f].err);
    free(s);
}

static double rel_u(double got, double want)
{
    return want == 0 ? (got == 0 ? 0 : INFINITY) : fabs(got - want) / fabs(want) / U;
}

/* One part's table: per family, the reference's and the textbook's answers
 * and, where the part counts them, the oracle's hits and ambiguous cases. */
typedef struct {
    int nf;
    Stat *ref, *tb;
    int *hits, *amb;
} Table;

static Table table_new(int nf, int per)
{
    Table tab = {nf, stats_new(nf, per), stats_new(nf, per),
                 calloc((size_t)nf, sizeof(int)), calloc((size_t)nf, sizeof(int))};
    return tab;
}

static void table_free(Table *tab)
{
    stats_free(tab->ref, tab->nf);
    stats_free(tab->tb, tab->nf);
    free(tab->hits);
    free(tab->amb);
}

/* Family f's stats: the reference's (m 0) or the textbook's (m 1). */
static Stat *table_stat(Table *tab, int m, int f)
{
    return m ? &tab->tb[f] : &tab->ref[f];
}

/* A row: the family (then its hits and ambiguous cases where counts), then
 * the reference and the textbook. */
static void table_row(Table *tab, int f, const char *family, bool counts)
{
    printf("| %s |", family);
    if (counts)
        printf(" %d | %d |", tab->hits[f], tab->amb[f]);
    stat_print(&tab->ref[f]);
    stat_print(&tab->tb[f]);
    printf("\n");
}

static const char HEADER[] =
    "| family | reference worst | median | worst/tol | fails | textbook worst | median | worst/tol | fails |\n"
    "|---|---|---|---|---|---|---|---|---|\n";

/* Parts 3a, 4 and 5: hit count, ambiguous count, then the reference and
 * the textbook (named). */
static const char HIT_HEADER[] =
    "| family | hits | ambiguous | reference worst | median | worst/tol | fails | %s worst | median | worst/tol | fails |\n"
    "|---|---|---|---|---|---|---|---|---|---|---|\n";

/* ---- the parts -------------------------------------------------------------- */

static void part1(uint64_t seed, int per)
{
    int nf = HARD_PART1_FAMILIES, n = nf * per;
    HardCase1 *c = malloc((size_t)n * sizeof *c);
    hard_part1(seed, c, n);
    Table tab = table_new(nf, per);
    for (int k = 0; k < n; k++) {
        double w, h;
        for (int m = 0; m < 2; m++) {
            Stat *s = table_stat(&tab, m, k % nf);
            (m ? textbook_image_plane : image_plane_size)(c[k].fov_degrees, c[k].aspect, c[k].d, &w, &h);
            double e = fmax(rel_u(w, c[k].w), rel_u(h, c[k].h));
            stat_add(s, e, e * U / HARD_PART1_REL_TOL);
            s->fails += !hard_check1(&c[k], w, h);
        }
    }
    printf("\n### Part 1: image_plane_size (relative error of w and h, in u; tolerance %g u)\n\n%s",
           HARD_PART1_REL_TOL / U, HEADER);
    for (int f = 0; f < nf; f++)
        table_row(&tab, f, c[f].family, false);
    table_free(&tab);
    free(c);
}

static void part2(uint64_t seed, int per)
{
    int nf = HARD_PART2_FAMILIES, n = nf * per;
    HardCase2 *c = malloc((size_t)n * sizeof *c);
    hard_part2(seed, c, n);
    Table tab = table_new(nf, per);
    for (int k = 0; k < n; k++) {
        for (int m = 0; m < 2; m++) {
            Stat *s = table_stat(&tab, m, k % nf);
            Vec3 p = (m ? textbook_pixel : pixel_coordinates)(c[k].i, c[k].j, c[k].nx, c[k].ny, c[k].w, c[k].h, c[k].d);
            double e = fmax(rel_u(p.x, c[k].p.x), rel_u(p.y, c[k].p.y));
            stat_add(s, e, e / HARD_PART2_TOL_U);
            s->fails += !hard_check2(&c[k], p);
        }
    }
    printf("\n### Part 2: pixel_coordinates (error of x in u |x|, of y in u |y|; tolerance %g)\n\n%s",
           HARD_PART2_TOL_U, HEADER);
    for (int f = 0; f < nf; f++)
        table_row(&tab, f, c[f].family, false);
    table_free(&tab);
    free(c);
}

static void part3a(uint64_t seed, int per)
{
    int nf = HARD_PART3A_FAMILIES, n = nf * per;
    HardCase3a *c = malloc((size_t)n * sizeof *c);
    hard_part3a(seed, c, n);
    Table tab = table_new(nf, per);
    for (int k = 0; k < n; k++) {
        const OracleHit *o = &c[k].expect;
        tab.hits[k % nf] += o->hit;
        tab.amb[k % nf] += o->ambiguous;
        for (int m = 0; m < 2; m++) {
            Stat *s = table_stat(&tab, m, k % nf);
            double t = 0;
            bool hit = (m ? textbook_intersect : sphere_intersect)(&c[k].sphere, &c[k].ray, &t);
            s->fails += !hard_check3a(&c[k], hit, t);
            if (hit && o->hit && !o->ambiguous) {
                double tol = oracle_sphere_t_tolerance(&c[k].sphere, &c[k].ray, o);
                stat_add(s, rel_u(t, o->t), fabs(t - o->t) / tol);
            }
        }
    }
    printf("\n### Part 3a: sphere_intersect (relative error of t, in u; tolerance %g u kappa)\n\n", ORACLE_K_T);
    printf(HIT_HEADER, "textbook");
    for (int f = 0; f < nf; f++)
        table_row(&tab, f, c[f].family, true);
    table_free(&tab);
    free(c);
}

static void part3b(uint64_t seed, int per)
{
    int nf = HARD_PART3B_FAMILIES, n = nf * per;
    HardCase3b *c = malloc((size_t)n * sizeof *c);
    hard_part3b(seed, c, n);
    printf("\n### Part 3b: camera_ray (direction error, in u, tolerance %g u) and ray_color (reference only)\n\n"
           "| family | ambiguous | direction worst | median | ray fails | colour fails |\n"
           "|---|---|---|---|---|---|\n", HARD_PART3B_DIR_TOL_U);
    Stat *dir = stats_new(nf, per);
    int *amb = calloc((size_t)nf, sizeof *amb), *cfail = calloc((size_t)nf, sizeof *cfail);
    for (int k = 0; k < n; k++) {
        Ray ray = camera_ray(c[k].eye, c[k].pixel);
        Vec3 u = c[k].ray.direction;
        double e = fmax(fabs(ray.direction.x - u.x), fmax(fabs(ray.direction.y - u.y), fabs(ray.direction.z - u.z))) / U;
        stat_add(&dir[k % nf], e, e / HARD_PART3B_DIR_TOL_U);
        dir[k % nf].fails += !hard_check3b_ray(&c[k], ray);
        Scene scene = hard_scene3b(&c[k]);
        cfail[k % nf] += !hard_check3b_color(&c[k], ray_color(&scene, &c[k].ray));
        amb[k % nf] += c[k].ambiguous;
    }
    for (int f = 0; f < nf; f++) {
        qsort(dir[f].err, (size_t)dir[f].n, sizeof *dir[f].err, cmp_double);
        printf("| %s | %d | %.3g | %.3g | %d | %d |\n", c[f].family, amb[f],
               dir[f].err[dir[f].n - 1], dir[f].err[dir[f].n / 2], dir[f].fails, cfail[f]);
    }
    free(amb);
    free(cfail);
    stats_free(dir, nf);
    free(c);
}

static void flat_answer(Stat *s, const OracleFlat *o, bool ok, bool hit, double t)
{
    s->fails += !ok;
    if (hit && o->hit && !o->ambiguous)
        stat_add(s, rel_u(t, o->t), fabs(t - o->t) / o->tol);
}

static void part4(uint64_t seed, int per)
{
    int nf = HARD_PART4_FAMILIES, n = nf * per;
    HardCase4 *c = malloc((size_t)n * sizeof *c);
    hard_part4(seed, c, n);
    Table tab = table_new(nf, per);
    for (int k = 0; k < n; k++) {
        tab.hits[k % nf] += c[k].expect.hit;
        tab.amb[k % nf] += c[k].expect.ambiguous;
        for (int m = 0; m < 2; m++) {
            double t = 0;
            bool hit = (m ? textbook_plane : plane_intersect)(&c[k].plane, &c[k].ray, &t);
            flat_answer(table_stat(&tab, m, k % nf), &c[k].expect, hard_check4(&c[k], hit, t), hit, t);
        }
    }
    printf("\n### Part 4: plane_intersect (relative error of t, in u; tolerance %g u kappa)\n\n", ORACLE_K_T);
    printf(HIT_HEADER, "p.n - e.n");
    for (int f = 0; f < nf; f++)
        table_row(&tab, f, c[f].family, true);
    table_free(&tab);
    free(c);
}

static void part5(uint64_t seed, int per)
{
    int nf = HARD_PART5_FAMILIES, n = nf * per;
    HardCase5 *c = malloc((size_t)n * sizeof *c);
    hard_part5(seed, c, n);
    /* the triangles' families, then the meshes' */
    Table tab = table_new(nf + HARD_MESH_FAMILIES, per + HARD_MESH_RAYS);
    for (int k = 0; k < n; k++) {
        tab.hits[k % nf] += c[k].expect.hit;
        tab.amb[k % nf] += c[k].expect.ambiguous;
        for (int m = 0; m < 2; m++) {
            double t = 0;
            bool hit = (m ? textbook_triangle : triangle_intersect)(&c[k].tri, &c[k].ray, &t);
            flat_answer(table_stat(&tab, m, k % nf), &c[k].expect, hard_check5(&c[k], hit, t), hit, t);
        }
    }
    printf("\n### Part 5: triangle_intersect (relative error of t, in u; tolerance %g u kappa)\n\n", ORACLE_K_T);
    printf(HIT_HEADER, "Moller-Trumbore");
    for (int f = 0; f < nf; f++)
        table_row(&tab, f, c[f].family, true);

    /* Closed meshes: per rays of HARD_MESH_RAYS, the first hit over the
     * mesh must be where the ray enters.  Their rows count the rays in the
     * hits column (none is ambiguous). */
    int nm = (per + HARD_MESH_RAYS - 1) / HARD_MESH_RAYS * HARD_MESH_FAMILIES;
    HardMesh *ms = malloc((size_t)nm * sizeof *ms);
    hard_meshes(seed, ms, nm);
    char name[HARD_MESH_FAMILIES][HARD_FAMILY_LEN];
    for (int k = 0; k < nm; k++) {
        int f = k % HARD_MESH_FAMILIES;
        snprintf(name[f], sizeof name[f], "%s", ms[k].family);
        tab.hits[nf + f] += HARD_MESH_RAYS;
        for (int r = 0; r < HARD_MESH_RAYS; r++)
            for (int m = 0; m < 2; m++) {
                bool any = false;
                double best = INFINITY;
                for (int i = 0; i < ms[k].ntris; i++) {
                    double t;
                    if ((m ? textbook_triangle : triangle_intersect)(&ms[k].tris[i], &ms[k].rays[r], &t)
                        && t < best) {
                        best = t;
                        any = true;
                    }
                }
                flat_answer(table_stat(&tab, m, nf + f), &ms[k].expect[r],
                            hard_check_mesh(&ms[k], r, any, best), any, best);
            }
    }
    for (int f = 0; f < HARD_MESH_FAMILIES; f++)
        table_row(&tab, nf + f, name[f], true);
    free(ms);
    table_free(&tab);
    free(c);
}

int main(int argc, char **argv)
{
    int per = argc > 1 ? atoi(argv[1]) : 2000;
    uint64_t seed = argc > 2 ? strtoull(argv[2], NULL, 0) : 1;
    if (per < 1) {
        fprintf(stderr, "usage: accuracy [cases per family [seed]]\n");
        return 2;
    }
    printf("## Accuracy on the hard families (%d cases per family, seed %llu)\n",
           per, (unsigned long long)seed);
    part1(seed, per);
    part2(seed, per);
    part3a(seed, per);
    part3b(seed, per);
    part4(seed, per);
    part5(seed, per);
    return 0;
}
