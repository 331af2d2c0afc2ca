/*
 * bench.h - `make bench`: how much speed each ray/sphere formulation buys
 * and how much accuracy it costs.
 *
 * The pieces, one job per file, are listed in README.md beside them (with
 * the results); this header declares them all.
 *
 * Everything the bench writes goes to one directory (out/bench by default).
 */
#ifndef BENCH_H
#define BENCH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "raytracer.h"
#include "../oracle/oracle.h"

/* ---- float counterparts of the lab's types ------------------------------ */
typedef struct { float x, y, z; } Vec3f;
typedef struct { Vec3f origin, direction; } Rayf;
typedef struct { Vec3f center; float radius; } Spheref;

Vec3f vec3f_from(Vec3 v);                 /* each component rounded to float */
Spheref spheref_from(const Sphere *s);
Rayf rayf_from(const Ray *r);

/* ---- methods.c: one ray against one sphere ------------------------------ */
/* All follow the lab's contract for sphere_intersect (smallest t > 0; a miss
 * returns false), except where a method's own assumption is stated. */
typedef bool (*IsectD)(const Sphere *sphere, const Ray *ray, double *t);
typedef bool (*IsectF)(const Spheref *sphere, const Rayf *ray, float *t);

bool isect_textbook_d(const Sphere *sphere, const Ray *ray, double *t);
bool isect_textbook_f(const Spheref *sphere, const Rayf *ray, float *t);
bool isect_unit_d(const Sphere *sphere, const Ray *ray, double *t);      /* assumes |r| = 1 */
bool isect_unit_f(const Spheref *sphere, const Rayf *ray, float *t);
bool isect_geometric_d(const Sphere *sphere, const Ray *ray, double *t); /* assumes |r| = 1 */
bool isect_geometric_f(const Spheref *sphere, const Rayf *ray, float *t);
bool isect_rtg_d(const Sphere *sphere, const Ray *ray, double *t);
bool isect_rtg_f(const Spheref *sphere, const Rayf *ray, float *t);
bool isect_reference_f(const Spheref *sphere, const Rayf *ray, float *t);
/* The same transliteration compiled as double: the benchmark checks that it
 * agrees with the linked sphere_intersect (which it times as "reference"). */
bool isect_reference_d(const Sphere *sphere, const Ray *ray, double *t);
/* The closest-hit loop over spheres with one of the above (methods_body.h). */
void closest_d(IsectD fn, const Sphere *spheres, int n, const Ray *rays, int nrays, int *idx,
               double *t);
void closest_f(IsectF fn, const Spheref *spheres, int n, const Rayf *rays, int nrays, int *idx,
               double *t);
/* Which of the reference's tests decides a pair (methods.c): its miss test
 * sums |f x r|^2 a term at a time and stops after one, two or three terms;
 * the rest go on to the roots, or to the careful branch. */
enum { REF_STAGE_NX, REF_STAGE_NXY, REF_STAGE_NN, REF_STAGE_ROOTS, REF_STAGE_CAREFUL, REF_STAGES };
int reference_stage(const Sphere *sphere, const Ray *ray);

/* ---- fastpath.c: the specialised fast path ------------------------------ */
/* Rays start at the eye (the origin of the sphere coordinates given to
 * fast_build) and have unit direction (to a few ulps).  Per sphere, built
 * once: the centre c, R^2, C = |c|^2 - R^2 rounded once from an exact
 * computation, and a threshold below which b = c.r is a certain miss.  Per
 * ray and sphere the vector loop computes only b and compares it with the
 * threshold: no sqrt, no division, no branch.  Packets of rays where some
 * ray passes are then solved accurately (Ray Tracing Gems' discriminant),
 * the nearest hit kept. */
#define FAST_PACKET 16                    /* rays per packet */

typedef struct {
    int n;
    double *cx, *cy, *cz;     /* centres, relative to the eye              */
    double *r2;               /* R^2                                       */
    double *c;                /* |c|^2 - R^2, rounded once from exact      */
    double *bthr;             /* b = c.r below this: certainly a miss      */
    float *fcx, *fcy, *fcz;   /* the same in float                         */
    float *fr2, *fc, *fbthr;
} FastScene;

