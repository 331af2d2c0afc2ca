/*
 * build.c - see build.h.
 */
#define _XOPEN_SOURCE 700
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "build.h"
#include "contract.h"
#include "grader.h"
#include "include_scan.h"
#include "jail.h"
#include "linkmsg.h"
#include "lookalike.h"
#include "own_headers.h"
#include "sandbox.h"
#include "kit/savefile.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


/* The compiler's limits, per run (tests/grader/README.md, "Limits").
 * Compiling a stage file takes gcc 0.2 s and 30 MiB resident (49 MiB of
 * address space), clang 0.5 s and 98 MiB (228 MiB of address space);
 * linking the test program less.  Objects are a few KiB. */
#define CC_SECONDS   20             /* wall clock: a pipe can only be timed out */
#define LOAD_SECONDS 5              /* runner --check: loading the object      */
#define LOAD_MEMORY_MB 64           /* as a test's                              */
#define CC_CPU       10             /* CPU seconds of each of its processes */
#define CC_MEMORY_MB 512            /* address space of each process (resident
                                       memory of the group on macOS) */
#define CC_FILE_MB   16             /* largest file it may write */

const char *const stage_names[NPARTS] = { CONTRACT_STAGE_NAMES };

/* Whether every folder from the root down to path (included) lets anyone
 * pass (o+x): where the fallback jail's user must reach its run's folders. */
static bool reachable(const char *path)
{
    char part[PATH_MAX];
    snprintf(part, sizeof part, "%s", path);
    for (;;) {
        struct stat st;
        if (stat(part[0] ? part : "/", &st) != 0 || !(st.st_mode & S_IXOTH))
            return false;
        char *slash = strrchr(part, '/');
        if (!slash || !part[0])
            return true;
        *slash = '\0';
    }
}

int build_tempdir(char *dir, size_t len, char *err, size_t errlen)
{
    const char *base = getenv("TMPDIR");
    /* As root in the fallback jail, the runs' user reaches its folders
     * through it: a TMPDIR in a private folder gives way to /tmp. */
    bool fallback = sandbox_drops_privileges() && !jail_namespaces();
    if (!base || !*base || access(base, W_OK) != 0 || base[0] != '/' || (fallback && !reachable(base)))
        base = "/tmp";
    snprintf(dir, len, "%s/rtgrade.XXXXXX", base);
    if (!mkdtemp(dir)) {
        snprintf(err, errlen, "cannot make a temporary directory in %s: %s", base, strerror(errno));
        return -1;
    }
    return 0;
}

/* Opens a submission's stage file to read: a regular file, not through a
 * symbolic link (as root, a link could point the grader at the reference
 * or at a file only root may read), and never waiting on a pipe.  The
 * descriptor, or -1 with errno ENOENT (none), ELOOP (a link) or EINVAL
 * (not a regular file). */
static int build_open_stage(const char *path)
{
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        if (errno == EMLINK)        /* what FreeBSD says of a link */
            errno = ELOOP;
        return -1;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        errno = EINVAL;
        return -1;
    }
    return fd;
}

static int copy_fd(int in, const char *src, const char *dst, size_t max, char *err, size_t errlen);

/* Copies src to dst (at most max bytes; larger is an error), mode 0644. */
static int copy_file(const char *src, const char *dst, size_t max, char *err, size_t errlen)
{
    int in = open(src, O_RDONLY);
    if (in < 0) {
        snprintf(err, errlen, "%s: %s", src, strerror(errno));
        return -1;
    }
    return copy_fd(in, src, dst, max, err, errlen);
}

/* copy_file from the open descriptor in, which it closes; the copy is
 * readable by all who may enter its folder (a run's user reads src/). */
static int copy_fd(int in, const char *src, const char *dst, size_t max, char *err, size_t errlen)
{
    FILE *f = fdopen(in, "rb");
    size_t n = 0;
    char *bytes = f ? kit_load_stream(f, max, &n) : NULL;
    if (!f)
        close(in);
    if (!bytes) {
        snprintf(err, errlen, "%s: not a regular file of at most %zu bytes", src, max);
        return -1;
    }
    int status = kit_save_file(dst, bytes, n, err, errlen);
    free(bytes);
    return status == 0 ? chmod(dst, 0644) : status;
}

/* The submission's stage file of part p, read; NULL when it has none (or
 * it cannot be read). */
static char *read_stage(const char *submission, int p)
{
    char path[PATH_MAX + 100];
    if ((size_t)snprintf(path, sizeof path, "%s/%s.c", submission, stage_names[p]) >= sizeof path)
        return NULL;
    int fd = build_open_stage(path);
    FILE *f = fd >= 0 ? fdopen(fd, "rb") : NULL;
    if (!f && fd >= 0)
        close(fd);
    size_t len = 0;
    return f ? kit_load_stream(f, BUILD_SOURCE_MAX, &len) : NULL;
}

