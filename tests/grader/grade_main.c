/*
 * grade - the autograder's command line.
 *
 *   grade [--submission DIR] [--part 1|2|3a|3b|4|5] [--results FILE] [--quiet]
 *         [--report DIR | --report-file FILE] [--all-failures]
 *       grades one submission: the parts of tests/weights.conf's "parts"
 *       line, or the one part named; exit 0 for full marks, 1 when points
 *       are lost, 2 when the grader itself could not run.  --report also
 *       writes the page with pictures, DIR/index.html (--report-file: FILE);
 *       a page that cannot be written is reported and changes nothing else.
 *       The table is short (report_table.c); --all-failures shows every
 *       failure in full, as the page does.
 *   grade --all DIR [--out DIR] [--jobs N] [--previous DIR]
 *       grades every subdirectory of DIR, in parallel; writes
 *       OUT/gradebook.csv, OUT/<submission>.json and OUT/<submission>.html,
 *       then the class page, OUT/index.html, and OUT/causes.csv
 *       (report_class.h), comparing with the run whose OUT was --previous.
 *   --weights FILE reads the points and parts from FILE instead of
 *       tests/weights.conf (either form).
 *   --format gradescope|prairielearn: the form of the --results file
 *       (Gradescope's results.json by default; report_prairielearn.h).
 *   --classroom FILE appends GitHub Classroom's runner results to FILE,
 *       one NAME=BASE64 line per runner (report_classroom.h).
 *
 * Run it from the kit's root (make does).  Student code never runs in this
 * process: each test runs in a fresh sandboxed child (sandbox.c).
 */
#define _XOPEN_SOURCE 700
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "build.h"
#include "lmsname.h"
#include "config.h"
#include "csv.h"
#include "grade.h"
#include "grader.h"
#include "jail.h"
#include "report.h"
#include "report_class.h"
#include "report_classroom.h"
#include "report_prairielearn.h"
#include "sandbox.h"
#include "terminal.h"
#include "kit/savefile.h"
#ifdef GRADER_ORACLE
#include "../oracle/testgen.h"
#endif

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static void usage(void)
{
    fprintf(stderr,
            "usage: grade [--submission DIR] [--part 1|2|3a|3b|4|5] [--results FILE] [--quiet]\n"
            "             [--format gradescope|prairielearn] [--classroom FILE]\n"
            "             [--report DIR | --report-file FILE] [--cost] [--verbose] [--all-failures]\n"
            "       grade --all DIR [--out DIR] [--jobs N] [--previous DIR]\n"
            "       grade --jail    (says where the submissions' code runs)\n"
            "       either with --weights FILE (default tests/weights.conf)\n"
            "exit status: 0 full marks, 1 points lost, 2 the grader could not run\n");
    exit(2);
}

/* The --format of the results file, and the --classroom file (or NULL). */
static bool results_prairielearn;
static const char *classroom_path;
static bool show_cost;             /* --cost: where grading's CPU time went */
/* The class page (report_class.h): where grade --all's child writes its
 * record (--class-record), and the previous run's OUT (--previous). */
static const char *class_record;
static const char *previous_out;
static bool verbose;               /* --verbose: progress on stderr           */
static bool every_failure;         /* --all-failures: the table in full       */

static int fail(const char *results, const char *fmt, const char *what)
{
    char msg[1024], err[512];
    snprintf(msg, sizeof msg, fmt, what);
    fprintf(stderr, "grade: %s\n", msg);
    if (results && (results_prairielearn ? report_prairielearn_error(results, msg, err, sizeof err)
                                         : report_json_error(results, msg, err, sizeof err)) != 0)
        fprintf(stderr, "grade: %s\n", err);
    if (class_record)
        class_record_write_error(class_record, msg);
    return 2;
}

static int load_tests(TestList *list, const GradeConfig *cfg, const bool parts[NPARTS], char *err,
                      size_t errlen)
{
    for (int p = 0; p < NPARTS; p++) {
        char path[256];
        if (!parts[p])
            continue;                   /* not graded: its tests are not read */
        snprintf(path, sizeof path, "tests/public/part%s.tests", part_label(p));
        if (tests_read(list, path, false, err, errlen) != 0)
            return -1;
    }
#ifdef GRADER_ORACLE
    struct stat st;
    if (stat("tests/hidden", &st) == 0) {
        /* tests/weights.conf's seed, salted (testgen.h), not the
         * submission's files: every submission meets the same cases. */
        testgen_hidden(list, cfg->seed ^ HIDDEN_SALT_CORE);
        if (parts[PART4] || parts[PART5])
            testgen_hidden_flat(list, cfg->seed ^ HIDDEN_SALT_FLAT);
    }
#else
    (void)parts;
#endif
    /* A part whose hard cases are worth nothing (weights.conf) has no
     * challenge, and no hard-case test. */
    bool none[NPARTS];
    for (int p = 0; p < NPARTS; p++)
        none[p] = !(cfg->hard[p] > 0);
    testlist_drop_hard(list, none);
    return 0;
}

