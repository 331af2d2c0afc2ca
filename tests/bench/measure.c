/*
 * measure.c - time, and this machine's limits.
 *
 *   now_seconds     CLOCK_MONOTONIC
 *   median, quantile
 *   measure_ceiling the clock (from /proc/cpuinfo, and measured with a
 *                   dependent integer loop), how many independent floating-
 *                   point multiplies and adds the core starts per cycle, and
 *                   from those the most ray/sphere tests per second the lab
 *                   scene's arithmetic allows
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "bench.h"

double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double quantile(double *v, int n, double q)
{
    if (n <= 0)
        return NAN;
    double pos = q * (n - 1);
    int lo = (int)pos;
    int hi = lo + 1 < n ? lo + 1 : lo;
    return v[lo] + (v[hi] - v[lo]) * (pos - lo);
}

double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return quantile(v, n, 0.5);
}

/* ---- the clock ------------------------------------------------------------ */

bool cpuinfo(const char *key, char *out, size_t len)
{
    FILE *f = fopen("/proc/cpuinfo", "r");     /* portable: false without /proc */
    if (!f)
        return false;
    char line[256];
    const char *colon = NULL;
    while (!colon && fgets(line, sizeof line, f))
        if (strncmp(line, key, strlen(key)) == 0 && (colon = strchr(line, ':')) != NULL) {
            snprintf(out, len, "%s", colon + 1 + strspn(colon + 1, " \t"));
            out[strcspn(out, "\n")] = '\0';
        }
    fclose(f);
    return colon != NULL;
}

static volatile uint64_t opaque_k1 = 0x9e3779b97f4a7c15ull, opaque_k2 = 12345;
static volatile double opaque_one = 1.0, opaque_zero = 0.0;

/* Each iteration is one xor and one add, each needing the previous result:
 * two cycles on any core whose integer xor and add take one cycle (all
 * current x86-64 and arm64 ones).  Both operands are unknown to the
 * compiler and loop-invariant, so it can neither fold nor split them. */
static uint64_t dependent_chain(uint64_t x, long n)
{
    uint64_t k1 = opaque_k1, k2 = opaque_k2;
    for (long i = 0; i < n; i++)
        x = (x ^ k1) + k2;
    return x;
}

/* MHz from one run of the chain. */
static double chain_mhz(long n)
{
    double t0 = now_seconds();
    uint64_t x = dependent_chain((uint64_t)n, n);
    double dt = now_seconds() - t0;
    bench_sink += (double)(x & 1);
    return 2.0 * (double)n / dt / 1e6;
}

/* ---- floating-point issue rates --------------------------------------------- */

/* Twelve independent chains of 128-bit vector multiplies by 1 (or adds of
 * 0): enough to hide the latency of any current core, so the time measures
 * how many vector instructions of each kind it starts per microsecond
 * (measure_ceiling turns that into cycles with the clock).  With gcc
 * and clang the chains are written as 128-bit vectors (their vector
 * extension), else as scalars, which use the same pipes. */
#if defined(__GNUC__) || defined(__clang__)
typedef double Pair __attribute__((vector_size(16)));
#define PAIR(a, b) { a, b }
#else
typedef double Pair;
#define PAIR(a, b) a
#endif