void build_explain_undefined(Build *b, const char *submission, int part)
{
    char names[3][LINKMSG_NAME_MAX];
    int nnames = b->messages ? linkmsg_undefined(b->messages, names, 3) : 0;
    if (nnames == 0)
        return;
    char *texts[NPARTS];
    for (int p = 0; p < NPARTS; p++)
        texts[p] = read_stage(submission, p);
    for (int k = 0; k < nnames; k++) {
        const char *stage = linkmsg_stage_of(names[k]);
        bool own = stage && strcmp(stage, stage_names[part]) == 0;
        int in = -1;
        for (int p = 0; p < NPARTS && in < 0; p++)
            if (p != part && texts[p] && linkmsg_defines(texts[p], names[k]))
                in = p;
        if (own && in >= 0) {
            appendf(&b->messages, "`%s' is defined in your %s.c, but it belongs in %s.c "
                    "(labs/raytracer.h), and each part is graded with the reference's other parts, "
                    "not with your other files: move it to %s.c\n", names[k], stage_names[in],
                    stage_names[part], stage_names[part]);
        } else if (own && texts[part] && !linkmsg_defines(texts[part], names[k])) {
            char defined[8 * LINKMSG_NAME_MAX + 64];
            linkmsg_definitions_list(texts[part], defined, sizeof defined);
            appendf(&b->messages, "your %s.c defines no function %s, which the tests call by the name "
                    "labs/raytracer.h declares. The functions it defines: %s.\n", stage_names[part],
                    names[k], defined);
        } else if (!stage && in >= 0) {
            appendf(&b->messages, "`%s' is defined in your %s.c, but each part is graded with the "
                    "reference's other parts, not with your other files: define %s in %s.c too "
                    "(static, so that the two do not clash in make render)\n", names[k],
                    stage_names[in], names[k], stage_names[part]);
        }
    }
    for (int p = 0; p < NPARTS; p++)
        free(texts[p]);
}

bool build_header_changed(const char *root, const char *name)
{
    char shipped[PATH_MAX], mine[PATH_MAX];
    snprintf(shipped, sizeof shipped, "%s/tests/grader/shipped/%s", root, name);
    snprintf(mine, sizeof mine, "%s/labs/%s", root, name);
    size_t n1 = 0, n2 = 0;
    char *a = kit_load_file(shipped, BUILD_SOURCE_MAX, &n1);
    char *c = a ? kit_load_file(mine, BUILD_SOURCE_MAX, &n2) : NULL;
    bool changed = a && (!c || n1 != n2 || memcmp(a, c, n1) != 0);
    free(a);
    free(c);
    return changed;
}

void build_explain_headers(const BuildConfig *cfg, Build *b, int part)
{
    static const char *names[] = { "raytracer.h", "vec3.h" };
    for (int k = 0; k < 2; k++)
        if (build_header_changed(cfg->root, names[k]))
            appendf(&b->messages, "labs/%s is not the one the kit came with: %s.c was built with the "
                    "kit's own, as your instructor's grader builds it. If it uses something you added "
                    "to labs/%s (a macro, a prototype), move that into %s.c.\n",
                    names[k], stage_names[part], names[k], stage_names[part]);
}

/* After a stage file did not compile: the characters in it that look like
 * C's but are not, which the compiler calls "stray" or "unexpected". */
static void explain_lookalikes(Build *b, const char *text, size_t n, const char *cfile)
{
    char lines[1200];
    if (lookalike_explain(text, n, cfile, lines, sizeof lines) == 0)
        return;
    appendf(&b->messages, "%s\n%s", LOOKALIKE_INTRO, lines);
}

/* After a failed compile: the headers the file includes from its own
 * folder in the submission, which its build here does not have. */
static void explain_own_headers(Build *b, const char *text, size_t n, const char *submission,
                                const char *cfile)
{
    char lines[1400];
    const char *dirs[] = { submission };
    if (own_headers_explain(text, n, dirs, 1, cfile, lines, sizeof lines) > 0)
        appendf(&b->messages, "%s", lines);
}

/* The file was not handed to the compiler: says why, and returns 0. */
static int not_compiled(Build *b, const char *what, const char *name)
{
    appendf(&b->messages, "%s%s\n", what, name);
    b->refused = true;
    return 0;
}

/* name's letters and digits, lower case, into out (at most n - 1 of them). */
static void name_key(const char *name, char *out, size_t n)
{
    size_t k = 0;
    for (; *name && k + 1 < n; name++) {
        unsigned char c = (unsigned char)*name;
        if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))
            out[k++] = (char)c;
        else if (c >= 'A' && c <= 'Z')
            out[k++] = (char)(c - 'A' + 'a');
    }
    out[k] = '\0';
}