/* The scene the page shows, and the reference's picture of it: rendered
 * by make with solutions/ in the instructor's kit, stored in the student
 * kit. */
#define REPORT_SCENE "labs/scenes/default.scene"
static const char *const report_reference[2] = { "out/build/report/default.png",
                                                 "labs/reference/default.png" };

/* Writes the report page to page; says on stderr (and, unless quiet, on
 * stdout) what happened.  The grade and the results file never depend on it. */
static void write_page(const char *page, const Grade *g, const GradeConfig *cfg,
                       const BuildConfig *bc, const char *submission, const char *kept, bool quiet)
{
    char err[1024];
    ReportRenderOptions ro = {
        .build = bc, .submission = submission, .kept_objects = kept, .scene = REPORT_SCENE,
        .reference = { report_reference[0], report_reference[1] }, .timeout = cfg->timeout,
    };
    ReportRenders rr;
    bool have = report_render(&ro, &rr, err, sizeof err) == 0;
    if (!have)
        fprintf(stderr, "grade: the report page has no pictures of the scene: %s\n", err);
    if (report_html(page, g, cfg, submission, have ? &rr : NULL, err, sizeof err) != 0)
        fprintf(stderr, "grade: the report page was not written: %s\n", err);
    else if (!quiet) {
        bool failed = false;            /* a graded test failed: the page draws it */
        for (int k = 0; k < g->tests->n && !failed; k++)
            failed = g->graded[g->tests->tests[k].part] && !g->results[k].passed;
        printf(failed ? "\nThe report with pictures of every failure: %s\n"
                      : "\nThe report (no failure to draw; your render beside the reference's): %s\n", page);
    }
    if (have)
        report_renders_free(&rr);
}

/* In the student kit, whose tests/grader/shipped holds the headers as the
 * kit shipped them: says on stderr which of labs/raytracer.h and
 * labs/vec3.h a student has changed.  Instructors grade the stage files
 * alone with the kit's own headers, so the grader here builds them with
 * the shipped ones too (build.c): a stage file that needs a change made
 * in labs/ builds in make render and not in make grade, and this says why. */
static void warn_changed_headers(const char *root)
{
    static const char *names[] = { "raytracer.h", "vec3.h" };
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (build_header_changed(root, names[k]))
            fprintf(stderr, "grade: labs/%s is not the one the kit came with. Your instructor grades "
                            "your part*.c files with the kit's own %s, so whatever they use from your "
                            "change (a macro, a prototype, a field) will be missing there, and they "
                            "will not build; make grade builds them with the kit's own too "
                            "(tests/grader/shipped/%s). Keep such things in your part*.c files.\n",
                            names[k], names[k], names[k]);
}

/* Whether dir holds a stage file of any part. */
static bool holds_stage_file(const char *dir)
{
    for (int p = 0; p < NPARTS; p++) {
        char path[PATH_MAX];
        if ((size_t)snprintf(path, sizeof path, "%s/%s.c", dir, stage_names[p]) < sizeof path &&
            access(path, F_OK) == 0)
            return true;
    }
    return false;
}

/* The folder of submission whose stage files are graded, into out: the
 * submission itself, or its labs folder (not a link) when that holds stage
 * files and the submission none, as a repository made from the student
 * kit does (GitHub Classroom's, cloned for grade --all).  Returns whether
 * that folder holds any stage file. */
static bool graded_folder(const char *submission, char *out, size_t n)
{
    snprintf(out, n, "%s", submission);
    if (holds_stage_file(submission))
        return true;
    char labs[PATH_MAX];
    struct stat st;
    if ((size_t)snprintf(labs, sizeof labs, "%s/labs", submission) < sizeof labs &&
        lstat(labs, &st) == 0 && S_ISDIR(st.st_mode) && holds_stage_file(labs) && strlen(labs) < n) {
        snprintf(out, n, "%s", labs);
        return true;
    }
    return false;
}

/* The sandbox runs programs by path: finds cc on PATH, into ccpath (n
 * bytes); says whether it is there. */
static bool on_path(const char *cc, char *ccpath, size_t n)
{
    const char *path = getenv("PATH") ? getenv("PATH") : "/usr/bin:/bin";
    char *copy = strdup(path), *save = NULL;
    ccpath[0] = '\0';
    for (char *dir = strtok_r(copy, ":", &save); dir; dir = strtok_r(NULL, ":", &save)) {
        snprintf(ccpath, n, "%s/%s", dir, cc);
        if (access(ccpath, X_OK) == 0)
            break;
        ccpath[0] = '\0';
    }
    free(copy);
    return ccpath[0] != '\0';
}

/* grade --cost: where the CPU time went.  The whole process: the
 * grader's own CPU (reading the tests included) and every child it
 * waited for. */
