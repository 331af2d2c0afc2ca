/*
 * grade.c - grading one submission: for each part, build its program, run
 * each test in a fresh sandboxed child, judge the answers here, and add up
 * the points.  A part that does not build, crashes or hangs loses only its
 * own points.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "grade.h"
#include "sandbox.h"
#include "diagnose.h"
#include "hexfloat.h"
#include "kit/zlib.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OUTPUT_SHOWN 1500     /* bytes of the student's own printing shown */
#define TEST_MEMORY_MB 64     /* a test program needs 3 to 4 MiB of address space */
#define MAX_BATCH 4096        /* tests of one part run together, at most     */

/* The first n bytes of s (up to a NUL) with pad before each line, so that
 * what a student's code printed sits under its heading, not beside it. */
static char *indented(const char *s, size_t n, const char *pad)
{
    size_t lines = 1, np = strlen(pad);
    for (size_t k = 0; k < n && s[k]; k++)
        lines += s[k] == '\n';
    char *out = malloc(n + lines * np + 1), *o = out;
    if (!out)
        return NULL;
    bool line_start = true;
    for (size_t k = 0; k < n && s[k]; k++) {
        if (line_start) {
            memcpy(o, pad, np);
            o += np;
        }
        *o++ = s[k];
        line_start = s[k] == '\n';
    }
    *o = '\0';
    return out;
}

/* What the child reads on stdin for a test; alone: a run of this test
 * alone, whose child writes each answer as soon as it has it (harness.c). */