/* Whether name ends in ".c", in any case. */
static bool c_file(const char *name)
{
    size_t n = strlen(name);
    return n > 2 && name[n - 2] == '.' && (name[n - 1] == 'c' || name[n - 1] == 'C');
}

/* The stage file is missing: says so, naming the files of the submission
 * that look like it under another name ("part1_image_plane (1).c", as a
 * browser names a second download; "Part1_Image_Plane.c"; a ".c.txt"),
 * and the C files named for its part alone ("part1.c", "Part3a_v2.c"). */
static int missing_stage(Build *b, const char *submission, const char *stage, const char *cfile)
{
    char want[80], part[80], key[300], seen[600] = "";
    int nseen = 0;
    name_key(stage, want, sizeof want);
    snprintf(part, sizeof part, "%.*s", (int)strcspn(stage, "_"), stage);     /* "part3a" */
    size_t np = strlen(part);
    DIR *d = opendir(submission);
    struct dirent *e;
    while (d && (e = readdir(d)) && nseen < 3) {
        name_key(e->d_name, key, sizeof key);
        bool for_part = c_file(e->d_name) && strncmp(key, part, np) == 0 &&
                        !(key[np] >= '0' && key[np] <= '9');                /* not part10.c */
        if ((!strstr(key, want) && !for_part) || strcmp(e->d_name, cfile) == 0)
            continue;
        size_t len = strlen(seen);
        snprintf(seen + len, sizeof seen - len, "%s%s", nseen ? ", " : "", e->d_name);
        nseen++;
    }
    if (d)
        closedir(d);
    if (nseen == 0)
        return not_compiled(b, "missing: the submission has no ", cfile);
    char text[900];
    snprintf(text, sizeof text, "%s; it has %s: hand it in as %s", cfile, seen, cfile);
    return not_compiled(b, "missing: the submission has no ", text);
}

/* The folder of a compiler that lies outside the system's program
 * folders, which the jail must show it: the folder of the file cc names
 * (links followed), or that folder's parent when it is a "bin" (/opt/gcc-13
 * for /opt/gcc-13/bin/gcc).  Nothing for one in the system's folders; and
 * nothing where that folder would show more than a compiler's (the root,
 * /tmp, a folder holding the kit or the grader's builds): such a compiler
 * cannot run in the jail, and run_cc says so. */
static void compiler_folder(const BuildConfig *cfg, const Build *b, char *out, size_t n)
{
    static const char *const system[] = { "/usr/", "/bin/", "/sbin/", "/lib/", "/lib64/" };
    char real[PATH_MAX], root[PATH_MAX], builds[PATH_MAX];
    out[0] = '\0';
    if (!realpath(cfg->cc, real))
        return;
    for (size_t k = 0; k < sizeof system / sizeof system[0]; k++)
        if (strncmp(real, system[k], strlen(system[k])) == 0)
            return;
    char *slash = strrchr(real, '/');
    if (!slash || slash == real)
        return;
    *slash = '\0';
    slash = strrchr(real, '/');
    if (slash && slash != real && strcmp(slash, "/bin") == 0)
        *slash = '\0';
    snprintf(builds, sizeof builds, "%s", b->dir);
    slash = strrchr(builds, '/');
    if (slash)
        *slash = '\0';                    /* the folder of every grading's build */
    if (!realpath(cfg->root, root) || path_below(root, real) || path_below(builds, real) ||
        path_below(real, root) || strcmp(real, "/tmp") == 0 || strcmp(real, "/var/tmp") == 0)
        return;
    snprintf(out, n, "%s", real);
}

/* Runs the compiler in the sandbox: in b->dir/src, which it may only read,
 * writing in the run's own folder (b->rundir) the files keep names, which
 * are then copied into src.  0 if it succeeded, 1 if not (its messages,
 * and why it was stopped, in b->messages), -1 when the grader could not
 * run it (err: the sandbox failed, or the compiler could not be started,
 * which is the kit's fault, not the student's). */