static void say_cost(const Grade *g)
{
    double self = sandbox_cpu(true), total = self + sandbox_cpu(false);
    printf("cost (CPU seconds): compiling %.3f, linking %.3f, tests %.3f, probes %.3f, "
           "the grader %.3f; total %.3f = %.2f x compiling\n", g->cpu_compile, g->cpu_link,
           g->cpu_tests, g->cpu_probes, self, total,
           g->cpu_compile > 0 ? total / g->cpu_compile : 0);
    int nruns;
    double jail;
    sandbox_jail_cost(&nruns, &jail);
    printf("the jail: %d runs, %.3f s building their namespaces (%s)\n", nruns, jail,
           jail_namespaces() ? "counted in the runs above" : "none: the fallback");
}

/* How the submission's builds go: in root, with the compiler cc, the
 * harness and reference objects where the Makefile built them (their
 * folder written to objdir, size bytes). */
static BuildConfig build_config(const char *root, const char *cc, char *objdir, size_t size)
{
    char ref[PATH_MAX + 64];
#ifndef GRADER_BUILD
#define GRADER_BUILD "out/build"
#endif
    if (GRADER_BUILD[0] == '/')
        snprintf(objdir, size, "%s/grader", GRADER_BUILD);
    else
        snprintf(objdir, size, "%s/%s/grader", root, GRADER_BUILD);
    snprintf(ref, sizeof ref, "%s/ref_part1_image_plane.o", objdir);
    /* The prebuilt runners (Linux), unless GRADE_NO_LOAD is set (the kit's
     * own tests grade both ways and compare). */
    char runner[PATH_MAX + 64];
    snprintf(runner, sizeof runner, "%s/runner_part1", objdir);
    const char *no_load = getenv("GRADE_NO_LOAD");
    BuildConfig bc = { .root = root, .cc = cc, .objdir = objdir, .reference = access(ref, R_OK) == 0,
                       .load = access(runner, X_OK) == 0 && !(no_load && *no_load) };
    return bc;
}

/* The line grade --summary ends with, for grade --all: every part's core
 * points, the hard cases' points, the total and the exit status. */
static void print_summary(const Grade *g, int status)
{
    printf("summary");
    for (int p = 0; p < NPARTS; p++)
        printf(" %.6g", g->core[p]);
    double hard = 0;
    for (int p = 0; p < NPARTS; p++)
        hard += g->hard[p];
    printf(" %.6g %.6g %d\n", hard, g->total + g->bonus, status);
}

static int grade_one(const char *submission, const char *part, const char *results,
                     const char *weights, const char *page, bool quiet, bool summary)
{
    char err[1024];
    GradeConfig cfg;
    if (config_read(&cfg, weights, err, sizeof err) != 0)
        return fail(results, "%s", err);
    struct stat st;
    if (stat(submission, &st) != 0 || !S_ISDIR(st.st_mode))
        return fail(results, "%s is not a directory", submission);
    char folder[PATH_MAX];
    graded_folder(submission, folder, sizeof folder);
    submission = folder;

    char root[PATH_MAX];
    if (!getcwd(root, sizeof root))
        return fail(results, "getcwd: %s", strerror(errno));
    if (jail_make_private(root, err, sizeof err) != 0)
        return fail(results, "%s", err);
    warn_changed_headers(root);
    const char *cc = getenv("CC") && *getenv("CC") ? getenv("CC") : "cc";
    char ccpath[PATH_MAX];
    if (!strchr(cc, '/') && !on_path(cc, ccpath, sizeof ccpath))
        return fail(results, "no C compiler: %s is not on PATH", cc);
    if (!strchr(cc, '/'))
        cc = ccpath;
    char objdir[PATH_MAX + 32];
    BuildConfig bc = build_config(root, cc, objdir, sizeof objdir);

    GradeOptions opt = { .submission = submission, .cfg = &cfg, .build = &bc, .verbose = verbose };
    /* The page's render reuses the objects the graded builds compiled. */
    char kept[PATH_MAX] = "";
    if (page && build_tempdir(kept, sizeof kept, err, sizeof err) == 0)
        opt.keep_objects = kept;
    for (int p = 0; p < NPARTS; p++)
        opt.parts[p] = part && *part ? part_from_label(part) == p : cfg.parts[p];
    TestList tests = { 0 };
    if (load_tests(&tests, &cfg, opt.parts, err, sizeof err) != 0)
        return fail(results, "%s", err);

    Grade g;
    if (grade_submission(&opt, &tests, &g, err, sizeof err) != 0) {
        grade_free(&g);                 /* what it had made before it stopped */
        testlist_free(&tests);
        if (kept[0])
            jail_remove_tree(kept);
        return fail(results, "%s", err);
    }
    if (!quiet)
        report_table(stdout, &g, &cfg, submission, every_failure);
    if (show_cost)
        say_cost(&g);
    int status = g.total < g.total_max || g.bonus < g.bonus_max ? 1 : 0;
    if (results && (results_prairielearn ? report_prairielearn(results, &g, err, sizeof err)
                                         : report_json(results, &g, err, sizeof err)) != 0) {
        fprintf(stderr, "grade: %s\n", err);
        status = 2;
    }
    if (classroom_path && report_classroom(classroom_path, &g, err, sizeof err) != 0) {
        fprintf(stderr, "grade: %s\n", err);
        status = 2;
    }
    if (page)
        write_page(page, &g, &cfg, &bc, submission, kept[0] ? kept : NULL, quiet);
    if (class_record && class_record_write(class_record, &g, cfg.timeout, err, sizeof err) != 0)
        fprintf(stderr, "grade: %s\n", err);          /* the class page lacks it; nothing else */
    if (kept[0])
        jail_remove_tree(kept);
    if (summary)
        print_summary(&g, status);
    fflush(stdout);
    grade_free(&g);
    testlist_free(&tests);
    return status;
}