/* Builds the fast path's scene from spheres, with the eye at eye.
 * Returns 0, or -1 if out of memory. */
int fast_build(FastScene *fs, const Sphere *spheres, int n, Vec3 eye);
void fast_free(FastScene *fs);

/* Nearest hit for count rays with unit directions (dx, dy, dz)[i] from the
 * eye: idx[i] = sphere index or -1, t[i] = its t (INFINITY on a miss).
 * count need not be a multiple of FAST_PACKET. */
void fast_closest_d(const FastScene *fs, const double *dx, const double *dy, const double *dz,
                    int count, int *idx, double *t);
void fast_closest_f(const FastScene *fs, const float *dx, const float *dy, const float *dz,
                    int count, int *idx, double *t);
/* Float filter, double solve: needs both copies of the directions. */
void fast_closest_m(const FastScene *fs, const float *fdx, const float *fdy, const float *fdz,
                    const double *dx, const double *dy, const double *dz,
                    int count, int *idx, double *t);

/* The double fast path's filter alone, as fast_closest_d runs it (two
 * spheres per pass where it can), with no solve: the (packet, sphere)
 * pairs that pass, or whose sphere holds the eye: those the double path
 * solves.  The bench counts them for the report, and times it to split the
 * fast path's time. */
long fast_filter_only(const FastScene *fs, const double *dx, const double *dy, const double *dz,
                      int count);

/* ---- workload.c: rays -------------------------------------------------- */
/* A set of rays in every layout a method may want. */
typedef struct {
    int n;
    Ray *rays;                        /* array of structures, double  */
    Rayf *raysf;                      /* array of structures, float   */
    double *dx, *dy, *dz;             /* structure of arrays, double  */
    float *fdx, *fdy, *fdz;           /* structure of arrays, float   */
} RaySet;

int rayset_alloc(RaySet *rs, int n);
void rayset_free(RaySet *rs);
enum { LAYOUT_AOS_D = 1, LAYOUT_AOS_F = 2, LAYOUT_SOA_D = 4, LAYOUT_SOA_F = 8 };
void rayset_put(RaySet *rs, int i, Ray ray, unsigned layouts);   /* in those (~0u: all) */

/* Camera rays through an nx x ny grid of pixel centres for scene (its fov
 * and d, the given size), every step-th pixel in each direction. */
int rayset_camera(RaySet *rs, const Scene *scene, int nx, int ny, int step);

/* One test case: a sphere and a ray. */
typedef struct {
    Sphere sphere;
    Ray ray;
} Case;

typedef enum { FAMILY_SCENE, FAMILY_FAR, FAMILY_NEAR, FAMILY_TANGENT, FAMILY_COUNT } Family;
extern const char *const family_names[FAMILY_COUNT], *const family_titles[FAMILY_COUNT];

/* Generates n cases of a hard family with a fixed seed.  Directions have
 * unit length (rounded).  Returns a malloc'd array or NULL. */
Case *cases_hard(Family f, int n, uint64_t seed);
/* Every (camera ray, sphere) pair of scene at its own size, every step-th
 * pixel in each direction: *n cases. */
Case *cases_scene(const Scene *scene, int step, int *n);

/* ---- suite.c: the methods ---------------------------------------------- */
typedef enum { PREC_DOUBLE, PREC_FLOAT, PREC_MIXED } Precision;
const char *precision_name(Precision p);
/* A method's name and precision, sep between them, into buf (METHOD_LABEL
 * bytes): "fast double" labels it on the plots and in the text, "fast |
 * double" and "fast,double" are its cells in markdown and CSV.  Returns buf. */
#define METHOD_LABEL 48
char *method_cells(char *buf, const char *name, Precision p, const char *sep);

typedef struct {
    const Sphere *spheres;    /* the scene, double                    */
    const Spheref *spheresf;  /* the same, rounded to float           */
    int n;
    const FastScene *fast;
} BenchScene;

typedef struct {
    const char *name;         /* short id, as in results.csv                */
    Precision precision;
    bool unit_dir;            /* assumes |r| = 1 (else: give it r / |r|)    */
    unsigned layouts;         /* the ray layouts closest reads (LAYOUT_*)   */
    /* The function itself, for the scalar methods (both NULL: the fast path). */
    IsectD scalar_d;
    IsectF scalar_f;
} Method;