static int run_cc(const BuildConfig *cfg, Build *b, char **argv, const char *const *keep,
                  double *cpu, char *err, size_t errlen)
{
    char src[600], cc_folder[PATH_MAX];
    snprintf(src, sizeof src, "%s/src", b->dir);
    compiler_folder(cfg, b, cc_folder, sizeof cc_folder);
    const char *visible[] = { src, cc_folder[0] ? cc_folder : NULL, NULL };
    SandboxSpec spec = {
        .argv = argv, .workdir = b->rundir, .cwd = src, .visible = visible, .keep = keep,
        .keep_to = src, .keep_max = (size_t)CC_FILE_MB << 20, .timeout = CC_SECONDS,
        .cpu_seconds = CC_CPU, .answer_max = 0, .output_max = 16384, .memory_mb = CC_MEMORY_MB,
        .max_procs = -1, .max_file_mb = CC_FILE_MB, .compiler = true,
    };
    SandboxResult res;
    if (sandbox_run(&spec, &res, err, errlen) != 0)
        return -1;
    *cpu += res.cpu_seconds;
    if (res.exit_code >= 125 && res.exit_code <= 127) {
        /* The jail or exec failed: the compiler never ran. */
        snprintf(err, errlen, "the compiler could not be started (%s, exit status %d%s%.300s): the "
                 "kit's error, not the submission's", cfg->cc, res.exit_code,
                 res.output_len ? ": " : "", res.output);
        sandbox_result_free(&res);
        return -1;
    }
    appendf(&b->messages, "%s", res.output);
    char why[200] = "";
    if (res.timed_out)
        snprintf(why, sizeof why, "the compiler took more than %d s, and was stopped\n", CC_SECONDS);
    else if (res.memory_exceeded)
        snprintf(why, sizeof why, "the compiler used more than %d MiB of memory, and was stopped\n", CC_MEMORY_MB);
    else if (res.signal == SIGXCPU)
        snprintf(why, sizeof why, "the compiler used more than %d s of CPU time, and was stopped\n", CC_CPU);
    else if (res.signal == SIGXFSZ)
        snprintf(why, sizeof why, "the compiler wrote a file larger than %d MiB, and was stopped\n", CC_FILE_MB);
    else if (res.signal == SIGKILL)
        snprintf(why, sizeof why, "the compiler was killed (signal 9): most likely the system ran out of memory\n");
    else if (res.signal)
        snprintf(why, sizeof why, "the compiler was killed by signal %d\n", res.signal);
    appendf(&b->messages, "%s", why);
    int ok = res.exit_code == 0;
    sandbox_result_free(&res);
    return ok ? 0 : 1;
}

/* Is name, as the compiler would find it from the build's src directory,
 * a file of the kit (the reference, the hidden tests)?  The grader's own
 * realpath, not the compiler's reading, decides: the compiler may run as a
 * user who cannot read the kit at all. */
static bool inside_kit(const BuildConfig *cfg, const Build *b, const char *name)
{
    char root[PATH_MAX], path[PATH_MAX + 700], real[PATH_MAX], own[PATH_MAX];
    if (!realpath(cfg->root, root))
        return false;
    if (name[0] == '/')
        snprintf(path, sizeof path, "%s", name);
    else
        snprintf(path, sizeof path, "%s/src/%s", b->dir, name);
    if (!realpath(path, real) || !path_below(real, root))
        return false;
    /* The build's own folder holds copies (its raytracer.h), not files of
     * the kit, even where TMPDIR puts it inside the kit; another build's
     * folder there is the kit's. */
    return !(realpath(b->dir, own) && path_below(real, own));
}

typedef struct {
    const BuildConfig *cfg;
    const Build *b;
} KitJudge;

static const char *judge_kit_file(const char *name, void *ctx)
{
    const KitJudge *k = ctx;
    return inside_kit(k->cfg, k->b, name) ? "which is part of the grader" : NULL;
}

/* Before compiling: refuses a stage file (its n bytes of text, copied into
 * dir) that names to the preprocessor a file of the kit, a device, a pipe
 * or a system file (include_scan.h); 1 with a message, or 0. */
static int scan_includes(const BuildConfig *cfg, Build *b, const char *text, size_t n, const char *dir)
{
    char why[400];
    KitJudge kit = { cfg, b };
    int refused = include_scan_judged(text, n, dir, judge_kit_file, &kit, why, sizeof why);
    if (refused)
        appendf(&b->messages, "refused: %s\n", why);
    return refused;
}

/* After compiling: where the compiler says it looked (includes through
 * macros too).  Returns 0, or 1 with a message. */
static int check_dependencies(const BuildConfig *cfg, Build *b, const char *depfile)
{
    FILE *f = fopen(depfile, "r");
    if (!f)
        return 0;
    char word[4096];                /* PATH_MAX is only 1024 on macOS */
    int status = 0;
    while (fscanf(f, "%4095s", word) == 1) {
        if (strchr(word, ':') || strcmp(word, "\\") == 0)
            continue;
        if (inside_kit(cfg, b, word)) {
            appendf(&b->messages, "refused: the file includes a file of the grader: %s\n", word);
            status = 1;
        }
    }
    fclose(f);
    return status;
}

/* The shared-object way (cfg->load): links the student's object alone
 * into b->dir/src/student.so and copies the prebuilt runner for the part.
 * Whether the object links as a whole program would (a symbol defined
 * nowhere, main or another part's function defined again) is known only
 * once the runner has loaded it: the build is left unchecked, and the
 * part's first run tells (build_link_verdict), or build_check.  Returns as
 * build_program. */