/* ---- grade --all ----------------------------------------------------------- */

typedef struct {
    char name[256];
    pid_t pid;
    int slot;                   /* its place among those graded at once */
    int fd;                     /* the child's stdout */
    char line[512];
    size_t len;
    int status;
} Job;

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* As root, the ids the submissions graded at once run their code as, one
 * each: spare ids, held against other graders for the whole run
 * (sandbox.h), so that one's code cannot signal another's tests, nor any
 * process of nobody's.  Fewer ids than jobs means fewer jobs; none (a
 * system that gives no spare ids) means one at a time, as nobody.  jobs
 * is at most MAX_ROOT_JOBS. */
#define MAX_ROOT_JOBS 64
static int job_users(int jobs, char ids[][16])
{
    uid_t spare[MAX_ROOT_JOBS];
    const char *unclaimed = NULL;
    int found = sandbox_spare_users(spare, jobs, &unclaimed);
    for (int k = 0; k < found; k++)
        snprintf(ids[k], sizeof ids[k], "%lu", (unsigned long)spare[k]);
    if (unclaimed && found > 0)
        fprintf(stderr, "grade: %s, so another grade --all run as root at the same time may "
                        "be given the same users\n", unclaimed);
    if (found == 0) {
        ids[0][0] = '\0';
        if (jobs > 1)
            fprintf(stderr, "grade: 1 submission at a time, not %d: as root each runs its code as "
                            "an unprivileged user of its own, and this system gives none but "
                            "nobody\n", jobs);
        return 1;
    }
    if (found < jobs)
        fprintf(stderr, "grade: %d submission%s at a time, not %d: as root each runs its code as "
                        "an unprivileged user of its own, and %d %s free (the system gives no "
                        "more, or other graders hold them)\n", found, found > 1 ? "s" : "", jobs,
                found, found > 1 ? "were" : "was");
    return found;
}

/* The folder of submissions, read: the submissions, and what was left out. */
typedef struct {
    char **names;       /* the submissions' folders, in order */
    int n;
    /* Folders whose names start with "." (.git, .github, a system's own)
     * and the __MACOSX that macOS's zip tool adds are not submissions: they
     * are left out, and the run names them, in order, the first eight. */
    int ndots;
    char hidden[256];
    int loose;          /* files named like stage files, at the top */
    int lms;            /* files named as a platform's download names them (lmsname.h) */
} Submissions;

/* A submission whose name the outputs cannot carry: "index", whose page
 * would be the class page (OUT/index.html, in any case where the file
 * system ignores case), or a name too long for NAME.json (a file's name
 * is at most 255 bytes).  Refused before anything is written, naming the
 * folder; returns 0, or fail's status. */
static int misnamed_submission(const char *dir, const Submissions *s)
{
    for (int k = 0; k < s->n; k++) {
        char shown[120] = "", err[1024];
        term_append(shown, sizeof shown, s->names[k]);
        size_t n = strlen(s->names[k]);
        if (strcasecmp(s->names[k], "index") == 0)
            snprintf(err, sizeof err, "%.600s/%s: a submission's folder may not be named %s, as its page "
                     "would be the class page (index.html): rename the folder", dir, shown, shown);
        else if (n > 255 - strlen(".json"))
            snprintf(err, sizeof err, "%.600s/%s%s: the folder's name is %zu bytes long, too long for its "
                     "results' file (the name and .json, at most 255 bytes): rename the folder", dir,
                     shown, strlen(shown) < n ? "..." : "", n);
        else
            continue;
        return fail(NULL, "%s", err);
    }
    return 0;
}

/* Reads the folder dir into s, refusing a misnamed submission; returns 0,
 * or fail's status (and s holds no names). */
