/*
 * build.h - compiling the program that runs one part's tests.
 *
 * The program for Part k is the harness for Part k, the submission's file
 * for Part k and, for the parts it may call, the reference (in the
 * instructor's kit) or the submission's own files (in the student kit).
 * It is built in a private temporary directory, by the compiler running in
 * the sandbox's jail (jail.h), from copies of the files it needs, which it
 * may only read, so that nothing else of the kit is within its reach.
 */
#ifndef BUILD_H
#define BUILD_H

#include <stdbool.h>
#include <stddef.h>

/* A stage file larger than this (1 MiB) is refused; make render's
 * lookalike scan (lookalike_main.c) reads no more either. */
#define BUILD_SOURCE_MAX (1 << 20)

typedef struct {
    const char *root;          /* the kit's root directory (absolute)          */
    const char *cc;            /* the compiler                                  */
    const char *objdir;        /* prebuilt harness_part<P>.o and, if any,
                                  the reference objects ref_<stage>.o          */
    bool reference;            /* reference objects exist for the other parts  */
    bool load;                 /* objdir has the prebuilt runners runner_part<P>
                                  (Linux): a part with one student file is
                                  built as a shared object they load       */
} BuildConfig;

typedef struct {
    char dir[512];             /* the temporary directory                       */
    char src[600];             /* dir/src: what the runs may read; only the
                                  grader writes there                          */
    const char *visible[2];    /* { src, NULL }: SandboxSpec.visible            */
    char runner[600];          /* the program, when ok                          */
    char object[600];          /* "" or the shared object it loads (its argument) */
    char rundir[600];          /* the working folder each run gets afresh       */
    bool ok;
    bool unchecked;            /* ok, but whether the object links is not
                                  known until the runner has loaded it once
                                  (build_link_verdict, build_check)         */
    char *messages;            /* the compiler's output (malloc'd, may be "")   */
    bool refused;              /* a file was not handed to the compiler (missing,
                                  unreadable, a link, a kit file included):
                                  messages are the grader's words           */
    double cpu_compile;        /* CPU seconds of the compiler's runs, compiling */
    double cpu_link;           /* and linking                                   */
} Build;

#include "grader.h"
#include "sandbox.h"

extern const char *const stage_names[NPARTS];   /* "part1_image_plane", ...  */

/* Builds the program for part from the submission directory.  Returns 0
 * when the grader could do its job (b->ok says whether the student's code
 * compiled), -1 when it could not (err says why). */
int build_part(const BuildConfig *cfg, int part, const char *submission, Build *b,
               char *err, size_t errlen);
void build_remove(Build *b);

/* After a build of part that did not link, for each function the linker
 * found undefined (up to three), adds to b->messages what the submission's
 * stage files show: a helper another stage file defines belongs in this
 * part's file too, as each part is graded with the reference's other
 * parts; a function of this part's contract defined in another stage file
 * belongs in this one; one this part's file does not define is named with
 * the functions the file does define. */
void build_explain_undefined(Build *b, const char *submission, int part);

/* After a build of part that did not compile or link, in the student kit
 * (whose tests/grader/shipped holds the kit's headers as shipped, which
 * the stage files are built with, as the instructor's grader builds them):
 * adds to b->messages which of labs/raytracer.h and labs/vec3.h the
 * student has changed, and that what the file uses from a change belongs
 * in the file. */
void build_explain_headers(const BuildConfig *cfg, Build *b, int part);

/* Whether the student kit at root (with tests/grader/shipped) has a labs/name
 * (raytracer.h or vec3.h) that is not as the kit shipped it; false in a
 * kit without tests/grader/shipped. */
bool build_header_changed(const char *root, const char *name);

/* An unchecked build's first run (res) tells whether its object links:
 * when the runner says it does not, b->ok becomes false with the linker's
 * message added, and 1 is returned; when the run ended cleanly, the object
 * loaded and b->unchecked becomes false.  Otherwise (a crash, a time out:
 * code run as the object loads may do that) the build stays unchecked. */
int build_link_verdict(Build *b, const SandboxResult *res);

/* Loads an unchecked build's object once (runner --check) and takes its
 * verdict; b->unchecked becomes false.  0, or -1 when the grader could not
 * run it (err says why). */
int build_check(Build *b, char *err, size_t errlen);

/* Builds the report page's render program: harness_render.o (which draws a
 * scene with Parts 1-3b) and the submission's four core stage files, those
 * whose objects the directory kept holds (build_keep_objects; kept may be
 * NULL) taken from there, the others compiled.  Returns as build_part. */
int build_render(const BuildConfig *cfg, const char *submission, const char *kept, Build *b,
                 char *err, size_t errlen);

/* Copies the student's stage objects of a build that succeeded into dir
 * (as <stage>.o, unless dir already has one), so that build_render need
 * not compile them again.  Failures only leave an object out. */
void build_keep_objects(const Build *b, const char *dir);

/* Makes a private temporary directory; 0 on success. */
int build_tempdir(char *dir, size_t len, char *err, size_t errlen);

#endif