static int load_program(const BuildConfig *cfg, Build *b, int part, const char *ofile, char *err,
                        size_t errlen)
{
    char so[PATH_MAX], out[700];
    snprintf(so, sizeof so, "%s/src/student.so", b->dir);
    snprintf(out, sizeof out, "%s/student.so", b->rundir);
    char *so_argv[] = { (char *)cfg->cc, "-shared", "-nostdlib", "-Wl,-Bsymbolic", (char *)ofile,
                        "-lgcc", "-o", out, NULL };
    const char *keep[] = { "student.so", NULL };
    int rc = run_cc(cfg, b, so_argv, keep, &b->cpu_link, err, errlen);
    if (rc != 0)
        return rc < 0 ? -1 : 0;
    if (access(so, R_OK) != 0) {
        snprintf(err, errlen, "the linker wrote no student.so");
        return -1;
    }
    char from[PATH_MAX];
    snprintf(from, sizeof from, "%s/runner_part%s", cfg->objdir, part_label(part));
    if (copy_file(from, b->runner, 16 << 20, err, errlen) || chmod(b->runner, 0755))
        return -1;
    snprintf(b->object, sizeof b->object, "%s/src/student.so", b->dir);
    b->ok = true;
    b->unchecked = true;
    return 0;
}

int build_link_verdict(Build *b, const SandboxResult *res)
{
    /* Only the runner's own verdict counts: code run as the object loads
     * (a constructor) may exit or crash first, and then the tests show it. */
    if (res->exit_code == 4 && res->answer && strncmp(res->answer, "link-error ", 11) == 0) {
        char *nl = strchr(res->answer, '\n');
        if (nl)
            *nl = '\0';
        appendf(&b->messages, "the linker: %s\n", res->answer + 11);
        b->ok = false;
        b->unchecked = false;
        return 1;
    }
    if (res->exit_code == 0 && !res->signal && !res->timed_out)
        b->unchecked = false;
    return 0;
}

int build_check(Build *b, char *err, size_t errlen)
{
    char *check_argv[] = { b->runner, "--check", b->object, NULL };
    SandboxSpec spec = {
        .argv = check_argv, .workdir = b->rundir, .visible = b->visible, .timeout = LOAD_SECONDS,
        .answer_max = 1024, .output_max = 4096, .memory_mb = LOAD_MEMORY_MB, .max_procs = 0,
        .max_file_mb = 0, .init = true,
    };
    SandboxResult res;
    if (sandbox_run(&spec, &res, err, errlen) != 0)
        return -1;
    b->cpu_link += res.cpu_seconds;
    build_link_verdict(b, &res);
    b->unchecked = false;
    sandbox_result_free(&res);
    return 0;
}

/* Compiles the stage file copied into the build (b->dir/src/<stage>.c) to
 * <stage>.o beside it.  defines: NULL, or up to four -D options.  Returns 0 when
 * there is an object, 1 when the student's file did not build (b->messages
 * says why), -1 when the grader could not run the compiler (err). */
static int compile_stage(const BuildConfig *cfg, Build *b, const char *stage, bool load,
                         char *const *defines, char *err, size_t errlen)
{
    char cfile[80], ofile[80], dfile[80], opath[PATH_MAX + 700], dpath[PATH_MAX + 700], oout[700],
         dout[700];
    snprintf(cfile, sizeof cfile, "%s.c", stage);
    snprintf(ofile, sizeof ofile, "%s.o", stage);
    snprintf(dfile, sizeof dfile, "%s.d", stage);
    snprintf(opath, sizeof opath, "%s/src/%s", b->dir, ofile);
    snprintf(dpath, sizeof dpath, "%s/src/%s", b->dir, dfile);
    snprintf(oout, sizeof oout, "%s/%s", b->rundir, ofile);
    snprintf(dout, sizeof dout, "%s/%s", b->rundir, dfile);
    char *argv[20] = { (char *)cfg->cc, "-std=c11", "-O1", "-ffp-contract=off", "-Wall", "-Wextra",
                       "-I.", "-MD", "-MF", dout, "-c", cfile, "-o", oout };
    int argc = 14;
    if (load)
        argv[argc++] = "-fPIC";
    for (int k = 0; defines && defines[k] && k < 4; k++)
        argv[argc++] = defines[k];
    argv[argc] = NULL;
    const char *keep[] = { ofile, dfile, NULL };
    int rc = run_cc(cfg, b, argv, keep, &b->cpu_compile, err, errlen);
    if (rc == 0 && access(opath, R_OK) != 0) {
        snprintf(err, errlen, "the compiler wrote no %s", ofile);
        rc = -1;
    }
    if (rc == 0 && check_dependencies(cfg, b, dpath))
        rc = 1;
    return rc;
}

enum { APART_MAX = 4 };