static int read_submissions(const char *dir, Submissions *s)
{
    memset(s, 0, sizeof *s);
    char err[1024];
    DIR *d = opendir(dir);
    struct stat dst;
    if (!d && stat(dir, &dst) == 0 && S_ISREG(dst.st_mode)) {   /* a download's zip, most likely */
        snprintf(err, sizeof err, "%.300s is a file, not a folder of submissions: if it is a class's "
                 "download from Canvas, Moodle or Blackboard, make sort-submissions FROM=%.300s "
                 "TO=new-folder sorts it into a folder per submission", dir, dir);
        return fail(NULL, "%s", err);
    }
    if (!d)
        return fail(NULL, "%s: cannot open the submissions directory", dir);
    char **dots = NULL;
    struct dirent *e;
    while ((e = readdir(d))) {
        char path[PATH_MAX];
        struct stat st;
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (stat(path, &st) != 0)
            continue;
        LmsName named;
        s->lms += lms_name(e->d_name, stage_names, NPARTS, &named);
        if (!S_ISDIR(st.st_mode)) {
            for (int p = 0; p < NPARTS; p++) {
                size_t ln = strlen(e->d_name), ls = strlen(stage_names[p]);
                if (ln >= ls + 2 && strcmp(e->d_name + ln - 2, ".c") == 0 &&
                    strncmp(e->d_name + ln - 2 - ls, stage_names[p], ls) == 0)
                    s->loose++;
            }
            continue;
        }
        bool system = e->d_name[0] == '.' || strcmp(e->d_name, "__MACOSX") == 0;
        char ***list = system ? &dots : &s->names;
        int *count = system ? &s->ndots : &s->n;
        char **grown = realloc(*list, (size_t)(*count + 1) * sizeof **list);
        char *name = strdup(e->d_name);
        if (!grown || !name) {
            closedir(d);
            return fail(NULL, "%s", "out of memory");
        }
        *list = grown;
        grown[(*count)++] = name;
    }
    closedir(d);
    if (s->ndots > 1)
        qsort(dots, (size_t)s->ndots, sizeof *dots, by_name);
    for (int k = 0; k < s->ndots; k++) {
        if (k > 0 && k <= 8)
            term_append(s->hidden, sizeof s->hidden, k < 8 ? ", " : ", ...");
        if (k < 8)
            term_append(s->hidden, sizeof s->hidden, dots[k]);
        free(dots[k]);
    }
    free(dots);
    if (s->n > 1)
        qsort(s->names, (size_t)s->n, sizeof *s->names, by_name);
    int rc = misnamed_submission(dir, s);
    if (rc != 0) {
        for (int k = 0; k < s->n; k++)
            free(s->names[k]);
        free(s->names);
        s->names = NULL;
        s->n = 0;
    }
    return rc;
}

/* A folder with no submissions: a wrong folder, most likely, and nothing
 * is written.  Says what it holds instead; returns fail's status. */
static int no_submissions(const char *dir, const Submissions *s)
{
    char err[1024], more[700] = "";
    if (s->lms)          /* a platform's download: the sorter reads its names */
        snprintf(more, sizeof more, "; %d of its files or folders are named as a Canvas, Moodle or "
                 "Blackboard download names a class's files: make sort-submissions FROM=%s "
                 "TO=new-folder sorts them into a folder per submission", s->lms, dir);
    else if (s->loose)          /* one folder of every student's files, as some downloads give */
        snprintf(more, sizeof more, "; it holds %d stage file%s of its own: put each submission's files "
                 "in a folder of its own, named after it", s->loose, s->loose == 1 ? "" : "s");
    snprintf(err, sizeof err, "%s holds no submissions: each submission is a folder of stage files in "
             "it%s%s%s%s", dir, s->ndots ? " (folders of the system's own, a name starting with \".\" or "
                                          "__MACOSX, are left out: " : "",
             s->hidden, s->ndots ? ")" : "", more);
    return fail(NULL, "%s", err);
}

/* What every child of a grade --all run is given. */
typedef struct {
    const char *self, *dir, *out, *weights;
    ClassRun *class_run;        /* NULL, or the class page's */
    char (*users)[16];          /* as root: the ids the code runs as, one a place */
    bool *busy;                 /* as root: the places taken */
} AllRun;

/* Starts grading submission k, name, in a child of its own whose summary
 * line j->fd reads; returns 0, or fail's status. */
static int start_job(const AllRun *run, Job *j, int k, const char *name)
{
    snprintf(j->name, sizeof j->name, "%s", name);
    char sub[PATH_MAX], res[PATH_MAX], page[PATH_MAX];
    snprintf(sub, sizeof sub, "%s/%s", run->dir, name);
    snprintf(res, sizeof res, "%s/%s.json", run->out, name);
    snprintf(page, sizeof page, "%s/%s.html", run->out, name);
    char record[PATH_MAX];
    if (run->class_run)
        class_record_path(run->class_run, k, record, sizeof record);
    /* As root, a free place, and with it the id the code runs as. */
    j->slot = 0;
    while (run->busy && run->busy[j->slot])
        j->slot++;
    const char *user = run->users ? run->users[j->slot] : "";
    if (run->busy)
        run->busy[j->slot] = true;
    int p[2];
    if (pipe(p) != 0)
        return fail(NULL, "pipe: %s", strerror(errno));
    j->pid = fork();
    if (j->pid == 0) {
        dup2(p[1], 1);
        close(p[0]);
        close(p[1]);
        char *argv[18] = { (char *)run->self, "--submission", sub, "--results", res,
                           "--weights", (char *)run->weights, "--report-file", page,
                           "--quiet", "--summary" };
        int argc = 11;
        if (user[0]) {
            argv[argc++] = "--sandbox-user";
            argv[argc++] = (char *)user;
        }
        if (run->class_run) {
            argv[argc++] = "--class-record";
            argv[argc++] = record;
        }
        argv[argc] = NULL;
        execv(run->self, argv);
        _exit(2);
    }
    close(p[1]);
    j->fd = p[0];
    return 0;
}

