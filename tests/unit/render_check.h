/*
 * render_check.h - a shipped scene loaded, and a scene rendered, for the
 * unit tests that render (test_render, test_bvh).  Include it after check.h.
 */
#ifndef RENDER_CHECK_H
#define RENDER_CHECK_H

#include "../../labs/kit/render.h"
#include "../../labs/kit/scene.h"

/* Loads the scene at path into scene, at nx x ny pixels (at the file's
 * size when nx is 0).  Returns 0, or -1 after a failed check. */
static inline int load_scene(Scene *scene, const char *path, int nx, int ny)
{
    char err[512];
    int status = scene_load(scene, path, err, sizeof err);
    CHECK_MSG(status == 0, "%s", err);
    if (status != 0)
        return -1;
    if (nx) {
        scene->nx = nx;
        scene->ny = ny;
    }
    return 0;
}

/* Renders scene with the hierarchy as asked, on threads threads, into a
 * fresh img, its stats in *stats unless that is NULL.  Returns 0, or -1
 * after a failed check (img is then empty). */
static inline int render_as(const Scene *scene, RenderHierarchy hierarchy, int threads, Image *img,
                            RenderStats *stats)
{
    char err[256] = "";
    RenderStats unused;
    if (image_alloc(img, scene->nx, scene->ny, err, sizeof err) < 0) {
        CHECK_MSG(0, "image_alloc: %s", err);
        return -1;
    }
    RenderOptions opt = { threads, false, hierarchy, { 0, 0 } };
    int status = render_scene(scene, img, &opt, stats ? stats : &unused, err, sizeof err);
    CHECK_MSG(status == 0, "render_scene returned %d: %s", status, err);
    if (status != 0) {
        image_free(img);
        return -1;
    }
    return 0;
}

#endif