static double ops_per_us(int kind, long n)
{
    Pair m = PAIR(opaque_one, opaque_one), z = PAIR(opaque_zero, opaque_zero);
    Pair a0 = PAIR(1, 2), a1 = PAIR(3, 4), a2 = PAIR(5, 6), a3 = PAIR(7, 8), a4 = PAIR(9, 10),
         a5 = PAIR(11, 12), a6 = PAIR(13, 14), a7 = PAIR(15, 16), a8 = PAIR(17, 18),
         a9 = PAIR(19, 20), a10 = PAIR(21, 22), a11 = PAIR(23, 24);
    double t0 = now_seconds();
    {
        if (kind == 0) {
            for (long i = 0; i < n; i++) {
                a0 = a0 * m; a1 = a1 * m; a2 = a2 * m; a3 = a3 * m; a4 = a4 * m; a5 = a5 * m;
                a6 = a6 * m; a7 = a7 * m; a8 = a8 * m; a9 = a9 * m; a10 = a10 * m; a11 = a11 * m;
            }
        } else if (kind == 1) {
            for (long i = 0; i < n; i++) {
                a0 = a0 + z; a1 = a1 + z; a2 = a2 + z; a3 = a3 + z; a4 = a4 + z; a5 = a5 + z;
                a6 = a6 + z; a7 = a7 + z; a8 = a8 + z; a9 = a9 + z; a10 = a10 + z; a11 = a11 + z;
            }
        } else {
            for (long i = 0; i < n; i++) {
                a0 = a0 * m; a1 = a1 + z; a2 = a2 * m; a3 = a3 + z; a4 = a4 * m; a5 = a5 + z;
                a6 = a6 * m; a7 = a7 + z; a8 = a8 * m; a9 = a9 + z; a10 = a10 * m; a11 = a11 + z;
            }
        }
    }
    double dt = now_seconds() - t0;
    Pair sum = a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7 + a8 + a9 + a10 + a11;
    double out[sizeof(Pair) / sizeof(double)];
    memcpy(out, &sum, sizeof sum);
    bench_sink += out[0];
    return 12.0 * (double)n / (dt * 1e6);
}

/* What a hit costs on top: sqrt and division, per number (lane) and per
 * microsecond, as ops_per_us.  Each of 24 numbers is its own chain,
 * x = sqrt(x) or x = x / 1, written as the fast
 * path's solve writes them (a loop over an array), so that the compiler
 * makes of them what it makes of the solve: vectors of two doubles with the
 * flags the bench builds both with (-fno-math-errno, as fastpath.o).  The
 * store and reload between rounds (MEMORY_BARRIER) add latency, not
 * throughput: 24 chains are more than enough to hide it. */
#if defined(__GNUC__) || defined(__clang__)
#define MEMORY_BARRIER() __asm__ volatile("" ::: "memory")
#else
#define MEMORY_BARRIER() ((void)0)
#endif

static double lanes_per_us(int kind, long n)
{
    double a[24];
    for (int k = 0; k < 24; k++)
        a[k] = 2 + k;
    double m = opaque_one;
    double t0 = now_seconds();
    if (kind == 0) {
        for (long i = 0; i < n; i++) {
            for (int k = 0; k < 24; k++)
                a[k] = sqrt(a[k]);
            MEMORY_BARRIER();
        }
    } else {
        for (long i = 0; i < n; i++) {
            for (int k = 0; k < 24; k++)
                a[k] = a[k] / m;
            MEMORY_BARRIER();
        }
    }
    double dt = now_seconds() - t0;
    double sum = 0;
    for (int k = 0; k < 24; k++)
        sum += a[k];
    bench_sink += sum;
    return 24.0 * (double)n / (dt * 1e6);
}

/* The least work a test needs in the lab's scenes: with the eye at the
 * origin, b = c.r (3 multiplies, 2 adds) and its comparison with a threshold
 * known per sphere (b >= sqrt(C) from outside: 1 compare).  A hit also needs
 * a sqrt and a division, but most rays miss most spheres, and the few hits
 * are left out.  Vectors of 128 bits (SSE2 on x86-64, NEON on arm64: what
 * the portable -O2 build targets) hold 2 doubles or 4 floats. */