/* The child pid of the first next jobs has ended with status: reads its
 * summary line and frees its place.  Returns how many jobs that ended. */
static int end_job(const AllRun *run, Job *all, int next, pid_t pid, int status)
{
    int ended = 0;
    for (int k = 0; k < next; k++) {
        Job *j = &all[k];
        if (j->pid != pid)
            continue;
        ssize_t r;
        while ((r = read(j->fd, j->line + j->len, sizeof j->line - 1 - j->len)) > 0)
            j->len += (size_t)r;
        j->line[j->len] = '\0';
        close(j->fd);
        j->status = WIFEXITED(status) ? WEXITSTATUS(status) : 2;
        j->pid = 0;
        if (run->busy)
            run->busy[j->slot] = false;
        ended++;
    }
    return ended;
}

/* Grades the submissions, jobs at a time, into all; returns 0, or
 * fail's status. */
static int run_jobs(const AllRun *run, const Submissions *s, Job *all, int jobs)
{
    int n = s->n, next = 0, running = 0, done = 0;
    const bool show_progress = isatty(STDERR_FILENO);   /* a log gets only the summary */
    while (done < n) {
        while (running < jobs && next < n) {
            int rc = start_job(run, &all[next], next, s->names[next]);
            if (rc != 0)
                return rc;
            next++;
            running++;
        }
        /* Wait for any child; read its summary line. */
        int status;
        pid_t pid = wait(&status);
        if (pid < 0)
            break;
        int ended = end_job(run, all, next, pid, status);
        running -= ended;
        done += ended;
        if (show_progress)
            fprintf(stderr, "\r  graded %d of %d submissions", done, n);
    }
    if (show_progress)
        fprintf(stderr, "\n");
    return 0;
}

/* What the gradebook says beyond its rows. */
typedef struct {
    int worst;                  /* 2 when a grading gave no summary, else 0 */
    int nempty;                 /* submissions with no stage file */
    char empty[200];            /* the first four of them */
} Gradebook;

/* One row of the gradebook f for job j, submission k, from its summary
 * line; its values to the class page too. */
static void gradebook_row(FILE *f, const GradeConfig *cfg, const AllRun *run, const Job *j, int k,
                          int ncols, Gradebook *gb)
{
    /* No stage file where the grader looks (the folder, or its labs):
     * nothing handed in, or files under other names (its .json names
     * them), which the gradebook tells from points lost. */
    char sub[PATH_MAX], folder[PATH_MAX];
    snprintf(sub, sizeof sub, "%s/%s", run->dir, j->name);
    bool none = !graded_folder(sub, folder, sizeof folder);
    double v[NPARTS + 2];
    int st = 2, used = 0;
    const char *s = strstr(j->line, "summary ");
    bool ok = s != NULL;
    if (ok)
        s += 7;
    for (int c = 0; ok && c < NPARTS + 2; c++) {
        ok = sscanf(s, "%lf%n", &v[c], &used) == 1;
        s += used;
    }
    ok = ok && sscanf(s, "%d", &st) == 1;
    class_add(run->class_run, k, j->name, ok ? v : NULL, ok ? st : j->status, none);
    csv_field(f, j->name);
    if (ok) {
        for (int p = 0; p < NPARTS; p++)
            if (cfg->parts[p])
                fprintf(f, ",%g", v[p]);
        fprintf(f, ",%g,%g,%s\n", v[NPARTS], v[NPARTS + 1],
                st == 0 ? "full marks" : none ? "no stage file" : "points lost");
        if (none && gb->nempty++ < 4) {
            term_append(gb->empty, sizeof gb->empty, gb->nempty > 1 ? ", " : "");
            term_append(gb->empty, sizeof gb->empty, j->name);
        }
    } else {
        for (int c = 0; c < ncols + 2; c++)
            fputc(',', f);
        fputc(',', f);
        char why[sizeof j->name + 32];
        snprintf(why, sizeof why, "grader error (see %s.json)", j->name);
        csv_field(f, why);
        fputc('\n', f);
        /* A grading that ended without its results (the grader killed,
         * say) gets a results file that says so, as the row does. */
        char res[PATH_MAX], said[200], werr[256];
        struct stat rst;
        snprintf(res, sizeof res, "%s/%s.json", run->out, j->name);
        snprintf(said, sizeof said, "The grader stopped (status %d) before it wrote this "
                 "submission's results: please tell the course staff.", j->status);
        if (lstat(res, &rst) != 0)
            report_json_error(res, said, werr, sizeof werr);
    }
    if (!ok)
        gb->worst = 2;
}

