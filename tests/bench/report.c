/*
 * report.c - the benchmark's output files:
 *   results.csv            one row per method and precision: throughput on
 *                          the ordinary scene, errors over all families
 *   results_by_family.csv  the errors family by family
 *   renders.csv            the render-level results
 *   report.md              the tables, and what they show in plain words
 *   plot.svg               throughput against error (svg.c)
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "bench.h"

#define RATIO_TARGET 1.05          /* reference / textbook, at most             */
#define SPEEDUP_TARGET 4.0         /* fast path / textbook scalar loop, at least */
#define SHARE_TARGET 0.50          /* fast path (double) / the double ceiling    */

/* ---- small helpers --------------------------------------------------------------- */

/* Method m's throughput over its precision's ceiling. */
static double share(const BenchResults *br, int m)
{
    double c = bench_methods[m].precision == PREC_DOUBLE ? br->ceiling.ceiling_d
                                                         : br->ceiling.ceiling_f;
    return c > 0 ? br->mtests[m] / c : 0;
}

/* The share of the throughput workload's pairs that the reference's
 * miss test decides at stage k. */
static double stage_share(const BenchResults *br, int k)
{
    return br->ref_stage_pairs > 0 ? (double)br->ref_stage[k] / (double)br->ref_stage_pairs : 0;
}

/* Numbers as text, from a pool of buffers so one printf can use several. */
static char *pool(void)
{
    static char bufs[32][METHOD_LABEL];
    static int next;
    next = (next + 1) % 32;
    return bufs[next];
}

/* v as text: "0", or in format large from limit up, else in small. */
static const char *num(double v, double limit, const char *small, const char *large)
{
    if (v == 0)
        return "0";
    char *b = pool();
    snprintf(b, METHOD_LABEL, v >= limit ? large : small, v);
    return b;
}

static const char *E(double v)            /* an error: 0 or two digits */
{
    return num(v, -INFINITY, "%.1e", "%.1e");
}

static const char *W(double v)            /* wrong answers per million */
{
    return num(v, 10, "%.2g", "%.0f");
}

static const char *P(double fraction)     /* a share as a percentage */
{
    return num(100 * fraction, 10, "%.2g%%", "%.0f%%");
}

/* Method m's name and precision, sep between them (method_cells). */
static const char *cells(int m, const char *sep)
{
    return method_cells(pool(), bench_methods[m].name, bench_methods[m].precision, sep);
}

/* ---- CSV ------------------------------------------------------------------------- */

/* Each file's body, for out_write (outfile.c): data is the BenchResults. */
static void csv_results(FILE *f, const void *data)
{
    const BenchResults *br = data;
    fprintf(f, "method,precision,mtests_per_s,mtests_per_s_q1,mtests_per_s_q3,share_of_ceiling,"
               "max_rel_err,median_rel_err,wrong_per_million,max_err_over_u_kappa,"
               "tests,ambiguous,wrong,compared_hits,ns_per_miss,ns_per_hit,"
               "grader_hard_failed,grader_hard_cases\n");
    for (int m = 0; m < bench_nmethods; m++) {
        const ErrorStats *s = &br->all[m];
        fprintf(f, "%s,%.2f,%.2f,%.2f,%.4f,%.3e,%.3e,%.2f,%.3e,%ld,%ld,%ld,%ld,", cells(m, ","),
                br->mtests[m], br->mtests_q1[m], br->mtests_q3[m], share(br, m), s->max_rel,
                s->median_rel, wrong_per_million(s), s->max_over_kappa, s->tests, s->ambiguous,
                s->wrong, s->hits);
        if (isnan(br->miss_ns[m]))
            fprintf(f, ",,");                   /* not a scalar method */
        else
            fprintf(f, "%.3f,%.3f,", br->miss_ns[m], br->hit_ns[m]);
        fprintf(f, "%d,%d\n", br->grader_failed[m], br->grader_cases);
    }
}

static void csv_families(FILE *f, const void *data)
{
    const BenchResults *br = data;
    fprintf(f, "family,method,precision,tests,ambiguous,wrong,wrong_per_million,compared_hits,"
               "max_rel_err,median_rel_err,max_err_over_u_kappa,over_tolerance\n");
    for (int fam = 0; fam < FAMILY_COUNT; fam++)
        for (int m = 0; m < bench_nmethods; m++) {
            const ErrorStats *s = &br->fam[m][fam];
            fprintf(f, "%s,%s,%ld,%ld,%ld,%.2f,%ld,%.3e,%.3e,%.3e,%ld\n", family_names[fam],
                    cells(m, ","), s->tests, s->ambiguous, s->wrong, wrong_per_million(s),
                    s->hits, s->max_rel, s->median_rel, s->max_over_kappa, s->over_tol);
        }
}