void measure_ceiling(Ceiling *c, bool quick, double mhz_during)
{
    enum { REPS = 9 };
    long n = quick ? 5000000L : 40000000L, nf = n / 8;
    double mhz[REPS], mul[REPS], add[REPS], mix[REPS], sq[REPS], dv[REPS];
    int reps = quick ? 3 : REPS;
    /* Each repetition measures the clock and the rates per microsecond;
     * the medians shrug off the repetitions another process disturbed, and
     * the rates are turned into cycles with one clock, the median one.  (A
     * rate in cycles of its own repetition's clock came out several times
     * too high whenever another process stopped the clock's loop, as under
     * make test's parallel lanes: 4.28 divisions a cycle once.) */
    for (int r = 0; r < reps; r++) {
        mhz[r] = chain_mhz(n);
        mul[r] = ops_per_us(0, nf);
        add[r] = ops_per_us(1, nf);
        mix[r] = ops_per_us(2, nf);
        sq[r] = lanes_per_us(0, nf / 8);
        dv[r] = lanes_per_us(1, nf / 8);
    }
    /* "cpu MHz", the first one (Linux); 0 if none.  In a virtual machine it
     * is often the nominal clock, not the one running. */
    char mhz_text[64];
    c->mhz_cpuinfo = cpuinfo("cpu MHz", mhz_text, sizeof mhz_text) ? atof(mhz_text) : 0;
    c->mhz_measured = mhz_during > 0 ? mhz_during : median(mhz, reps);
    c->mhz = c->mhz_measured;
    c->mul_per_cycle = median(mul, reps) / c->mhz;
    c->add_per_cycle = median(add, reps) / c->mhz;
    c->mix_per_cycle = median(mix, reps) / c->mhz;
    c->sqrt_per_cycle = median(sq, reps) / c->mhz;
    c->div_per_cycle = median(dv, reps) / c->mhz;
    /* Pipes come in whole numbers: use the nearest (at least 1). */
    c->mul_pipes = fmax(1, floor(c->mul_per_cycle + 0.5));
    c->add_pipes = fmax(1, floor(c->add_per_cycle + 0.5));
    c->mix_pipes = fmax(1, floor(c->mix_per_cycle + 0.5));
    c->lanes_d = 2;
    c->lanes_f = 4;
    c->ops_mul = 3;
    c->ops_add = 3;
    /* Cycles per vector of tests: each kind on its own pipes, and both kinds
     * together no faster than the mixed rate. */
    double cyc = fmax(fmax(c->ops_mul / c->mul_pipes, c->ops_add / c->add_pipes),
                      (c->ops_mul + c->ops_add) / c->mix_pipes);
    c->cycles_per_vector = cyc;
    c->ceiling_d = c->mhz * c->lanes_d / cyc;
    c->ceiling_f = c->mhz * c->lanes_f / cyc;
}

/* ---- interleaved rounds ------------------------------------------------------ */

bool rounds_next(Rounds *it)
{
    if (it->k >= it->n * it->rounds)
        return false;
    it->r = it->k / it->n;
    it->j = it->k % it->n;
    it->m = (it->r + it->j) % it->n;
    it->k++;
    return true;
}

/* ---- throughput ------------------------------------------------------------ */

/* How many passes of one seconds make a sample of about sample_s (at least 1). */
static int passes_for(double sample_s, double one)
{
    int p = (int)(sample_s / (one > 1e-9 ? one : 1e-9));
    return p < 1 ? 1 : p;
}

/* Runs method m's closest-hit loop passes times over rs; seconds per pass. */
static double time_passes(const Method *m, const BenchScene *sc, const RaySet *rs,
                          int passes, int *idx, double *t)
{
    double t0 = now_seconds();
    for (int p = 0; p < passes; p++)
        method_closest(m, sc, rs, idx, t);
    double dt = now_seconds() - t0;
    /* consume the answers, so no compiler may skip computing them */
    double sum = 0;
    for (int i = 0; i < rs->n; i++)
        sum += idx[i] + (t[i] < INFINITY ? t[i] : 0);
    bench_sink += sum;
    return dt / passes;
}