/* Writes csv, the gradebook, a row a job; returns 0, or fail's status. */
static int write_gradebook(const char *csv, const GradeConfig *cfg, const AllRun *run, const Job *all,
                           int n, Gradebook *gb)
{
    char err[PATH_MAX + 128];
    SaveStream out;
    FILE *f = save_open(&out, csv, err, sizeof err);
    if (!f)
        return fail(NULL, "%s", err);
    /* One column per graded part (the "parts" line), then the hard-case
     * points, the total and the status. */
    fprintf(f, "submission");
    int ncols = 0;
    for (int p = 0; p < NPARTS; p++)
        if (cfg->parts[p]) {
            fprintf(f, ",part%s", part_label(p));
            ncols++;
        }
    fprintf(f, ",hard,total,status\n");
    for (int k = 0; k < n; k++)
        gradebook_row(f, cfg, run, &all[k], k, ncols, gb);
    if (save_close(&out, csv, 0600, err, sizeof err) != 0)   /* every grade in it: the owner's alone */
        return fail(NULL, "%s", err);
    return 0;
}

/* What the run did, after the gradebook is written. */
static void say_what_was_done(const Submissions *s, const char *dir, const char *csv, const Gradebook *gb,
                              bool as_users, int jobs)
{
    int n = s->n, nempty = gb->nempty, loose = s->loose;
    if (as_users && jobs > 1)
        printf("graded %d at a time, as root: each one's code ran as an unprivileged user of its "
               "own\n", jobs);
    if (!sandbox_drops_privileges() && jail_namespaces())
        printf("graded as yourself, not as root: each submission's code ran in a jail of its own "
               "(a user namespace), which showed it none of your files and none of your processes\n");
    else if (!sandbox_drops_privileges())
        printf("graded as yourself, not as root, where this system gives no namespaces: each "
               "submission's code ran as you, and could read and change your files and stop your "
               "processes; grade code you do not trust as root, where each submission's code runs as an "
               "unprivileged user of its own\n");
    if (s->ndots)
        printf("left out %d folder%s of the system's own (a name starting with \".\", or macOS's __MACOSX), "
               "not taken for a submission: %s\n", s->ndots, s->ndots == 1 ? "" : "s", s->hidden);
    if (loose)
        printf("left out %d stage file%s lying in %s itself: a submission is a folder of its own%s\n", loose,
               loose == 1 ? "" : "s", dir,
               s->lms ? " (they are named as a Canvas, Moodle or Blackboard download names a class's files: "
                        "make sort-submissions sorts them into a folder per submission)" : "");
    if (nempty)
        printf("%d submission%s no stage file (status \"no stage file\": empty, or files under other "
               "names, which %s .json names): %s%s\n", nempty, nempty == 1 ? " holds" : "s hold",
               nempty == 1 ? "its" : "each one's", gb->empty, nempty > 4 ? ", ..." : "");
    printf("graded %d submission%s: wrote %s, and one .json and one .html (the report page) %s\n",
           n, n == 1 ? "" : "s", csv, n == 1 ? "for it" : "each");
}

static int grade_all(const char *self, const char *dir, const char *out, const char *weights, int jobs)
{
    char err[1024];
    GradeConfig cfg;
    if (config_read(&cfg, weights, err, sizeof err) != 0)
        return fail(NULL, "%s", err);
    Submissions s;
    int rc = read_submissions(dir, &s);
    if (rc != 0)
        return rc;
    int n = s.n;
    if (n == 0)
        return no_submissions(dir, &s);
    if (mkdir(out, 0700) != 0 && errno != EEXIST)
        return fail(NULL, "%s: cannot make the output directory", out);
    char here[PATH_MAX];
    if (!getcwd(here, sizeof here) || jail_make_private(here, err, sizeof err) != 0 ||
        jail_make_private(dir, err, sizeof err) != 0 || jail_make_private(out, err, sizeof err) != 0)
        return fail(NULL, "%s", err);
    AllRun run = { self, dir, out, weights, class_begin(out, previous_out), NULL, NULL };

    jobs = jobs < n ? jobs : n;      /* n > 0: an empty folder was refused above */
    if (sandbox_drops_privileges()) {
        jobs = jobs < MAX_ROOT_JOBS ? jobs : MAX_ROOT_JOBS;
        run.users = calloc((size_t)jobs, sizeof *run.users);
        run.busy = calloc((size_t)jobs, sizeof *run.busy);
        if (!run.users || !run.busy)
            return fail(NULL, "%s", "out of memory");
        jobs = job_users(jobs, run.users);
    }
    Job *all = calloc((size_t)n + 1, sizeof *all);
    rc = run_jobs(&run, &s, all, jobs);
    if (rc != 0)
        return rc;
    char csv[PATH_MAX];
    snprintf(csv, sizeof csv, "%s/gradebook.csv", out);
    Gradebook gb = { 0, 0, "" };
    rc = write_gradebook(csv, &cfg, &run, all, n, &gb);
    bool as_users = run.users != NULL;
    for (int k = 0; k < n; k++)
        free(s.names[k]);
    free(s.names);
    free(all);
    free(run.users);
    free(run.busy);
    if (rc != 0)
        return rc;
    say_what_was_done(&s, dir, csv, &gb, as_users, jobs);
    class_finish(run.class_run, &cfg, load_tests);
    return gb.worst;
}