static void csv_renders(FILE *f, const void *data)
{
    const BenchResults *br = data;
    fprintf(f, "scene,width,height,spheres,method,precision,seconds,mrays_per_s,"
               "differ_pixels,differ_share,ambiguous_pixels,rays_only_seconds\n");
    for (int s = 0; s < br->nrenders; s++) {
        const RenderResult *r = &br->renders[s];
        for (int m = 0; m < bench_nmethods; m++)
            fprintf(f, "%s,%d,%d,%d,%s,%.4f,%.2f,%ld,%.6f,%ld,%.4f\n", r->scene, r->nx, r->ny,
                    r->nspheres, cells(m, ","), r->seconds[m],
                    (double)r->pixels / r->seconds[m] / 1e6, r->differ[m],
                    (double)r->differ[m] / (double)r->pixels, r->ambiguous, r->rays_seconds);
    }
}

/* ---- the plots ---------------------------------------------------------------------- */

/* A plot's subtitle: how the bench ran (a quick run or not, the CPU, one
 * thread), then fmt's text. */
static const char *subtitle(const BenchResults *br, const char *fmt, ...)
{
    static char sub[400];
    int n = snprintf(sub, sizeof sub, "%s%s, one thread, ",
                     br->quick ? "QUICK RUN (small sizes): " : "", br->cpu);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(sub + n, sizeof sub - (size_t)n, fmt, ap);
    va_end(ap);
    return sub;
}

static int write_plot(const BenchResults *br, const char *dir, char *err, size_t errlen)
{
    MethodPoint pts[BENCH_MAX_METHODS];
    for (int m = 0; m < bench_nmethods; m++)
        pts[m] = (MethodPoint){ bench_methods[m].name, bench_methods[m].precision, br->mtests[m],
                                { br->all[m].max_rel, br->all[m].max_over_kappa } };
    static const PlotPanel panels[2] = {
        { "Worst relative error in t, over the scene and the hard families",
          "max |t - t_exact| / t_exact (log scale; smaller is better)" },
        { "The same error in units of what rounding the input alone can cause (u kappa)",
          "max |t - t_exact| / (u kappa t_exact), u = 2^-53 (log scale; about 1 is the best "
          "possible)" },
    };
    const char *sub = subtitle(br, "-O2; throughput on default.scene (%d rays x %d spheres); "
                                   "errors on %d cases", br->tp_rays, br->tp_spheres,
                               br->family_cases[0] + br->family_cases[1] +
                                   br->family_cases[2] + br->family_cases[3]);
    return svg_plot(dir, "plot.svg", "Ray/sphere intersection: speed against accuracy", sub, pts,
                    bench_nmethods, panels, "million ray/sphere tests per second", err, errlen);
}

/* ---- report.md ----------------------------------------------------------------------- */

static void md_results_table(FILE *f, const BenchResults *br)
{
    fprintf(f, "| method | precision | Mtests/s | IQR | share of ceiling | max rel. error | "
               "median rel. error | wrong per million | max error / (u kappa) | "
               "grader's hard cases failed |\n");
    fprintf(f, "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int m = 0; m < bench_nmethods; m++) {
        const ErrorStats *s = &br->all[m];
        fprintf(f, "| %s | %.0f | %.0f-%.0f | %s | %s | %s | %s | %s | %d / %d |\n",
                cells(m, " | "), br->mtests[m], br->mtests_q1[m], br->mtests_q3[m], P(share(br, m)),
                E(s->max_rel), E(s->median_rel), W(wrong_per_million(s)), E(s->max_over_kappa),
                br->grader_failed[m], br->grader_cases);
    }
}

static void md_family_table(FILE *f, const BenchResults *br, int fam)
{
    fprintf(f, "| method | precision | max rel. error | median rel. error | wrong per million | "
               "max error / (u kappa) | hits compared |\n");
    fprintf(f, "|---|---|---:|---:|---:|---:|---:|\n");
    for (int m = 0; m < bench_nmethods; m++) {
        const ErrorStats *s = &br->fam[m][fam];
        fprintf(f, "| %s | %s | %s | %s | %s | %ld |\n", cells(m, " | "), E(s->max_rel),
                E(s->median_rel), W(wrong_per_million(s)), E(s->max_over_kappa), s->hits);
    }
}

static void md_render_table(FILE *f, const BenchResults *br)
{
    if (br->nrenders == 0)
        return;
    fprintf(f, "Each cell: render time in ms (one thread: making the rays and intersecting "
               "them) / share of pixels whose sphere differs from the exact render.\n\n"
               "| method | precision |");
    for (int s = 0; s < br->nrenders; s++)
        fprintf(f, " %s (%d) |", br->renders[s].scene, br->renders[s].nspheres);
    fprintf(f, "\n|---|---|");
    for (int s = 0; s < br->nrenders; s++)
        fprintf(f, "---:|");
    fprintf(f, "\n");
    for (int m = 0; m < bench_nmethods; m++) {
        fprintf(f, "| %s |", cells(m, " | "));
        for (int s = 0; s < br->nrenders; s++) {
            const RenderResult *r = &br->renders[s];
            fprintf(f, " %.0f / %s |", 1e3 * r->seconds[m],
                    P((double)r->differ[m] / (double)r->pixels));
        }
        fprintf(f, "\n");
    }
    fprintf(f, "| *rays only* | |");
    for (int s = 0; s < br->nrenders; s++)
        fprintf(f, " %.0f |", 1e3 * br->renders[s].rays_seconds);
    fprintf(f, "\n\nThe last row is the time to make the rays alone (parts 1, 2 and 3b), which "
               "every renderer spends. Pixels the exact render allows either way (within "
               "rounding of a silhouette):");
    for (int s = 0; s < br->nrenders; s++)
        fprintf(f, " %s %ld%s", br->renders[s].scene, br->renders[s].ambiguous,
                s + 1 < br->nrenders ? "," : ".\n");
}