extern const Method bench_methods[];
extern const int bench_nmethods;
/* The methods by index, in bench_methods' order: name and precision (M: mixed). */
enum { TEXTBOOK_D, TEXTBOOK_F, UNIT_D, UNIT_F, GEOMETRIC_D, GEOMETRIC_F, RTG_D, RTG_F,
       REFERENCE_D, REFERENCE_F, FAST_D, FAST_F, FAST_M };
/* One test: hit and t, computed at the method's precision. */
bool method_one(const Method *m, const Sphere *sphere, const Ray *ray, double *t);
/* Nearest hit for rays [0, rs->n): idx[i], t[i] as fast_closest_d. */
void method_closest(const Method *m, const BenchScene *scene, const RaySet *rs, int *idx,
                    double *t);

/* ---- errors of one method on one workload, against the oracle ------------ */
typedef struct {
    long tests;                /* cases                                    */
    long ambiguous;            /* oracle: either answer acceptable         */
    long wrong;                /* hit/miss differs, not ambiguous          */
    long hits;                 /* both hit, not ambiguous: t compared      */
    long over_tol;             /* of those, error above ORACLE_K_T u kappa
                                  (reported for the spheres)               */
    long hard_failed;          /* the grader's rule, oracle_flat_accepts   */
    double max_rel, median_rel;
    double max_over_kappa;     /* max of error / (u kappa)                 */
    double max_u_well;         /* max error in u where kappa <= 100
                                  (reported for the triangles)             */
} ErrorStats;

/* Counts one case in e (tests aside): the method's answer (hit, t) against
 * the exact one (exact_hit, exact_t, kappa; either is right when
 * ambiguous); a compared hit's relative error goes to rel[e->hits]
 * (accuracy.c). */
void errors_add(ErrorStats *e, bool ambiguous, bool exact_hit, double exact_t, double kappa,
                bool hit, double t, double *rel);

/* Wrong hit/miss answers per million cases the oracle is sure of. */
double wrong_per_million(const ErrorStats *s);
double per_million(long count, long of);       /* 0 if of is 0 */

/* ---- tri_methods.c, triangles.c: Part 5 ------------------------------------- */
typedef struct { Vec3f a, b, c; } Trianglef;

bool tri_moller_trumbore_d(const Triangle *tri, const Ray *ray, double *t);
bool tri_moller_trumbore_f(const Trianglef *tri, const Rayf *ray, float *t);
bool tri_wbw_plain_d(const Triangle *tri, const Ray *ray, double *t);
bool tri_geometric_d(const Triangle *tri, const Ray *ray, double *t);

typedef struct {
    const char *name;
    Precision precision;
    bool (*fn_d)(const Triangle *tri, const Ray *ray, double *t);     /* or */
    bool (*fn_f)(const Trianglef *tri, const Rayf *ray, float *t);
} TriMethod;

#define TRI_MAX_METHODS 8
extern const TriMethod tri_methods[];
extern const int tri_nmethods;


/* The four kinds of crack rays: at shared edges and shared vertices, of
 * meshes near the origin and at offsets 10^3 to 10^6. */
enum { CRACK_EDGE, CRACK_VERTEX, CRACK_FAR_EDGE, CRACK_FAR_VERTEX, CRACK_KINDS };

typedef struct {
    bool ran;
    int tp_rays, tp_triangles;             /* the throughput workload         */
    double mtests[TRI_MAX_METHODS];        /* million tests per second        */
    ErrorStats ordinary[TRI_MAX_METHODS];  /* triangles in view, camera rays  */
    ErrorStats hard[TRI_MAX_METHODS];      /* Part 5's hard families          */
    long crack_rays_per_kind;              /* rays aimed, per kind            */
    long rays[TRI_MAX_METHODS][CRACK_KINDS];   /* of them, judged for the
                                              method: those whose mesh its
                                              precision can place           */
    long cracks[TRI_MAX_METHODS][CRACK_KINDS]; /* of those, rays through     */
    long missed_all[TRI_MAX_METHODS];      /* judged rays no triangle hit
                                              anywhere                       */
    double min_chord;                      /* shortest chord / entry t seen  */
    double max_entry_gap;                  /* largest |clipped entry t -
                                              constructed entry t| / t     */
} TriResults;