/* A helper defined, not static, in two of the student's stage files that
 * one program links (Part 3b with the student's own Part 3a, in the
 * student kit): the linker refuses it, where the instructor's grader,
 * which links each stage file with the reference's others, does not, and
 * tests/grader/README.md promises full marks.  Its output is what b->messages holds
 * from before (the length before the link).  Each of the files after the
 * first that defines such a name is compiled again with the name made its
 * own (-Dname=name_in_<stage>), the program (link) linked again, and the
 * linker's words give way to make render's: write static.  Returns as
 * run_cc: 1 (the link's failure stands) unless every name the linker says
 * is defined twice is a helper that two files, compiled here, define. */
static int link_apart(const BuildConfig *cfg, Build *b, const char *submission, const int *parts,
                      int nparts, char **link, size_t before, char *err, size_t errlen)
{
    char names[APART_MAX][LINKMSG_NAME_MAX];
    int nnames = linkmsg_duplicate(b->messages + before, names, APART_MAX);
    char *texts[NPARTS] = { NULL };
    bool apart = nnames > 0;
    for (int k = 0; k < nparts; k++)
        texts[k] = read_stage(submission, parts[k]);
    char defs[NPARTS][APART_MAX][2 * LINKMSG_NAME_MAX + 40] = { { { 0 } } };
    char *defines[NPARTS][APART_MAX + 1];
    char said[2048] = "";
    for (int q = 0; q < nnames && apart; q++) {
        int first = -1;
        apart = !linkmsg_stage_of(names[q]);            /* a helper, not the contract's */
        for (int k = 0; k < nparts && apart; k++)
            if (texts[k] && linkmsg_defines(texts[k], names[q]))
                first = first < 0 ? k : first;
        apart = apart && first >= 0;
        char list[512] = "";
        for (int k = 0; k < nparts && apart; k++) {
            if (!texts[k] || !linkmsg_defines(texts[k], names[q]))
                continue;
            size_t n = strlen(list);
            snprintf(list + n, sizeof list - n, "%s%s.c", n ? " and " : "", stage_names[parts[k]]);
            if (k != first)
                snprintf(defs[k][q], sizeof defs[k][q], "-D%s=%s_in_%s", names[q], names[q],
                         stage_names[parts[k]]);
        }
        apart = apart && strstr(list, " and ");
        size_t n = strlen(said);
        snprintf(said + n, sizeof said - n, "%s is defined in %s: make render links your stage files "
                 "into one program, where a function may be defined only once, and stops there. Write "
                 "static in front of each definition of %s (graded here with each file's %s its own).\n",
                 names[q], list, names[q], names[q]);
    }
    for (int k = 0; k < nparts; k++)
        free(texts[k]);
    int rc = 1;
    for (int k = 0; k < nparts && apart && rc != -1; k++) {
        int nd = 0;
        for (int q = 0; q < nnames; q++)
            if (defs[k][q][0])
                defines[k][nd++] = defs[k][q];
        defines[k][nd] = NULL;
        char cpath[PATH_MAX + 700];
        snprintf(cpath, sizeof cpath, "%s/%s.c", b->src, stage_names[parts[k]]);
        if (nd > 0 && (access(cpath, R_OK) != 0 ||
                       (rc = compile_stage(cfg, b, stage_names[parts[k]], false, defines[k], err,
                                           errlen)) != 0))
            apart = false;
    }
    if (!apart)
        return rc < 0 ? -1 : 1;
    size_t failed = strlen(b->messages);
    const char *keep[] = { "runner", NULL };
    rc = run_cc(cfg, b, link, keep, &b->cpu_link, err, errlen);
    if (rc == 0) {
        b->messages[before] = '\0';                    /* the first link's words */
        appendf(&b->messages, "%s", said);
    } else if (rc > 0) {
        b->messages[failed] = '\0';                    /* the first link's stand */
    }
    return rc;
}

/* b's folders: b->dir, its src (what the runs may read) and rundir. */
static int make_build_dirs(Build *b, char *err, size_t errlen)
{
    memset(b, 0, sizeof *b);
    b->messages = calloc(1, 1);
    if (build_tempdir(b->dir, sizeof b->dir, err, errlen))
        return -1;
    /* src holds what the runs may read, and only the grader writes there;
     * each run works in a fresh folder of its own, rundir (sandbox.h). */
    snprintf(b->src, sizeof b->src, "%s/src", b->dir);
    snprintf(b->rundir, sizeof b->rundir, "%s/run", b->dir);
    snprintf(b->runner, sizeof b->runner, "%s/src/runner", b->dir);
    b->visible[0] = b->src;
    b->visible[1] = NULL;
    const char *src = b->src;
    /* src: the run's user may read it (its group), and no one else: in the
     * fallback jail the runs of another submission graded at once run as
     * another user. */
    uid_t uid;
    gid_t gid;
    sandbox_ids(&uid, &gid);
    if (chmod(b->dir, 0711) || mkdir(src, 0750) || chmod(src, 0750) ||
        (sandbox_drops_privileges() && chown(src, 0, gid))) {
        snprintf(err, errlen, "%s: %s", b->dir, strerror(errno));
        return -1;
    }
    return 0;
}