/* The reference against the textbook: the ratio, split by outcome, and why
 * the reference costs what it costs. */
static void md_ratio(FILE *f, const BenchResults *br)
{
    int tb = TEXTBOOK_D, rd = REFERENCE_D;
    double h = br->hit_share;
    double mix_t = (1 - h) * br->miss_ns[tb] + h * br->hit_ns[tb];
    double mix_r = (1 - h) * br->miss_ns[rd] + h * br->hit_ns[rd];
    fprintf(f, "## The reference against the textbook\n\n");
    fprintf(f, "Same run, medians: the reference's closest-hit loop over the ordinary scene "
               "takes **%.3fx** the textbook's (target: at most %.2fx). ",
            br->ratio_of_medians, RATIO_TARGET);
    if (br->ratio_of_medians <= RATIO_TARGET)
        fprintf(f, "**The target is met.**\n\n");
    else if (br->ratio_q1 <= RATIO_TARGET)
        fprintf(f, "**On the target within the rounds' spread** (per-round quartiles "
                   "%.3f-%.3f): the medians miss it by %.1f%%.\n\n",
                br->ratio_q1, br->ratio_q3, 100 * (br->ratio_of_medians / RATIO_TARGET - 1));
    else
        fprintf(f, "**The target is missed by %.1f%%**: the reference would have to be %.1f%% "
                   "faster.\n\n",
                100 * (br->ratio_of_medians / RATIO_TARGET - 1),
                100 * (1 - RATIO_TARGET / br->ratio_of_medians));
    if (br->placed)
        fprintf(f, "The same objects linked in the reverse order (`bench-reordered "
                   "--ratio-only`, run just before) gave **%.3fx** (per-round quartiles "
                   "%.3f-%.3f), %s. Only the addresses of the code differ between the two "
                   "programs; before the bench aligned its functions and loops to 64 bytes, "
                   "that alone moved this ratio by up to 10%%. The target counts as met only "
                   "when it is met under both: **%s under both**.\n\n",
                br->placed_ratio, br->placed_q1, br->placed_q3,
                br->placed_ratio <= RATIO_TARGET ? "within the target" : "outside the target",
                br->placed_ratio <= RATIO_TARGET && br->ratio_of_medians <= RATIO_TARGET
                    ? "met" : "not met");
    fprintf(f, "What costs it: every scalar method called on the scene's own (sphere, ray) "
               "pairs, split by the exact answer (%.1f%% of the scene's tests hit), same run, "
               "medians:\n\n", 100 * h);
    fprintf(f, "| method | precision | ns per miss | ns per hit | hit / miss |\n"
               "|---|---|---:|---:|---:|\n");
    for (int m = 0; m < bench_nmethods; m++)
        if (!isnan(br->miss_ns[m]))
            fprintf(f, "| %s | %.2f | %.2f | %.1f |\n", cells(m, " | "), br->miss_ns[m],
                    br->hit_ns[m], br->hit_ns[m] / br->miss_ns[m]);
    double extra_miss = (1 - h) * (br->miss_ns[rd] - br->miss_ns[tb]);
    double extra_hit = h * (br->hit_ns[rd] - br->hit_ns[tb]);
    fprintf(f, "\nOn a miss the reference costs %.2fx the textbook, on a hit %.2fx; weighted by "
               "the scene's mix, %.2fx. ",
            br->miss_ns[rd] / br->miss_ns[tb], br->hit_ns[rd] / br->hit_ns[tb], mix_r / mix_t);
    if (extra_miss > 0 && extra_hit > 0)
        fprintf(f, "Of the reference's extra time, %.0f%% goes on misses and %.0f%% on hits.",
                100 * extra_miss / (extra_miss + extra_hit),
                100 * extra_hit / (extra_miss + extra_hit));
    fprintf(f, "\n\n");
    fprintf(f, "Why it costs that: the reference decides hit or miss with one accurate test, "
               "Lagrange's identity B^2 - A C = A R^2 - |f x r|^2, and sums |f x r|^2 a term "
               "at a time, stopping at the first partial sum above A R^2 (adding a term that "
               "is not negative never makes a rounded sum smaller, so such a line misses). "
               "Counting floating-point operations: a miss after n.x^2 costs 8 multiplies and "
               "6 adds or subtractions (A, R^2, A R^2 and one component of f x r), after two "
               "terms 11 and 9, after three 14 and 11; the textbook's miss costs 12 and 11 (A, "
               "B, C and B^2 - A C). Here %s of the tests stop after one term, %s after two, "
               "%s after three. A hit costs the whole sum, then B and C and the root without "
               "cancellation (q = -(B + sign(B) sqrt), t = C / q): 20 multiplies and 18 adds, "
               "one sqrt and one division, against the textbook's 12, 13, one sqrt and one "
               "division. Ray Tracing Gems' l = f - (B/A) r, with its second division, is kept "
               "only for directions so short or long that A R^2 leaves [2^-900, 2^900], which "
               "the lab's camera rays and scenes never reach.\n\n",
            P(stage_share(br, REF_STAGE_NX)), P(stage_share(br, REF_STAGE_NXY)),
            P(stage_share(br, REF_STAGE_NN)));
    fprintf(f, "Check: the float transliteration, compiled as double, gave the linked "
               "reference's answers bit for bit on %ld of %ld cases (%s).\n\n",
            br->translit_cases - br->translit_differ, br->translit_cases,
            br->translit_differ == 0 ? "transliteration: agrees"
                                     : "transliteration: STALE, update methods_body.h");
}