/* Runs the three steps (scenes: the directory of cracks.scene).  Returns
 * 0, or -1 with a reason in err. */
int triangle_bench(const char *scenes, bool quick, uint64_t seed, TriResults *tr, char *err,
                   size_t errlen);
/* results_triangles.csv and plot_triangles.svg in dir; 0, or -1 with err. */
int triangles_write(const TriResults *tr, const char *dir, const char *subtitle, char *err,
                    size_t errlen);
/* The section of report.md. */
void triangles_md(FILE *f, const TriResults *tr);

/* ---- scaling.c: Part 5 at scale ------------------------------------------- */
#define SCALE_MAX 7

/* One mesh, rendered with the hierarchy and without. */
typedef struct {
    int triangles, nodes;
    double read_seconds;            /* scene_load, the OBJ file included        */
    double build_seconds;           /* the hierarchy, and its probe             */
    double seconds_with, seconds_without;   /* median render times              */
    int pixels_with, pixels_without;        /* of images of the same view       */
} ScaleRow;

typedef struct {
    bool ran;
    int n, nx, ny;                  /* meshes; the size rendered with the hierarchy */
    int reps;                       /* renders of each, the median taken        */
    double budget;                  /* tests a render without the hierarchy     */
    char paths[SCALE_MAX][1100];    /* each mesh's scene                        */
    ScaleRow rows[SCALE_MAX];
    double e2e_seconds, e2e_bytes;  /* the render program on the largest mesh:
                                       wall time, peak resident memory          */
    double ratio_big, ratio_small;  /* render times of 10^6 and 10^4 triangles,
                                       taken in turn (0: not measured)          */
} ScaleResults;

/* Writes the meshes and their scenes into dir (scenes: the directory of
 * knot.scene) and runs render, the render program, on the largest: to be
 * called before the bench has grown (scaling.c).  Returns 0, or -1 with a
 * reason in err. */
int scaling_prepare(const char *dir, const char *scenes, const char *render, bool quick,
                    ScaleResults *sr, char *err, size_t errlen);
/* Measures each mesh.  Returns 0, or -1 with a reason in err. */
int scaling_bench(bool quick, ScaleResults *sr, char *err, size_t errlen);
/* results_scaling.csv and plot_scaling.svg in dir; 0, or -1 with err. */
int scaling_write(const ScaleResults *sr, const char *dir, const char *subtitle, char *err,
                  size_t errlen);
/* The section of report.md. */
void scaling_md(FILE *f, const ScaleResults *sr);

/* ---- measure.c: time, clock, ceiling ------------------------------------ */
double now_seconds(void);                    /* CLOCK_MONOTONIC */
/* The text after the colon of /proc/cpuinfo's first line that starts with
 * key, into out (len bytes); false without /proc or such a line. */
bool cpuinfo(const char *key, char *out, size_t len);
double median(double *v, int n);             /* sorts v */
double quantile(double *v, int n, double q); /* v sorted */

typedef struct {
    double mhz_cpuinfo;        /* from /proc/cpuinfo, 0 if not available   */
    double mhz_measured;       /* from a dependent integer-add loop (median
                                  of readings between throughput rounds)    */
    double mhz;                /* the one used                              */
    double mul_per_cycle;      /* independent vector multiplies per cycle   */
    double add_per_cycle;      /* independent vector adds per cycle         */
    double mix_per_cycle;      /* the two interleaved                       */
    double mul_pipes, add_pipes, mix_pipes;   /* the same, rounded          */
    double sqrt_per_cycle;     /* square roots per cycle, per lane (as the
                                  fast path's solve is compiled)            */
    double div_per_cycle;      /* divisions per cycle, per lane (likewise)  */
    double cycles_per_vector;  /* for one vector of tests                   */
    int lanes_d, lanes_f;      /* vector lanes the portable build uses      */
    int ops_mul, ops_add;      /* per test, the minimum for the lab scene   */
    double ceiling_d, ceiling_f;   /* million tests per second              */
} Ceiling;

/* Measures the pipes and fills c.  mhz_during: the clock measured while the
 * methods ran (0: measure it here). */