/* The headers the students see, into src.  In the student kit, as the
 * kit shipped them (tests/grader/shipped): what a student adds to
 * labs/raytracer.h, the instructor's grader will not have, so this one
 * does not either (grade_main.c warns of the change). */
static int copy_headers(const BuildConfig *cfg, const char *src, char *err, size_t errlen)
{
    static const char *headers[] = { "raytracer.h", "vec3.h" };
    for (int k = 0; k < 2; k++) {
        char from[PATH_MAX], to[PATH_MAX + 700];
        snprintf(from, sizeof from, "%s/tests/grader/shipped/%s", cfg->root, headers[k]);
        if (access(from, R_OK) != 0)
            snprintf(from, sizeof from, "%s/labs/%s", cfg->root, headers[k]);
        snprintf(to, sizeof to, "%s/%s", src, headers[k]);
        if (copy_file(from, to, BUILD_SOURCE_MAX, err, errlen))
            return -1;
    }
    return 0;
}

/* Copies a submission's stage file into src, checks it and compiles it.
 * Returns 1 when it built, 0 when it did not (b says why), -1 when the
 * grader could not do its job (err says why). */
static int build_stage(const BuildConfig *cfg, Build *b, const char *submission, const char *stage,
                       bool load, char *err, size_t errlen)
{
    const char *src = b->src;
    char path[PATH_MAX], to[PATH_MAX + 700], cfile[80], cerr[512];
    snprintf(cfile, sizeof cfile, "%s.c", stage);
    snprintf(path, sizeof path, "%s/%s.c", submission, stage);
    snprintf(to, sizeof to, "%s/%s.c", src, stage);
    int in = build_open_stage(path);
    if (in < 0 && errno == ENOENT)
        return missing_stage(b, submission, stage, cfile);
    if (in < 0 && (errno == ELOOP || errno == EINVAL))
        return not_compiled(b, errno == ELOOP ? "refused: a symbolic link, not a file (hand in the file "
                                                "itself): " : "refused: not a regular file: ", cfile);
    if (in < 0) {           /* unreadable, say: as the system puts it */
        snprintf(cerr, sizeof cerr, "%s: %s", cfile, strerror(errno));
        return not_compiled(b, "cannot read ", cerr);
    }
    struct stat st;
    if (fstat(in, &st) == 0 && st.st_size > BUILD_SOURCE_MAX) {
        close(in);
        snprintf(cerr, sizeof cerr, "%s is %lld bytes; a stage file may be at most %d (1 MiB)",
                 cfile, (long long)st.st_size, BUILD_SOURCE_MAX);
        return not_compiled(b, "refused: too large: ", cerr);
    }
    if (copy_fd(in, path, to, BUILD_SOURCE_MAX, cerr, sizeof cerr))
        return not_compiled(b, cerr, "");
    /* The copy, read once for what must not reach the compiler. */
    size_t n = 0;
    char *text = kit_load_file(to, BUILD_SOURCE_MAX, &n);
    if (!text) {
        snprintf(cerr, sizeof cerr, "%s: its copy cannot be read back", cfile);
        return not_compiled(b, "cannot read ", cerr);
    }
    bool utf16 = lookalike_utf16(text, n), refused = !utf16 && scan_includes(cfg, b, text, n, src);
    if (utf16) {
        free(text);
        snprintf(cerr, sizeof cerr, "%s " LOOKALIKE_UTF16, cfile);
        return not_compiled(b, "refused: ", cerr);
    }
    if (refused) {
        free(text);
        b->refused = true;          /* scan_includes said why */
        return 0;
    }
    int rc = compile_stage(cfg, b, stage, load, NULL, err, errlen);
    if (rc > 0) {
        explain_lookalikes(b, text, n, cfile);
        explain_own_headers(b, text, n, submission, cfile);
    }
    free(text);
    return rc < 0 ? -1 : rc == 0;
}

/* In the instructor's kit: the reference for every part but skip, added
 * to the link. */
static int add_references(const BuildConfig *cfg, const char *src, int skip, char **link, int *nlink,
                          char (*names)[96], char *err, size_t errlen)
{
    char path[PATH_MAX], to[PATH_MAX + 700];
    for (int p = 0; p < NPARTS; p++) {
        if (p == skip)
            continue;
        snprintf(path, sizeof path, "%s/ref_%s.o", cfg->objdir, stage_names[p]);
        snprintf(names[*nlink], sizeof names[*nlink], "ref_%d.o", p);
        snprintf(to, sizeof to, "%s/%s", src, names[*nlink]);
        if (copy_file(path, to, 16 << 20, err, errlen))
            return -1;
        link[*nlink] = names[*nlink];
        (*nlink)++;
    }
    return 0;
}