/* The slowest and the fastest scalar double method, in Mtests/s. */
static void scalar_double_range(const BenchResults *br, double *lo, double *hi)
{
    *lo = INFINITY, *hi = 0;
    for (int m = 0; m < bench_nmethods; m++)
        if (bench_methods[m].scalar_d) {
            *lo = br->mtests[m] < *lo ? br->mtests[m] : *lo;
            *hi = br->mtests[m] > *hi ? br->mtests[m] : *hi;
        }
}

/* The method nearest its ceiling (the first of equals). */
static int best_share(const BenchResults *br)
{
    int best = 0;
    for (int m = 0; m < bench_nmethods; m++)
        if (share(br, m) > share(br, best))
            best = m;
    return best;
}

/* The findings' item on the renders (br->nrenders > 0): the largest
 * difference from the exact render, and on default.scene what making the
 * rays costs against intersecting them (tb, rd, fd: the textbook, the
 * reference and the fast path in double). */
static void md_finding_renders(FILE *f, const BenchResults *br, int tb, int rd, int fd)
{
    long worst = 0, accurate_wrong = 0;
    int ws = 0, wm = 0, sd = 0;
    for (int s = 0; s < br->nrenders; s++) {
        for (int m = 0; m < bench_nmethods; m++)
            if (br->renders[s].differ[m] > worst) {
                worst = br->renders[s].differ[m];
                ws = s;
                wm = m;
            }
        accurate_wrong += br->renders[s].differ[rd] + br->renders[s].differ[fd];
        if (strcmp(br->renders[s].scene, "default") == 0)
            sd = s;
    }
    fprintf(f, "- **In pictures:** ");
    if (worst == 0)
        fprintf(f, "every renderer matches the exact render on every scene.");
    else
        fprintf(f, "the largest difference is %s on %s: %s of the pixels (far.scene is the "
                   "lecture's far small sphere). The reference and the double fast path "
                   "differ from the exact render in %ld pixels over all scenes.",
                cells(wm, " "), br->renders[ws].scene,
                P((double)worst / (double)br->renders[ws].pixels), accurate_wrong);
    const RenderResult *r = &br->renders[sd];
    fprintf(f, " On %s.scene at %dx%d, making the rays (parts 1, 2 and 3b) takes %.0f ms; "
               "intersecting them takes the textbook %.0f ms more and the fast path %.0f ms "
               "more%s\n",
            r->scene, r->nx, r->ny, 1e3 * r->rays_seconds,
            1e3 * (r->seconds[tb] - r->rays_seconds), 1e3 * (r->seconds[fd] - r->rays_seconds),
            r->seconds[fd] < 2 * r->rays_seconds
                ? ": with the fast path, the rays, not the spheres, are most of the time."
                : ".");
}