void measure_ceiling(Ceiling *c, bool quick, double mhz_during);

/* Interleaved rounds: every round visits each of n items once, in an
 * order rotated by one every round, so that a slow spell or a warm cache
 * favours no item.  In
 *     for (Rounds it = { .n = n, .rounds = rounds }; rounds_next(&it);)
 * it.r is the round, it.m the item, it.j its place in the round, it.k - 1
 * the turns before this one.  Item m's sample of round r goes to
 * samples[m * rounds + r]. */
typedef struct { int n, rounds, k, r, j, m; } Rounds;
bool rounds_next(Rounds *it);

/* Times every method's closest loop over rs, interleaved: rounds rounds,
 * each running every method once (for about sample_s seconds).  Stores
 * pass_seconds[m * rounds + r], the time of one pass of method m in round
 * r, and round_mhz[r], the clock measured after round r.  Returns 0, or -1
 * if out of memory. */
int measure_throughput(const BenchScene *sc, const RaySet *rs, int rounds, double sample_s,
                       double *pass_seconds, double *round_mhz);

/* Cost per test by outcome, for the scalar methods: every method calls its
 * function on the same (sphere, ray) pairs, first pairs that miss, then pairs
 * that hit, interleaved over rounds; medians in ns per call.  Methods
 * without a scalar function get NAN.  Returns 0, or -1 if out of memory. */
int measure_outcomes(const Case *miss, int nmiss, const Case *hit, int nhit, int rounds,
                     double sample_s, double *miss_ns, double *hit_ns);

/* ---- accuracy.c ---------------------------------------------------------- */

/* Exact answers for cases (oracle_sphere's), computed once. */
OracleHit *exact_answers(const Case *cases, int n);

/* Errors of method m on cases.  errs (room for n) receives the relative
 * errors of the compared hits, *nerrs of them. */
void accuracy_run(const Method *m, const Case *cases, const OracleHit *exact, int n,
                  ErrorStats *st, double *errs, long *nerrs);

/* ---- renders.c ------------------------------------------------------------ */
typedef struct {
    char scene[64];            /* file name without directory or .scene */
    int nspheres;
    int nx, ny;
    long pixels, ambiguous;    /* ambiguous: the exact render allows two colours */
    double seconds[32];        /* per method: median render time, one thread */
    double rays_seconds;       /* making the rays alone (every renderer does) */
    long differ[32];           /* per method: pixels not as the exact render */
} RenderResult;

/* Renders the scene at path at nx x ny with every method, reps times
 * interleaved, and compares each with the exact render (oracle_closest).
 * Returns 0, 1 for a scene with planes or triangles (skipped: the methods
 * are ray/sphere ones), or -1 with a reason in err. */
int render_bench(const char *path, int nx, int ny, int reps, RenderResult *res,
                 char *err, size_t errlen);

/* ---- report.c ------------------------------------------------------------- */
#define BENCH_MAX_METHODS 32
#define BENCH_MAX_SCENES 16

typedef struct {
    /* how it ran */
    bool quick;
    char date[64], cpu[128], compiler[128];
    double load_before, load_after;      /* 1-minute load average, -1 if unknown */
    double seconds_total;
    uint64_t seed;
    int rounds;                          /* throughput rounds                 */
    int tp_rays, tp_spheres;             /* the throughput workload           */
    int family_cases[FAMILY_COUNT];
    int render_reps;
    /* per method */
    double mtests[BENCH_MAX_METHODS], mtests_q1[BENCH_MAX_METHODS], mtests_q3[BENCH_MAX_METHODS];
    ErrorStats fam[BENCH_MAX_METHODS][FAMILY_COUNT];
    ErrorStats all[BENCH_MAX_METHODS];   /* the families pooled */
    /* reference / textbook, double, the ordinary scene */
    double ratio_of_medians, ratio_paired, ratio_q1, ratio_q3;
    /* the same ratio measured by the same objects linked in another order
     * (bench --placement FILE; placed is false without it) */
    bool placed;
    double placed_ratio, placed_q1, placed_q3;
    /* the reference's miss test on the throughput workload: pairs decided at
     * each stage (reference_stage), and exits that sphere_intersect
     * contradicts (must be 0) */
    long ref_stage[REF_STAGES], ref_stage_pairs, ref_stage_wrong;
    /* the fast path's (packet, sphere) pairs on that workload, and those solved */
    long fast_pairs, fast_solved;
    /* the filter alone (fast_filter_only) on that workload: Mtests per second,
     * the median of the rounds, timed after the throughput rounds */
    double fast_filter_mtests;
    /* ns per call on pairs of the ordinary scene that miss and that hit */
    double miss_ns[BENCH_MAX_METHODS], hit_ns[BENCH_MAX_METHODS];
    double hit_share;                    /* share of the scene's tests that hit */
    /* the float transliteration, compiled as double, against the linked
     * reference: cases compared and cases that differ (must be 0) */
    long translit_cases, translit_differ;
    /* the grader's hard cases (tests/oracle/hard.h), judged by its rule */
    int grader_cases;
    int grader_failed[BENCH_MAX_METHODS];
    Ceiling ceiling;
    RenderResult renders[BENCH_MAX_SCENES];
    int nrenders;
    TriResults tri;                      /* Part 5 (triangles.c)              */
    ScaleResults scale;                  /* Part 5 at scale (scaling.c)       */
} BenchResults;