int measure_throughput(const BenchScene *sc, const RaySet *rs, int rounds, double sample_s,
                       double *pass_seconds, double *round_mhz)
{
    int nm = bench_nmethods, passes[BENCH_MAX_METHODS];
    int *idx = malloc((size_t)rs->n * sizeof *idx);
    double *t = malloc((size_t)rs->n * sizeof *t);
    if (!idx || !t) {
        free(idx);
        free(t);
        return -1;
    }
    /* Calibrate: enough passes for each sample to last about sample_s. */
    for (int m = 0; m < nm; m++) {
        time_passes(&bench_methods[m], sc, rs, 1, idx, t);        /* to warm up */
        passes[m] = passes_for(sample_s, time_passes(&bench_methods[m], sc, rs, 1, idx, t));
    }
    /* Interleave: every round times every method once, starting each round
     * one method further on, so that a slow spell or a warm cache favours
     * no method.  A short clock reading per round gives the clock the
     * ceiling uses, taken under the same conditions. */
    for (Rounds it = { .n = nm, .rounds = rounds }; rounds_next(&it);) {
        int m = it.m;
        if (it.j == 0)
            progress("throughput", it.r, rounds);
        pass_seconds[m * rounds + it.r] = time_passes(&bench_methods[m], sc, rs, passes[m], idx, t);
        if (it.j == nm - 1)
            round_mhz[it.r] = chain_mhz(200000);
    }
    progress("throughput", rounds, rounds);
    free(idx);
    free(t);
    return 0;
}

/* ---- cost by outcome ------------------------------------------------------- */

/* The cases rounded to float, as the float methods take them. */
typedef struct {
    Spheref sphere;
    Rayf ray;
} CaseF;

static CaseF *cases_float(const Case *c, int n)
{
    CaseF *cf = malloc((size_t)(n > 0 ? n : 1) * sizeof *cf);
    for (int i = 0; cf && i < n; i++) {
        cf[i].sphere = spheref_from(&c[i].sphere);
        cf[i].ray = rayf_from(&c[i].ray);
    }
    return cf;
}

/* Seconds per call of m's scalar function over the n cases (cf: the same
 * in float), passes times. */
static double time_pairs(const Method *m, const Case *c, const CaseF *cf, int n, int passes)
{
    double sum = 0;
    double t0 = now_seconds();
    for (int k = 0; k < passes; k++) {
        if (m->scalar_d) {
            for (int i = 0; i < n; i++) {
                double t = 0;
                if (m->scalar_d(&c[i].sphere, &c[i].ray, &t))
                    sum += t;
            }
        } else {
            for (int i = 0; i < n; i++) {
                float t = 0;
                if (m->scalar_f(&cf[i].sphere, &cf[i].ray, &t))
                    sum += t;
            }
        }
    }
    double dt = now_seconds() - t0;
    bench_sink += sum;
    return dt / passes / (n > 0 ? n : 1);
}

int measure_outcomes(const Case *miss, int nmiss, const Case *hit, int nhit, int rounds,
                     double sample_s, double *miss_ns, double *hit_ns)
{
    int nm = bench_nmethods;
    const Case *c[2] = { miss, hit };
    int n[2] = { nmiss, nhit }, passes[2];
    CaseF *cf[2] = { cases_float(miss, nmiss), cases_float(hit, nhit) };
    double *samples = malloc((size_t)(2 * nm * rounds) * sizeof *samples);
    int status = -1;
    if (!samples || !cf[0] || !cf[1])
        goto done;
    /* calibrate on the textbook, the same passes for every method */
    for (int o = 0; o < 2; o++) {
        double one = time_pairs(&bench_methods[TEXTBOOK_D], c[o], cf[o], n[o], 1);
        passes[o] = passes_for(sample_s, one * (n[o] > 0 ? n[o] : 1));
    }
    for (Rounds it = { .n = nm, .rounds = rounds }; rounds_next(&it);) {
        const Method *m = &bench_methods[it.m];
        if (it.j == 0)
            progress("cost by outcome", it.r, rounds);
        for (int o = 0; o < 2; o++)         /* NAN: not a scalar method */
            samples[(o * nm + it.m) * rounds + it.r] =
                m->scalar_d || m->scalar_f ? time_pairs(m, c[o], cf[o], n[o], passes[o]) : NAN;
    }
    for (int m = 0; m < nm; m++) {
        miss_ns[m] = 1e9 * median(samples + m * rounds, rounds);
        hit_ns[m] = 1e9 * median(samples + (nm + m) * rounds, rounds);
    }
    status = 0;
done:
    free(samples);
    free(cf[0]);
    free(cf[1]);
    return status;
}