static void md_findings(FILE *f, const BenchResults *br)
{
    int tb = TEXTBOOK_D, tf = TEXTBOOK_F, rd = REFERENCE_D, rf = REFERENCE_F, rgd = RTG_D;
    int fd = FAST_D, ff = FAST_F, fm = FAST_M;

    /* 1. scalar speed */
    double lo, hi;
    scalar_double_range(br, &lo, &hi);
    fprintf(f, "- **One test at a time, the formula moves the speed by %.1fx at most.** The "
               "scalar double methods run at %.0f to %.0f million tests per second. Each test "
               "is a call and some twenty operations, and most tests end at "
               "the first comparison (most rays miss most spheres), so the accurate formulas' "
               "extra work shows mainly on hits (see the ns per hit below). Scalar float is no "
               "faster than scalar double (the textbook: %.0f against %.0f): one number at a "
               "time, both cost the same.\n",
            hi / lo, lo, hi, br->mtests[tf], br->mtests[tb]);
    /* 2. accuracy in double */
    const ErrorStats *far_t = &br->fam[tb][FAMILY_FAR], *far_r = &br->fam[rd][FAMILY_FAR];
    fprintf(f, "- **In double the ordinary scene hides the difference; the hard cases show "
               "it.** On default.scene the textbook's worst relative error in t is %s, the "
               "reference's %s: both far below a pixel. On far small spheres the textbook's "
               "worst is %s and it answers hit or miss wrongly %s times per million rays: "
               "B^2 - A C loses R^2 when both terms are near |f|^2, an error growing like "
               "(D/R)^2. The reference's worst there is %s with %s wrong answers.\n",
            E(br->fam[tb][FAMILY_SCENE].max_rel), E(br->fam[rd][FAMILY_SCENE].max_rel),
            E(far_t->max_rel), W(wrong_per_million(far_t)), E(far_r->max_rel),
            W(wrong_per_million(far_r)));
    fprintf(f, "- **Some errors belong to the question, not the method.** From an origin "
               "10^-12 R above a big sphere, rounding the origin alone moves t by about 10^-4 "
               "of itself: every double method's worst relative error in that family is near "
               "%s. Dividing by the condition number (u kappa) separates the methods: the "
               "textbook's worst is %s u kappa, the reference's %s, Ray Tracing Gems' %s, the "
               "fast path's %s. About 1 is the best any method can do.\n",
            E(br->fam[rd][FAMILY_NEAR].max_rel), E(br->all[tb].max_over_kappa),
            E(br->all[rd].max_over_kappa), E(br->all[rgd].max_over_kappa),
            E(br->all[fd].max_over_kappa));
    /* 3. float */
    fprintf(f, "- **Float is a different story.** Rounding the inputs to float (7 digits) "
               "moves a sphere 10^7 radii away by more than half its radius: on the far "
               "family the textbook in float is wrong %s times per million, the reference's "
               "float version %s, the float fast path %s. On the ordinary scene float's worst "
               "error in t is %s (textbook) to %s (reference), still well under a pixel.\n",
            W(wrong_per_million(&br->fam[tf][FAMILY_FAR])),
            W(wrong_per_million(&br->fam[rf][FAMILY_FAR])),
            W(wrong_per_million(&br->fam[ff][FAMILY_FAR])), E(br->fam[tf][FAMILY_SCENE].max_rel),
            E(br->fam[rf][FAMILY_SCENE].max_rel));
    /* 4. the fast path */
    fprintf(f, "- **Specialising is what buys speed.** The fast path knows the eye is at the "
               "origin (so C and a per-sphere threshold are computed once, not per ray), "
               "lays the spheres out as arrays and tests %d rays against a sphere at once in "
               "vector registers, and leaves sqrt and division to the packets where some ray "
               "can hit. It runs at %.0f (double), %.0f (float) and %.0f (float filter, double "
               "solve) million tests per second: %.1fx, %.1fx and %.1fx the textbook's double "
               "loop. Its double answers are as accurate as the reference's (worst %s u kappa, "
               "%ld wrong); the mixed version gives exactly the double version's answers.\n",
            FAST_PACKET, br->mtests[fd], br->mtests[ff], br->mtests[fm],
            br->mtests[fd] / br->mtests[tb], br->mtests[ff] / br->mtests[tb],
            br->mtests[fm] / br->mtests[tb], E(br->all[fd].max_over_kappa), br->all[fd].wrong);
    /* 5. renders */
    if (br->nrenders > 0)
        md_finding_renders(f, br, tb, rd, fd);
    /* 6. the ceiling */
    int best = best_share(br);
    fprintf(f, "- **Against the machine's limit** (%.0f million tests per second in double, "
               "%.0f in float): the scalar loops reach %s (textbook) and %s (reference); the "
               "best method, %s, %s. A call per test, one number at a time, cannot come "
               "close; the fast path spends the rest loading rays, turning comparisons into "
               "masks and solving the packets that may hit.\n",
            br->ceiling.ceiling_d, br->ceiling.ceiling_f, P(share(br, tb)), P(share(br, rd)),
            cells(best, " "), P(share(br, best)));
}

/* Where the double fast path's cycles go, per (packet, sphere) pair: the
 * filter at the ceiling's rate, the solves' sqrt and division at their
 * measured rates, and what is left.  The sqrt and division run on their own
 * unit, which can work while the multiplies and adds go on: the parts are
 * sizes, not a sum that must add up. */
static void md_fast_budget(FILE *f, const BenchResults *br, int fd)
{
    const Ceiling *c = &br->ceiling;
    if (!(br->mtests[fd] > 0) || !(c->sqrt_per_cycle > 0) || !(c->div_per_cycle > 0) ||
        br->fast_pairs <= 0)
        return;
    double solved = (double)br->fast_solved / (double)br->fast_pairs;
    double pair = FAST_PACKET * c->mhz / br->mtests[fd];
    double filter = FAST_PACKET * c->cycles_per_vector / c->lanes_d;
    double ray_solve = 1 / c->sqrt_per_cycle + 1 / c->div_per_cycle;
    double solve = solved * FAST_PACKET * ray_solve;
    fprintf(f, "- **Where its time goes**, in cycles per (packet, sphere) pair: %.1f in all. "
               "The filter at the ceiling's rate needs %.1f; the solves' square roots and "
               "divisions take %.1f of their own unit (%s of the pairs, %d rays each, %.1f "
               "cycles a ray at the %.2f sqrts and %.2f divisions per cycle measured, per "
               "number), which may overlap the multiplies and adds; the rest is the solves' "
               "other arithmetic, loading rays, forming masks, the loops and calls.",
            pair, filter, solve, P(solved), FAST_PACKET, ray_solve, c->sqrt_per_cycle,
            c->div_per_cycle);
    if (br->fast_filter_mtests > 0) {
        double alone = FAST_PACKET * c->mhz / br->fast_filter_mtests;
        fprintf(f, " Timed alone, with no solve, the filter takes %.1f (%s of the ceiling's "
                   "rate), so the solves and what surrounds them add %.1f.",
                alone, P(filter / alone), pair - alone);
    }
    fprintf(f, "\n");
}