/* Builds b->dir/src/runner from the prebuilt harness object harness (a file
 * name in cfg->objdir), the submission's stage files of the nparts parts
 * listed (each compiled here, or copied from the directory kept when it
 * holds that stage's object from an earlier build of the same files), and,
 * when skip >= 0 and cfg has them, the reference objects of every part but
 * skip; with cfg->load and one stage file of one part, that file as a
 * shared object and the part's prebuilt runner instead (load_program).
 * Returns 0 when the
 * grader could do its job (b->ok says whether the student's code built),
 * -1 when it could not (err says why). */
static int build_program(const BuildConfig *cfg, const char *harness, const int *parts, int nparts,
                         int skip, const char *kept, const char *submission, Build *b,
                         char *err, size_t errlen)
{
    /* One student file of a part's program, on Linux: a shared object. */
    bool load = cfg->load && skip >= 0 && nparts == 1;
    if (make_build_dirs(b, err, errlen) || copy_headers(cfg, b->src, err, errlen))
        return -1;
    const char *src = b->src;
    char path[PATH_MAX], to[PATH_MAX + 700];
    snprintf(path, sizeof path, "%s/%s", cfg->objdir, harness);
    snprintf(to, sizeof to, "%s/harness.o", src);
    if (!load && copy_file(path, to, 16 << 20, err, errlen))    /* loaded: the runner has it */
        return -1;

    char *link[16];
    int nlink = 0;
    static char names[16][96];
    link[nlink++] = (char *)cfg->cc;
    link[nlink++] = "harness.o";
    for (int k = 0; k < nparts; k++) {
        const char *stage = stage_names[parts[k]];
        char ofile[80], cerr[512];
        snprintf(ofile, sizeof ofile, "%s.o", stage);
        snprintf(path, sizeof path, "%s/%s", kept ? kept : "", ofile);
        snprintf(to, sizeof to, "%s/%s", src, ofile);
        bool from_kept = kept && access(path, R_OK) == 0 &&
                         copy_file(path, to, 64 << 20, cerr, sizeof cerr) == 0;
        int rc = from_kept ? 1 : build_stage(cfg, b, submission, stage, load, err, errlen);
        if (rc <= 0)
            return rc;
        snprintf(names[nlink], sizeof names[nlink], "%s", ofile);
        link[nlink] = names[nlink];
        nlink++;
    }
    if (load)
        return load_program(cfg, b, skip, names[nlink - 1], err, errlen);
    /* In the instructor's kit: the reference for every other part. */
    if (skip >= 0 && cfg->reference && add_references(cfg, src, skip, link, &nlink, names, err, errlen))
        return -1;
    char out[700];
    snprintf(out, sizeof out, "%s/runner", b->rundir);
    link[nlink++] = "-lm";
    link[nlink++] = "-o";
    link[nlink++] = out;
    link[nlink] = NULL;
    const char *keep[] = { "runner", NULL };
    size_t before = strlen(b->messages);
    int rc = run_cc(cfg, b, link, keep, &b->cpu_link, err, errlen);
    if (rc > 0 && nparts > 1)
        rc = link_apart(cfg, b, submission, parts, nparts, link, before, err, errlen);
    if (rc < 0)
        return -1;
    b->ok = rc == 0 && chmod(b->runner, 0755) == 0;
    return 0;
}

int build_part(const BuildConfig *cfg, int part, const char *submission, Build *b,
               char *err, size_t errlen)
{
    /* The student's files: this part's, and in the student kit Part 3a for 3b. */
    int parts[2] = { part, PART3A };
    int nparts = part == PART3B && !cfg->reference ? 2 : 1;
    char harness[32];
    snprintf(harness, sizeof harness, "harness_part%s.o", part_label(part));
    return build_program(cfg, harness, parts, nparts, part, NULL, submission, b, err, errlen);
}

int build_render(const BuildConfig *cfg, const char *submission, const char *kept, Build *b,
                 char *err, size_t errlen)
{
    static const int core[NCORE_PARTS] = { PART1, PART2, PART3A, PART3B };
    return build_program(cfg, "harness_render.o", core, NCORE_PARTS, -1, kept, submission, b,
                         err, errlen);
}

void build_keep_objects(const Build *b, const char *dir)
{
    for (int p = 0; p < NPARTS; p++) {
        char from[PATH_MAX], to[PATH_MAX], why[256];
        snprintf(from, sizeof from, "%s/src/%s.o", b->dir, stage_names[p]);
        snprintf(to, sizeof to, "%s/%s.o", dir, stage_names[p]);
        if (access(from, R_OK) == 0 && access(to, F_OK) != 0)
            copy_file(from, to, 64 << 20, why, sizeof why);
    }
}

void build_remove(Build *b)
{
    if (b->dir[0])
        jail_remove_tree(b->dir);
    free(b->messages);
    b->messages = NULL;
    b->dir[0] = '\0';
}
