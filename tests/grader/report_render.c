/*
 * report_render.c - the report page's pictures of a scene: the
 * submission's render, drawn in the sandbox by a program built from its
 * four core stage files and harness_render.c, and the reference's render,
 * read from a PNG file (see report.h).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "report.h"
#include "build.h"
#include "sandbox.h"
#include "kit/png.h"
#include "kit/savefile.h"
#include "kit/scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The largest reference file whose bytes are kept; a larger one (or one
 * that is not a PNG) is read by image_read and encoded anew. */
#define REFERENCE_PNG_MAX ((size_t)64 << 20)
/* The render's memory: a test's (grade.c), with room for the picture. */
#define REPORT_RENDER_MEMORY_MB 64

/* The harness's input: the scene's size, view and spheres (hex floats, so
 * that the child reads exactly the scene's numbers).  malloc'd, or NULL. */
static char *scene_input(const Scene *s, size_t *len)
{
    char *t = NULL;
    appendf(&t, "render %d %d\nfov %a d %a\nbackground %a %a %a\nspheres %d\n", s->nx, s->ny,
            s->fov_degrees, s->d, s->background.x, s->background.y, s->background.z, s->nspheres);
    for (int k = 0; k < s->nspheres; k++) {
        const Sphere *sp = &s->spheres[k];
        appendf(&t, "%a %a %a %a %a %a %a\n", sp->center.x, sp->center.y, sp->center.z, sp->radius,
                sp->color.x, sp->color.y, sp->color.z);
    }
    *len = t ? strlen(t) : 0;
    return t;
}

/* Keeps the first lines of text (the compiler's messages) in note. */
static void note_text(char *note, size_t len, const char *head, const char *text)
{
    snprintf(note, len, "%s%s", head, text ? text : "");
    size_t n = strlen(note);
    if (n + 1 >= len && len > 40)
        snprintf(note + len - 40, 40, "\n[... more messages cut]\n");
}

/* Renders scene with the submission's code into rr->sub.  Returns 0 (with
 * have_sub telling whether it worked, and sub_note why not), or -1 when the
 * grader itself failed (err). */
static int render_submission(const ReportRenderOptions *o, const Scene *scene, ReportRenders *rr,
                             char *err, size_t errlen)
{
    Build b;
    if (build_render(o->build, o->submission, o->kept_objects, &b, err, errlen) != 0) {
        build_remove(&b);
        return -1;
    }
    if (!b.ok) {
        note_text(rr->sub_note, sizeof rr->sub_note,
                  "Your code could not be built into the renderer, so there is no picture "
                  "of it (it needs all four files of Parts 1 to 3b):\n", b.messages);
        build_remove(&b);
        return 0;
    }
    size_t len = 0;
    char *input = scene_input(scene, &len);
    size_t want = (size_t)scene->nx * (size_t)scene->ny * 3;
    char *argv[] = { b.runner, NULL };
    /* A test's limits, as tests/grader/README.md says, and its jail. */
    SandboxSpec spec = {
        .argv = argv, .workdir = b.rundir, .visible = b.visible, .input = input, .input_len = len,
        .timeout = o->timeout, .answer_max = want, .output_max = 4096,
        .memory_mb = REPORT_RENDER_MEMORY_MB, .max_procs = 0, .max_file_mb = 0, .init = true,
    };
    SandboxResult res;
    if (!input || sandbox_run(&spec, &res, err, errlen) != 0) {
        if (!input)
            snprintf(err, errlen, "out of memory");
        free(input);
        build_remove(&b);
        return -1;
    }
    free(input);
    build_remove(&b);
    if (res.timed_out) {
        snprintf(rr->sub_note, sizeof rr->sub_note, "Your code did not finish drawing the %dx%d "
                 "picture within %g s (the limit of one test), so there is no picture of it.",
                 scene->nx, scene->ny, o->timeout);
    } else if (res.signal) {
        snprintf(rr->sub_note, sizeof rr->sub_note, "Your code crashed (signal %d: %s) while "
                 "drawing the picture, so there is none.", res.signal, strsignal(res.signal));
    } else if (res.exit_code != 0 || res.answer_len != want) {
        snprintf(rr->sub_note, sizeof rr->sub_note, "Your code stopped (exit status %d) before "
                 "the picture was drawn, so there is none.", res.exit_code);
    } else {
        /* The answer is the picture's pixels, row by row: it becomes the
         * image, rather than a copy made in fresh memory. */
        rr->sub = (Image){ scene->nx, scene->ny, (unsigned char *)res.answer };
        res.answer = NULL;
        rr->have_sub = true;
    }
    sandbox_result_free(&res);
    return 0;
}

int report_render(const ReportRenderOptions *o, ReportRenders *rr, char *err, size_t errlen)
{
    memset(rr, 0, sizeof *rr);
    double start = sandbox_now();
    const char *slash = strrchr(o->scene, '/');
    const char *base = slash ? slash + 1 : o->scene;
    size_t stem = strcspn(base, ".");
    snprintf(rr->scene, sizeof rr->scene, "%.*s", (int)(stem < 60 ? stem : 60), base);

    Scene scene;
    char why[512];
    if (scene_load(&scene, o->scene, why, sizeof why) < 0) {
        snprintf(rr->sub_note, sizeof rr->sub_note, "The scene could not be read: %s", why);
        snprintf(rr->ref_note, sizeof rr->ref_note, "The scene could not be read: %.400s", why);
        return 0;
    }
    /* The reference: the first of the files named that can be read.  A
     * PNG's bytes are kept, for the page to show as they are rather than
     * encode the same pixels again. */
    for (int k = 0; k < 2 && !rr->have_ref; k++) {
        const char *path = o->reference[k];
        if (!path || access(path, R_OK) != 0)
            continue;
        free(rr->ref_png);
        rr->ref_png = kit_load_file(path, REFERENCE_PNG_MAX, &rr->ref_png_len);
        if (!rr->ref_png || !png_has_signature(rr->ref_png, rr->ref_png_len) ||
            png_decode(rr->ref_png, rr->ref_png_len, &rr->ref.width, &rr->ref.height, &rr->ref.rgb,
                       why, sizeof why) != 0) {
            free(rr->ref_png);          /* image_read says why, naming the file */
            rr->ref_png = NULL;
        }
        if (!rr->ref_png && image_read(&rr->ref, path, why, sizeof why) < 0) {
            snprintf(rr->ref_note, sizeof rr->ref_note, "The reference picture could not be read: %.400s", why);
        } else if (rr->ref.width != scene.nx || rr->ref.height != scene.ny) {
            snprintf(rr->ref_note, sizeof rr->ref_note, "The reference picture %s is %dx%d, not the "
                     "scene's %dx%d.", path, rr->ref.width, rr->ref.height, scene.nx, scene.ny);
            image_free(&rr->ref);
        } else {
            rr->have_ref = true;
            rr->ref_note[0] = '\0';
        }
    }
    if (!rr->have_ref) {
        free(rr->ref_png);
        rr->ref_png = NULL;
    }
    if (!rr->have_ref && !rr->ref_note[0])
        snprintf(rr->ref_note, sizeof rr->ref_note, "There is no reference picture of %s here.",
                 rr->scene);
    int status = render_submission(o, &scene, rr, err, errlen);
    scene_free(&scene);
    rr->seconds = sandbox_now() - start;
    return status;
}

void report_renders_free(ReportRenders *rr)
{
    if (rr->have_sub)
        image_free(&rr->sub);
    if (rr->have_ref)
        image_free(&rr->ref);
    free(rr->ref_png);
    memset(rr, 0, sizeof *rr);
}