static void md_ceiling(FILE *f, const BenchResults *br)
{
    const Ceiling *c = &br->ceiling;
    fprintf(f, "- **Clock**: %.0f MHz, measured with a loop of dependent integer xor-then-add "
               "(two one-cycle operations per iteration, so two cycles), timed after every "
               "throughput round; the median of %d readings. ", c->mhz_measured, br->rounds);
    if (c->mhz_cpuinfo > 0)
        fprintf(f, "/proc/cpuinfo says %.0f MHz: the nominal clock, which a core under load " /* portable: */
                   "exceeds; the measured clock is the one the tests ran at.\n", c->mhz_cpuinfo);
    else
        fprintf(f, "(No /proc/cpuinfo on this system.)\n");
    fprintf(f, "- **Pipes**: independent 128-bit vector multiplies start at %.2f per cycle, "
               "adds at %.2f, the two interleaved at %.2f (twelve independent chains each); "
               "rounded to whole pipes: %.0f, %.0f and %.0f.\n",
            c->mul_per_cycle, c->add_per_cycle, c->mix_per_cycle, c->mul_pipes, c->add_pipes,
            c->mix_pipes);
    fprintf(f, "- **Vector width**: the portable build (-O2, no -march) uses 128-bit vectors "
               "(SSE2 on x86-64, NEON on arm64): %d doubles or %d floats.\n",
            c->lanes_d, c->lanes_f);
    fprintf(f, "- **Work per test** in the lab's scenes, at the least: with the eye at the "
               "origin, b = c.r and its comparison with a threshold known per sphere "
               "(b >= sqrt(C) is the hit test from outside): %d multiplies and %d adds or "
               "compares. Hits need a sqrt and a division more, but most tests miss.\n",
            c->ops_mul, c->ops_add);
    fprintf(f, "- **Ceiling** = clock x lanes / cycles per vector of tests, with cycles = "
               "max(%d / %.0f, %d / %.0f, %d / %.0f) = %.2f: **%.0f million tests per second "
               "in double, %.0f in float**.\n",
            c->ops_mul, c->mul_pipes, c->ops_add, c->add_pipes, c->ops_mul + c->ops_add,
            c->mix_pipes, c->cycles_per_vector, c->ceiling_d, c->ceiling_f);
    fprintf(f, "- **Sqrt and division**, which only hits need: %.2f square roots and %.2f "
               "divisions per cycle (24 independent chains each, per number, compiled as the "
               "fast path's solve is).\n",
            c->sqrt_per_cycle, c->div_per_cycle);
    fprintf(f, "- Not counted: loading the rays, the loop, the hits' sqrt and division. With "
               "-march=native (AVX-512 here) the vectors, and so the ceiling, would be four "
               "times wider; the kit does not use it, to stay portable.\n");
    fprintf(f, "\n| method | precision | Mtests/s | share of ceiling |\n|---|---|---:|---:|\n");
    for (int m = 0; m < bench_nmethods; m++)
        fprintf(f, "| %s | %.0f | %s |\n", cells(m, " | "), br->mtests[m], P(share(br, m)));
}

/* The title, and how and where the bench ran. */
static void md_intro(FILE *f, const BenchResults *br)
{
    fprintf(f, "# Ray/sphere intersection: speed against accuracy\n\n");
    if (br->quick)
        fprintf(f, "> **Quick run** (`bench --quick`, as `make test` runs it): small sizes and "
                   "few rounds. The numbers only show that the benchmark works; `make bench` "
                   "gives the real ones.\n\n");
    fprintf(f, "Written by `make bench` on %s in %.0f s. Machine: %s, one thread. Compiler: %s, "
               "`-std=c11 -O2 -ffp-contract=off` (the fast path's file also "
               "`-fno-math-errno`). Load average %.2f before, %.2f after.\n\n",
            br->date, br->seconds_total, br->cpu, br->compiler, br->load_before, br->load_after);
}

/* The headline's first item: the reference's cost over the textbook's
 * against its target, under one placement of the code or two. */