/* Writes results.csv, results_by_family.csv, renders.csv, report.md and
 * plot.svg into dir.  Returns 0, or -1 with a reason in err. */
int report_write(const BenchResults *br, const char *dir, char *err, size_t errlen);

/* ---- outfile.c: every output file written whole: to a temporary file beside
 * it, renamed into place once closed, so that none is ever left half-written. */
/* Opens dir/name's temporary file (".tmp" after the name) for writing.
 * Returns it, or NULL with "dir/name: cannot write" in err. */
FILE *out_open(const char *dir, const char *name, char *err, size_t errlen);

/* Closes f, opened by out_open(dir, name), and renames it over dir/name.
 * Returns 0, or -1 with "dir/name: write failed" in err and the temporary
 * file gone. */
int out_close(FILE *f, const char *dir, const char *name, char *err, size_t errlen);

/* Writes dir/name whole with body(f, data).  Returns 0, or -1 with err. */
int out_write(const char *dir, const char *name, void (*body)(FILE *f, const void *data),
              const void *data, char *err, size_t errlen);

/* ---- svg.c: the plots, drawn as SVG by hand (no plotting package): speed
 * against error on log axes, and lines on log axes. */
typedef struct {
    const char *label;      /* shown beside the point                          */
    double x;               /* error (smaller is better); 0 is drawn at 1e-18   */
    double y;               /* throughput (larger is better), > 0              */
    int group;              /* 0 double, 1 float, 2 mixed: colour and marker   */
} PlotPoint;

/* A method in the speed-against-error plot: its throughput y, and its
 * error x[k] in panel k. */
typedef struct {
    const char *name;
    Precision precision;
    double y, x[2];
} MethodPoint;

typedef struct {
    const char *title;      /* above the panel                                 */
    const char *xlabel;
} PlotPanel;

/* Writes the speed-against-error plot of n methods to dir/name: two panels,
 * one above the other, panel k with method i at (pts[i].x[k], pts[i].y),
 * labelled by method_cells and coloured by its precision; both with ylabel.
 * Returns 0, or -1 with a reason in err. */
int svg_plot(const char *dir, const char *name, const char *title, const char *subtitle,
             const MethodPoint *pts, int n, const PlotPanel panels[2], const char *ylabel,
             char *err, size_t errlen);

/* A line of points, drawn in the colour and marker of its points' group. */
typedef struct {
    const PlotPoint *pts;       /* by x; their labels are not drawn */
    int n;
    const char *label;          /* in the legend */
} PlotSeries;

/* Writes one panel of lines on log axes to dir/name.  Returns 0, or -1 with
 * a reason in err. */
int svg_lines(const char *dir, const char *name, const char *title, const char *subtitle,
              const char *xlabel, const char *ylabel, const PlotSeries *series, int nseries,
              char *err, size_t errlen);

/* ---- progress (bench_main.c) ----------------------------------------------- */
void progress(const char *step, int done, int total);

/* A sink the compiler cannot see through: measured results go here. */
extern volatile double bench_sink;

#endif