/* A whole number from v, lo to hi; false when v is anything else. */
static bool whole_number(const char *v, long lo, long hi, long *n)
{
    char *end;
    errno = 0;
    *n = strtol(v, &end, 10);
    return end != v && !*end && !errno && *n >= lo && *n <= hi;
}

int main(int argc, char **argv)
{
    const char *submission = "labs", *part = NULL, *results = NULL, *all = NULL, *out = "out/grades";
    const char *weights = "tests/weights.conf", *format = NULL, *page = NULL, *report = NULL, *user = NULL;
    char page_buf[PATH_MAX];
    bool quiet = false, summary = false, jail = false;
    long jobs = sysconf(_SC_NPROCESSORS_ONLN), user_id = 0;
    enum { TAKE, EMPTY_IS_NULL, EMPTY_IS_DEFAULT };
    const struct { const char *name; const char **to; int empty; } words[] = {
        { "--submission", &submission, TAKE },  { "--part", &part, TAKE },
        { "--results", &results, EMPTY_IS_NULL }, { "--all", &all, TAKE },
        { "--out", &out, EMPTY_IS_DEFAULT },     { "--report", &report, TAKE },
        { "--report-file", &page, EMPTY_IS_NULL }, { "--weights", &weights, TAKE },
        { "--format", &format, TAKE },
        { "--class-record", &class_record, TAKE }, /* from grade --all */
        { "--previous", &previous_out, EMPTY_IS_NULL },
        { "--sandbox-user", &user, TAKE },       /* from grade --all, as root */
        { "--classroom", &classroom_path, EMPTY_IS_NULL },
        { "--jobs", NULL, TAKE },
    };
    const struct { const char *name; bool *to; } flags[] = {
        { "--quiet", &quiet }, { "--summary", &summary }, { "--cost", &show_cost }, { "--jail", &jail },
        { "--verbose", &verbose }, { "--all-failures", &every_failure },
    };
    for (int k = 1; k < argc; k++) {
        bool known = false;
        for (size_t w = 0; w < sizeof words / sizeof words[0] && !known; w++) {
            if (strcmp(argv[k], words[w].name) != 0 || k + 1 >= argc)
                continue;
            const char *v = argv[++k];
            known = true;
            if (!words[w].to && !whole_number(v, 1, 1024, &jobs)) {
                fprintf(stderr, "grade: --jobs %s: want a whole number of submissions at a time, 1 to 1024\n", v);
                return 2;
            }
            if (words[w].to && (*v || words[w].empty == TAKE))
                *words[w].to = v;
            else if (words[w].to && words[w].empty == EMPTY_IS_NULL)
                *words[w].to = NULL;
        }
        for (size_t w = 0; w < sizeof flags / sizeof flags[0] && !known; w++)
            if (strcmp(argv[k], flags[w].name) == 0)
                known = *flags[w].to = true;
        if (!known)
            usage();
    }
    if (jail) {
        printf("%s\n", jail_describe());
        return 0;
    }
    if (report) {
        snprintf(page_buf, sizeof page_buf, "%s/index.html", report);
        page = page_buf;
    }
    if (user) {
        if (!whole_number(user, 1, LONG_MAX, &user_id) || user_id != (long)(uid_t)user_id || (uid_t)user_id == (uid_t)-1)
            usage();
        sandbox_set_user((uid_t)user_id, true);     /* held by grade --all for this one */
    }
    if (format && *format && strcmp(format, "gradescope") != 0 && strcmp(format, "prairielearn") != 0) {
        fprintf(stderr, "grade: FORMAT must be gradescope or prairielearn, not '%s'\n", format);
        return 2;
    }
    results_prairielearn = format && !strcmp(format, "prairielearn");
    if (part && *part && part_from_label(part) < 0) {
        fprintf(stderr, "grade: PART must be 1, 2, 3a, 3b, 4 or 5, not '%s'\n", part);
        return 2;
    }
    if (all) {
        char self[PATH_MAX];
        if (!realpath(argv[0], self))
            return fail(NULL, "cannot find this program: %s", argv[0]);
        char wpath[PATH_MAX];
        if (!realpath(weights, wpath))      /* the children run from the same root */
            return fail(NULL, "%s: cannot find the weights file", weights);
        return grade_all(self, all, out, wpath, jobs > 0 ? (int)jobs : 1);
    }
    /* As root, a submission graded alone runs its code as an unprivileged
     * user of its own too: a spare id, held for the whole grading against
     * every other grader (sandbox.h), so that its code cannot signal the
     * tests of another grading run at the same time, nor the system's
     * processes that run as nobody.  Where the system gives no spare id,
     * as nobody. */
    if (!user && sandbox_drops_privileges()) {
        uid_t id;
        const char *unclaimed = NULL;
        if (sandbox_spare_users(&id, 1, &unclaimed) == 1) {
            sandbox_set_user(id, unclaimed == NULL);
            if (unclaimed && !quiet)
                fprintf(stderr, "grade: %s, so another grading run as root at the same time may "
                                "run its code as the same user\n", unclaimed);
        }
    }
    return grade_one(submission, part, results, weights, page, quiet, summary);
}