static void md_ratio_headline(FILE *f, const BenchResults *br)
{
    fprintf(f, "- **Reference / textbook cost, double, ordinary scene: %.3fx** (ratio of the "
               "medians; per-round ratios: median %.3f, quartiles %.3f-%.3f). Target at most "
               "%.2fx: ",
            br->ratio_of_medians, br->ratio_paired, br->ratio_q1, br->ratio_q3, RATIO_TARGET);
    if (br->ratio_of_medians <= RATIO_TARGET)
        fprintf(f, "**met**.");
    else if (br->ratio_q1 <= RATIO_TARGET)
        fprintf(f, "**on it within the rounds' spread** (the medians miss it by %.1f%%); "
                   "what costs it is below.",
                100 * (br->ratio_of_medians / RATIO_TARGET - 1));
    else
        fprintf(f, "**missed by %.1f%%**; what costs it is below.",
                100 * (br->ratio_of_medians / RATIO_TARGET - 1));
    if (br->placed) {
        double worst = br->ratio_of_medians > br->placed_ratio ? br->ratio_of_medians
                                                               : br->placed_ratio;
        fprintf(f, " The same objects linked in the reverse order: **%.3fx** (quartiles "
                   "%.3f-%.3f). **Under both placements of the code: %s**",
                br->placed_ratio, br->placed_q1, br->placed_q3,
                worst <= RATIO_TARGET ? "met." : "not met.");
    }
    fputc('\n', f);
}

/* ## Headline: the targets, met or not, and where the reference's and the
 * fast path's time goes. */
static void md_headline(FILE *f, const BenchResults *br)
{
    int tb = TEXTBOOK_D, tf = TEXTBOOK_F, rd = REFERENCE_D;
    int fd = FAST_D, ff = FAST_F, fm = FAST_M;
    fprintf(f, "## Headline\n\n");
    md_ratio_headline(f, br);
    fprintf(f, "- **The reference's miss test** sums |f x r|^2 a term at a time and stops at "
               "the first partial sum above A R^2: of the %ld (ray, sphere) pairs timed, %s "
               "stop after n.x^2, %s after n.x^2 + n.y^2 and %s after the whole sum (misses); "
               "%s go on to the roots (the line meets the sphere: the hits) and %s to the "
               "careful branch. %s\n",
            br->ref_stage_pairs, P(stage_share(br, REF_STAGE_NX)), P(stage_share(br, REF_STAGE_NXY)),
            P(stage_share(br, REF_STAGE_NN)), P(stage_share(br, REF_STAGE_ROOTS)),
            P(stage_share(br, REF_STAGE_CAREFUL)),
            br->ref_stage_wrong == 0 ? "Every early miss is one the reference gives too."
                                     : "**Some early misses disagree with the reference: the "
                                       "stage replica in methods.c is stale.**");
    fprintf(f, "- **Fast path (double): %s of the ceiling** (%.0f of %.0f million tests per "
               "second; its rounds' quartiles %s-%s). Target at least %.0f%%: **%s**. It "
               "solved %s of its (packet, sphere) pairs: a sqrt and a division for each of "
               "their %d rays.\n",
            P(share(br, fd)), br->mtests[fd], br->ceiling.ceiling_d,
            P(br->ceiling.ceiling_d > 0 ? br->mtests_q1[fd] / br->ceiling.ceiling_d : 0),
            P(br->ceiling.ceiling_d > 0 ? br->mtests_q3[fd] / br->ceiling.ceiling_d : 0),
            100 * SHARE_TARGET, share(br, fd) >= SHARE_TARGET ? "met" : "not met",
            P(br->fast_pairs > 0 ? (double)br->fast_solved / (double)br->fast_pairs : 0),
            FAST_PACKET);
    md_fast_budget(f, br, fd);
    struct { int fast, base; } pairs[] = { { fd, tb }, { fm, tb }, { ff, tf } };
    for (int k = 0; k < 3; k++) {
        int p = pairs[k].fast, q = pairs[k].base;
        double sp = br->mtests[p] / br->mtests[q];
        bool err_ok = br->all[p].max_rel <= br->all[q].max_rel &&
                      br->all[p].wrong <= br->all[q].wrong;
        fprintf(f, "- **Fast path (%s) / textbook scalar loop (%s): %.1fx**; worst error %s "
                   "against %s, wrong answers %ld against %ld. Target (at least %.0fx, error no "
                   "larger): **%s**.\n",
                precision_name(bench_methods[p].precision),
                precision_name(bench_methods[q].precision), sp, E(br->all[p].max_rel),
                E(br->all[q].max_rel), br->all[p].wrong, br->all[q].wrong, SPEEDUP_TARGET,
                sp >= SPEEDUP_TARGET && err_ok ? "met" : "not met");
    }
    fprintf(f, "- **Ceiling** for the lab scene on this machine: %.0f million tests per second "
               "in double, %.0f in float (how: below). The textbook reaches %s of it, the "
               "reference %s, the fast path %s (double), %s (mixed) and %s (float).\n\n",
            br->ceiling.ceiling_d, br->ceiling.ceiling_f, P(share(br, tb)), P(share(br, rd)),
            P(share(br, fd)), P(share(br, fm)), P(share(br, ff)));
}