static char *test_input(const Test *t, bool alone, size_t *len)
{
    size_t cap = 256 + (size_t)t->ncases * 26 * CASE_MAX_IN + (size_t)t->nspheres * 26 * 7
                 + (size_t)t->ntriangles * 26 * 9;
    char *s = malloc(cap);
    if (!s)
        return NULL;
    size_t n = (size_t)snprintf(s, cap, "%s%s %d\n", alone ? "alone\n" : "", kind_name(t->kind), t->ncases);
    if (t->kind == KIND_COLOR || t->kind == KIND_IMAGE) {
        n += (size_t)snprintf(s + n, cap - n, "background %a %a %a\nspheres %d\n",
                              t->background[0], t->background[1], t->background[2], t->nspheres);
        for (int k = 0; k < t->nspheres; k++) {
            const TestSphere *sp = &t->spheres[k];
            n += (size_t)snprintf(s + n, cap - n, "%a %a %a %a %a %a %a\n", sp->c[0], sp->c[1],
                                  sp->c[2], sp->R, sp->color[0], sp->color[1], sp->color[2]);
        }
    }
    if (t->kind == KIND_MESH) {
        n += (size_t)snprintf(s + n, cap - n, "triangles %d\n", t->ntriangles);
        for (int k = 0; k < t->ntriangles; k++) {
            const double *v = t->triangles[k].v;
            n += (size_t)snprintf(s + n, cap - n, "%a %a %a %a %a %a %a %a %a\n",
                                  v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
        }
    }
    /* The cases, the bulk of it, without snprintf (hexfloat.h). */
    int nin = kind_nin(t->kind);
    for (int c = 0; c < t->ncases; c++) {
        for (int k = 0; k < nin; k++) {
            if (k)
                s[n++] = ' ';
            n += hexfloat_format(s + n, t->cases[c].in[k]);
        }
        s[n++] = '\n';
    }
    s[n] = '\0';
    *len = n;
    return s;
}

static const char *signal_story(int sig)
{
    switch (sig) {
    case SIGSEGV: return " (SIGSEGV: a bad pointer, or an array index out of range)";
    case SIGBUS:  return " (SIGBUS: a bad pointer)";
    case SIGFPE:  return " (SIGFPE: an integer division by zero)";
    case SIGABRT: return " (SIGABRT: abort() or a failed assert)";
    case SIGXCPU: return " (SIGXCPU: too much CPU time)";
    case SIGXFSZ: return " (SIGXFSZ: it tried to write a file; tests may not)";
    case SIGKILL: return " (SIGKILL: killed from outside, most likely because the system ran out of memory)";
    default:      return "";
    }
}

/* The limits of a child that runs ntests tests of the part's program (b)
 * on input: one test's time and memory, ntests tests' output (the "output"
 * of tests/weights.conf each), no file, no process.  argv (3 slots) is
 * filled with the program and its object. */
static SandboxSpec test_spec(const GradeOptions *opt, const Build *b, char **argv, const char *input,
                             size_t len, int ntests)
{
    argv[0] = (char *)b->runner;
    argv[1] = b->object[0] ? (char *)b->object : NULL;
    argv[2] = NULL;
    return (SandboxSpec){
        .argv = argv, .workdir = b->rundir, .visible = b->visible, .input = input,
        .input_len = len, .timeout = opt->cfg->timeout, .init = true,
        .output_stop = (size_t)ntests * ((size_t)opt->cfg->output_kib << 10),
        .memory_mb = TEST_MEMORY_MB, .max_procs = 0, .max_file_mb = 0,
    };
}

/* Runs test t in a fresh sandboxed child of the part's program; 0 when it
 * ran (res then holds what it did), -1 with a reason in err. */
static int run_child(const GradeOptions *opt, const Build *b, const Test *t, SandboxResult *res,
                     char *err, size_t errlen)
{
    size_t len = 0;
    char *input = test_input(t, true, &len);
    if (!input) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    char *argv[3];
    SandboxSpec spec = test_spec(opt, b, argv, input, len, 1);
    spec.answer_max = 512 + (size_t)t->ncases * 160;
    spec.output_max = 64 * 1024;
    int status = sandbox_run(&spec, res, err, errlen);
    free(input);
    return status;
}

/* Runs one test in the sandbox and judges it, beside the other tests of
 * its part (check_answers_in_part). */
static void run_test(const GradeOptions *opt, const Build *b, const Test *t, const PartSoFar *part,
                     TestResult *r)
{
    SandboxResult res;
    char err[256];
    if (run_child(opt, b, t, &res, err, sizeof err) != 0) {
        appendf(&r->output, "the grader could not run this test: %s", err);
        return;
    }
    r->seconds = res.seconds;

    char *verdict = NULL;
    bool ok = check_answers_in_part(t, res.answer, res.answer_len, part, &verdict,
                                    &r->answers);
    r->ran = true;
    const char *why = "";
    char whybuf[200] = "";
    if (res.timed_out) {
        snprintf(whybuf, sizeof whybuf, "  it did not finish within %g s: an endless loop?\n", opt->cfg->timeout);
    } else if (res.memory_exceeded) {
        snprintf(whybuf, sizeof whybuf, "  it used more than %d MiB of memory, and was stopped\n", TEST_MEMORY_MB);
    } else if (res.output_exceeded) {
        snprintf(whybuf, sizeof whybuf, "  it printed more than %ld KiB, and was stopped: print less "
                 "(or nothing) from this function\n", opt->cfg->output_kib);
    } else if (res.signal) {
        snprintf(whybuf, sizeof whybuf, "  it crashed: signal %d%s\n", res.signal, signal_story(res.signal));
    } else if (res.exit_code != 0) {
        snprintf(whybuf, sizeof whybuf, "  it exited with status %d before the test finished "
                 "(does your code call exit?)\n", res.exit_code);
    }
    why = whybuf;
    ok = ok && res.exit_code == 0 && !res.timed_out && !res.memory_exceeded && !res.output_exceeded;
    r->passed = ok;
    r->score = ok ? r->max_score : 0;

    size_t ns = res.output_len < OUTPUT_SHOWN ? res.output_len : OUTPUT_SHOWN;
    char *shown = ns && !ok ? indented(res.output, ns, "    ") : NULL;
    appendf(&r->output, "%s%s%s%s", ok ? "" : t->note[0] ? "  about: " : "", ok ? "" : t->note,
            ok || !t->note[0] ? "" : "\n", ok ? "" : why);
    r->verdict_at = r->output ? strlen(r->output) : 0;
    r->verdict_len = ok || !r->output ? 0 : strlen(verdict);
    appendf(&r->output, "%s%s%s", ok ? "" : verdict, ns && !ok ? "  your code printed:\n" : "",
            shown ? shown : "");
    free(shown);
    if (ns && !ok && (res.output_truncated || res.output_len > OUTPUT_SHOWN))
        appendf(&r->output, "\n  [... more output cut]\n");
    free(verdict);
    sandbox_result_free(&res);
}

/* The input of Part part's tests run together: each test's input, one
 * after the other, *len bytes; *ntests tests, whose answers take at most
 * *answer_max bytes.  NULL out of memory (or with no test). */
static char *batch_input(const TestList *tests, int part, size_t *len, size_t *answer_max, int *ntests)
{
    KitBuf input = { 0 };
    for (int k = 0; k < tests->n; k++) {
        const Test *t = &tests->tests[k];
        if (t->part != part)
            continue;
        size_t n = 0;
        char *one = test_input(t, false, &n);
        if (!one || kit_buf_append(&input, one, n) != 0) {
            free(one);
            kit_buf_free(&input);
            return NULL;
        }
        free(one);
        *answer_max += 512 + (size_t)t->ncases * 160;
        (*ntests)++;
    }
    *len = input.len;
    return (char *)input.data;
}

/* Of Part part's tests run together, whose answers are from[j] (size[j]
 * bytes) for its j-th test, those that passed: their results (each taking
 * seconds), marked done.  How many. */
static int take_passes(const TestList *tests, int part, const char *const *from, const size_t *size,
                       double seconds, TestResult *results, bool *done)
{
    int j = 0, passed = 0;
    for (int k = 0; k < tests->n; k++) {
        const Test *t = &tests->tests[k];
        if (t->part != part)
            continue;
        char *verdict = NULL;
        Answers a;
        memset(&a, 0, sizeof a);
        bool ok = check_answers(t, from[j], size[j], &verdict, &a);
        free(verdict);
        j++;
        if (!ok) {
            answers_free(&a);
            continue;
        }
        TestResult *r = &results[k];
        r->answers = a;
        r->ran = r->passed = true;
        r->score = r->max_score;
        r->seconds = seconds;
        appendf(&r->output, "%s", "");
        done[k] = true;
        passed++;
    }
    return passed;
}

/* The shortcut: every test of the part in one child.  A test passes here
 * only if the child ran all of them to their end ("end N" after each) and
 * exited cleanly, within one test's time and memory; then each test's
 * answers are judged as its own run's would be.  Nothing else is taken from
 * the batch: a test it fails, and every test when the child crashed,
 * exited early, hung or printed a malformed answer, runs alone afterwards
 * (run_test), so that its verdict and what the student reads come from a
 * process of its own.  Marks in done[] the tests passed here. */
static void run_batch(const GradeOptions *opt, Build *b, const TestList *tests, int part,
                      TestResult *results, bool *done, double *spent)
{
    size_t len = 0, answer_max = 0;
    int ntests = 0;
    char *input = batch_input(tests, part, &len, &answer_max, &ntests);
    if (!input || ntests < 2) {
        free(input);
        return;
    }
    char *argv[3];
    SandboxSpec spec = test_spec(opt, b, argv, input, len, ntests);
    spec.answer_max = answer_max;
    spec.output_max = 4096;
    SandboxResult res;
    char err[256];
    int status = sandbox_run(&spec, &res, err, sizeof err);
    free(input);
    if (status != 0)
        return;
    *spent += res.seconds;
    if (b->unchecked && build_link_verdict(b, &res)) {      /* it does not link */
        sandbox_result_free(&res);
        return;
    }
    if (res.exit_code != 0 || res.signal || res.timed_out || res.memory_exceeded ||
        res.output_exceeded || res.answer_truncated) {
        if (opt->verbose)
            fprintf(stderr, "  Part %s: the %d tests together: %s; each runs alone\n", part_label(part),
                    ntests, res.timed_out ? "out of time" : res.memory_exceeded ? "out of memory"
                    : res.output_exceeded ? "it printed too much"
                    : res.signal ? "it crashed" : res.answer_truncated ? "too much output"
                    : "it exited early");
        sandbox_result_free(&res);
        return;
    }
    /* Split the answers after each "end N" line; all or nothing. */
    const char *from[MAX_BATCH];
    size_t size[MAX_BATCH];
    if (ntests > MAX_BATCH || batch_split(res.answer, res.answer_len, ntests, from, size) != ntests) {
        if (opt->verbose)
            fprintf(stderr, "  Part %s: the %d tests together: answers malformed; each runs alone\n",
                    part_label(part), ntests);
        sandbox_result_free(&res);
        return;
    }
    int passed = take_passes(tests, part, from, size, res.seconds / ntests, results, done);
    if (opt->verbose)
        fprintf(stderr, "  Part %s: the %d tests together: %d passed; %d run alone\n", part_label(part),
                ntests, passed, ntests - passed);
    sandbox_result_free(&res);
}

/* The diagnosis's probes run as tests do, each in its own child.  Once a
 * probe runs out of time or memory the rest are not run, nor any after two
 * of the part's tests ran out of time (the diagnosis then confirms nothing
 * they would have shown): code that loops or hogs memory would make each
 * of them wait out the whole limit. */
typedef struct {
    const GradeOptions *opt;
    const Build *b;
    bool stopped;
    double *spent;             /* the seconds the part's runs took so far     */
} ProbeContext;

static int run_probe(void *ctx, const Test *t, Answers *a)
{
    ProbeContext *pc = ctx;
    SandboxResult res;
    char err[256], *verdict = NULL;
    if (pc->stopped || *pc->spent + pc->opt->cfg->timeout > pc->opt->cfg->part_time ||
        run_child(pc->opt, pc->b, t, &res, err, sizeof err) != 0)
        return -1;
    *pc->spent += res.seconds;
    pc->stopped = res.timed_out || res.memory_exceeded || res.output_exceeded;
    check_answers(t, res.answer, res.answer_len, &verdict, a);
    free(verdict);
    sandbox_result_free(&res);
    return 0;
}

/* Each test's points: its group's points shared by its tests' weights. */
static void share_points(const GradeConfig *cfg, const TestList *tests, Grade *g)
{
    double wsum[NPARTS][2] = { { 0 } };
    for (int k = 0; k < tests->n; k++)
        wsum[tests->tests[k].part][tests->tests[k].hard] += tests->tests[k].weight;
    for (int k = 0; k < tests->n; k++) {
        const Test *t = &tests->tests[k];
        double pts = t->hard ? cfg->hard[t->part] : cfg->core[t->part];
        g->results[k].max_score = pts * t->weight / wsum[t->part][t->hard];
    }
}

/* The tests of Part p the batch did not pass (done), each alone, or why
 * not; passed and named are room for what the part did so far.  Returns
 * how many did not finish in time. */
static int run_rest_alone(const GradeOptions *opt, const Build *b, Grade *g, int p, const bool *done,
                          const Test **passed, const char **named, double *spent)
{
    const TestList *tests = g->tests;
    const GradeConfig *cfg = opt->cfg;
    int timeouts = 0;
    bool first = true;
    for (int k = 0; k < tests->n; k++) {
        const Test *t = &tests->tests[k];
        TestResult *r = &g->results[k];
        if (t->part != p || done[k])
            continue;
        if (!b->ok) {
            char why[200];
            grade_unbuilt_why(g, p, false, why, sizeof why);
            appendf(&r->output, first ? "  %s, so this part scores 0:\n%s"
                                      : "  %s (see the first test of this part)%s",
                    why, first ? g->build_messages[p] : "");
        } else if (timeouts >= 2) {
            appendf(&r->output, "  not run: two earlier tests of this part did not finish in time");
        } else if (*spent + cfg->timeout > cfg->part_time) {
            appendf(&r->output, "  not run: this part's tests took %g s in all, the most a part may "
                    "take (its tests each took long: does the code sleep or loop?)", cfg->part_time);
        } else {
            if (opt->verbose)
                fprintf(stderr, "  %s\n", t->name);
            PartSoFar part = { passed, 0, named, 0 };
            for (int j = 0; j < tests->n; j++) {
                const TestResult *rj = &g->results[j];
                if (tests->tests[j].part != p)
                    continue;
                if (rj->passed)
                    passed[part.npassed++] = &tests->tests[j];
                else if (rj->ran && rj->answers.named)
                    named[part.nnamed++] = rj->answers.named;
            }
            run_test(opt, b, t, &part, r);
            *spent += r->seconds;
            if (!r->passed && r->seconds >= cfg->timeout)
                timeouts++;
        }
        first = false;
    }
    return timeouts;
}

/* The probes on Part p's code, and the diagnosis they confirm. */
static void diagnose_built_part(const GradeOptions *opt, const Build *b, Grade *g, int p, bool stopped,
                                double *spent)
{
    const TestList *tests = g->tests;
    /* After two tests out of time, a probe would be the third. */
    ProbeContext pc = { opt, b, stopped, spent };
    Probes probes = { run_probe, &pc, p == PART3B && !opt->build->reference, false, opt->cfg->full_hints };
    for (int k = 0; k < tests->n; k++)
        probes.part3a_failed = probes.part3a_failed ||
            (tests->tests[k].part == PART3A && !tests->tests[k].hard && g->results[k].ran &&
             !g->results[k].passed);
    diagnose_part(p, tests, g->results, &probes, &g->diagnosis[p], &g->diagnosis_hard[p],
                  &g->causes[p]);
}

/* Builds Part p, runs its tests and diagnoses it. */
static int grade_part(const GradeOptions *opt, Grade *g, int p, char *err, size_t errlen)
{
    const TestList *tests = g->tests;
    g->graded[p] = true;
    if (opt->verbose)
        fprintf(stderr, "  building Part %s ...\n", part_label(p));
    Build b;
    if (build_part(opt->build, p, opt->submission, &b, err, errlen) != 0) {
        build_remove(&b);
        return -1;
    }
    /* A part's runs (its tests together, each alone, the probes) start
     * only while they can end within its time (weights.conf's
     * part-time), counted as the seconds its runs took: code whose
     * every test sleeps just under the limit costs at most that. */
    double children = sandbox_cpu(false), spent = 0;
    bool *done = calloc((size_t)tests->n + 1, sizeof *done);
    const Test **passed = calloc((size_t)tests->n + 1, sizeof *passed);
    const char **named = calloc((size_t)tests->n + 1, sizeof *named);
    if (!done || !passed || !named) {
        free(done);
        free(passed);
        free(named);
        build_remove(&b);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    /* A loaded part's first run, the batch, also tells whether its
     * object links; when it cannot (no batch, or it crashed), a run that
     * only loads it does, as the build's. */
    if (b.ok)
        run_batch(opt, &b, tests, p, g->results, done, &spent);
    if (b.ok && b.unchecked) {
        double before = sandbox_cpu(false);
        int rc = build_check(&b, err, errlen);
        children += sandbox_cpu(false) - before;
        if (rc != 0) {
            free(done);
            free(passed);
            free(named);
            build_remove(&b);
            return -1;
        }
    }
    if (!b.ok && !b.refused) {
        build_explain_undefined(&b, opt->submission, p);
        build_explain_headers(opt->build, &b, p);
    }
    g->build_messages[p] = b.messages;
    g->build_refused[p] = b.refused;
    g->built[p] = b.ok;
    b.messages = NULL;
    g->cpu_compile += b.cpu_compile;
    g->cpu_link += b.cpu_link;
    /* The tests the batch did not pass, each alone, then the probes. */
    int timeouts = run_rest_alone(opt, &b, g, p, done, passed, named, &spent);
    check_part_again(tests, g->results, p);
    free(done);
    free(passed);
    free(named);
    g->cpu_tests += sandbox_cpu(false) - children;
    children = sandbox_cpu(false);
    if (b.ok)
        diagnose_built_part(opt, &b, g, p, timeouts >= 2, &spent);
    g->cpu_probes += sandbox_cpu(false) - children;
    if (opt->keep_objects && b.ok)
        build_keep_objects(&b, opt->keep_objects);
    build_remove(&b);
    return 0;
}

/* The parts' scores and the total from the tests'. */
static void add_up(const GradeConfig *cfg, const TestList *tests, Grade *g)
{
    for (int k = 0; k < tests->n; k++) {
        const Test *t = &tests->tests[k];
        const TestResult *r = &g->results[k];
        if (!g->graded[t->part])
            continue;
        if (t->hard) {
            g->hard[t->part] += r->score;
            g->hard_max[t->part] += r->max_score;
        } else {
            g->core[t->part] += r->score;
            g->core_max[t->part] += r->max_score;
        }
    }
    /* A part's points are the ones weights.conf gives it: its tests' shares
     * (30 / 13 each, say) add up to them only within rounding, so the
     * maxima, and a part that passed every test, are set to them. */
    for (int p = 0; p < NPARTS; p++) {
        bool all_core = true, all_hard = true;
        for (int k = 0; k < tests->n; k++)
            if (tests->tests[k].part == p && g->graded[p] && !g->results[k].passed) {
                all_core = all_core && tests->tests[k].hard;
                all_hard = all_hard && !tests->tests[k].hard;
            }
        if (g->core_max[p] > 0) {
            g->core_max[p] = cfg->core[p];
            if (all_core)
                g->core[p] = cfg->core[p];
        }
        if (g->hard_max[p] > 0) {
            g->hard_max[p] = cfg->hard[p];
            if (all_hard)
                g->hard[p] = cfg->hard[p];
        }
    }
    for (int p = 0; p < NPARTS; p++) {
        g->total += g->core[p];
        g->total_max += g->core_max[p];
        if (cfg->hard_is_bonus) {
            g->bonus += g->hard[p];
            g->bonus_max += g->hard_max[p];
        } else {
            g->total += g->hard[p];
            g->total_max += g->hard_max[p];
        }
    }
}

int grade_submission(const GradeOptions *opt, const TestList *tests, Grade *g,
                     char *err, size_t errlen)
{
    memset(g, 0, sizeof *g);
    g->tests = tests;
    g->results = calloc((size_t)tests->n + 1, sizeof *g->results);
    if (!g->results) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double start = sandbox_now();
    share_points(opt->cfg, tests, g);
    for (int p = 0; p < NPARTS; p++)
        if (opt->parts[p] && grade_part(opt, g, p, err, errlen) != 0)
            return -1;
    add_up(opt->cfg, tests, g);
    g->seconds = sandbox_now() - start;
    return 0;
}

void grade_free(Grade *g)
{
    if (g->results)
        for (int k = 0; k < g->tests->n; k++) {
            free(g->results[k].output);
            answers_free(&g->results[k].answers);
        }
    free(g->results);
    for (int p = 0; p < NPARTS; p++) {
        free(g->build_messages[p]);
        free(g->diagnosis[p]);
        free(g->diagnosis_hard[p]);
        free(g->causes[p]);
    }
    memset(g, 0, sizeof *g);
}

bool grade_warned(const Grade *g, int p)
{
    return g->graded[p] && g->built[p] && g->build_messages[p] && g->build_messages[p][0];
}

void grade_unbuilt_why(const Grade *g, int p, bool capital, char *out, size_t n)
{
    if (g->build_refused[p])
        snprintf(out, n, "%s grader did not compile your %s.c", capital ? "The" : "the", stage_names[p]);
    else
        snprintf(out, n, "%s %s.c did not build", capital ? "Your" : "your", stage_names[p]);
}