/* ## Throughput and error: how they are measured, the table, the plot. */
static void md_throughput(FILE *f, const BenchResults *br)
{
    fprintf(f, "## Throughput and error\n\n");
    fprintf(f, "Throughput: the closest-hit loop (every sphere, keep the nearest, as part 3b's "
               "`ray_color`) over %d camera rays of default.scene against its %d spheres, one "
               "thread; the median of %d interleaved rounds, and the interquartile range. "
               "Errors: over the "
               "ordinary scene and the three hard families below (%d cases): relative error in "
               "t where both the method and the exact answer hit; wrong hit/miss answers per "
               "million cases, not counting those the oracle marks ambiguous; the worst error in "
               "units of u kappa (u = 2^-53, kappa the condition number of t: about 1 is the "
               "best any method can do). Last column: the grader's Part 3a hard cases "
               "(tests/oracle/hard.h), judged by the grader's own rule; the methods that assume "
               "unit directions (A = 1, geometric, fast) are given r / |r| there and their t "
               "divided by |r|, as a caller would.\n\n",
            br->tp_rays, br->tp_spheres, br->rounds,
            br->family_cases[0] + br->family_cases[1] + br->family_cases[2] + br->family_cases[3]);
    md_results_table(f, br);
    fprintf(f, "\n![Throughput against worst error](plot.svg)\n\n");
}

/* ## Errors by family: a table for each. */
static void md_families(FILE *f, const BenchResults *br)
{
    fprintf(f, "## Errors by family\n\n");
    for (int fam = 0; fam < FAMILY_COUNT; fam++) {
        fprintf(f, "### %s: %s\n\n%d cases, %ld of them ambiguous (not counted).\n\n",
                family_names[fam], family_titles[fam], br->family_cases[fam],
                br->fam[0][fam].ambiguous);
        md_family_table(f, br, fam);
        fprintf(f, "\n");
    }
}

/* ## Render level: the lab's scenes rendered whole. */
static void md_renders(FILE *f, const BenchResults *br)
{
    fprintf(f, "## Render level\n\n");
    fprintf(f, "Every scene in labs/scenes at %dx%d (its own field of view and distance), the "
               "median of %d interleaved renders per method. The exact render is "
               "oracle_closest at every pixel.\n\n",
            br->nrenders > 0 ? br->renders[0].nx : 0, br->nrenders > 0 ? br->renders[0].ny : 0,
            br->render_reps);
    md_render_table(f, br);
}

/* ## How it is measured. */
static void md_method(FILE *f, const BenchResults *br)
{
    fprintf(f, "\n## How it is measured\n\n");
    fprintf(f, "- Every method is timed in the same run: each round times every method once "
               "(about 5 ms each) in an order rotated by one every round, so drift in the clock "
               "or in other load falls on all alike. Medians, not means: a disturbed round moves "
               "a median little. The machine may be shared: see the load average above.\n");
    fprintf(f, "- The scalar methods are called through a function pointer from the same loop, "
               "as `ray_color` calls `sphere_intersect` in another file: nothing is inlined, and "
               "the linked reference is on equal terms. Every answer (sphere and t) is stored "
               "and summed into a checksum that is printed, so no work can be dropped.\n");
    fprintf(f, "- Exact answers: tests/oracle (double-double arithmetic). Hard cases: a fixed "
               "seed (%llu), the same cases every run.\n",
            (unsigned long long)br->seed);
    fprintf(f, "- Float methods get the double inputs rounded to float, as a float renderer "
               "would: that rounding is part of their error.\n");
    fprintf(f, "- Files: results.csv (the table above), results_by_family.csv, renders.csv, "
               "plot.svg; for Part 5, results_triangles.csv and plot_triangles.svg, and at "
               "scale results_scaling.csv and plot_scaling.svg. Source: tests/bench (bench.h "
               "lists the files).\n");
}

static void md_report(FILE *f, const void *data)
{
    const BenchResults *br = data;
    md_intro(f, br);
    md_headline(f, br);
    md_throughput(f, br);
    fprintf(f, "## What it shows\n\n");
    md_findings(f, br);
    fprintf(f, "\n");
    md_ratio(f, br);
    md_families(f, br);
    md_renders(f, br);
    fprintf(f, "\n## The ceiling\n\n");
    md_ceiling(f, br);
    if (br->tri.ran)
        triangles_md(f, &br->tri);
    if (br->scale.ran)
        scaling_md(f, &br->scale);
    md_method(f, br);
}

int report_write(const BenchResults *br, const char *dir, char *err, size_t errlen)
{
    if (out_write(dir, "results.csv", csv_results, br, err, errlen) != 0 ||
        out_write(dir, "results_by_family.csv", csv_families, br, err, errlen) != 0 ||
        out_write(dir, "renders.csv", csv_renders, br, err, errlen) != 0 ||
        write_plot(br, dir, err, errlen) != 0)
        return -1;
    if (br->tri.ran &&
        triangles_write(&br->tri, dir, subtitle(br, "-O2; throughput on cracks.scene (%d rays x "
                                                    "%d triangles); errors on %ld hard cases",
                                                br->tri.tp_rays, br->tri.tp_triangles,
                                                br->tri.hard[0].tests), err, errlen) != 0)
        return -1;
    if (br->scale.ran &&
        scaling_write(&br->scale, dir, subtitle(br, "the reference; closed knots in knot.scene's "
                                                    "view, %dx%d with the hierarchy",
                                                br->scale.nx, br->scale.ny), err, errlen) != 0)
        return -1;
    return out_write(dir, "report.md", md_report, br, err, errlen);
}
