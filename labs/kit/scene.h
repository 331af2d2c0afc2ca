/*
 * scene.h - reading a scene file.
 *
 * The format, its defaults and what is refused: handouts/overview.md, "The
 * scenes" (the largest side is IMAGE_MAX_SIDE).  Numbers may also be C hex
 * floats.
 */
#ifndef KIT_SCENE_H
#define KIT_SCENE_H

#include <stddef.h>
#include "../raytracer.h"

#define SCENE_MAX_SPHERES   100000
#define SCENE_MAX_PLANES    100000
#define SCENE_MAX_TRIANGLES 1000000

/* The guard: a sphere kept just past a scene's last one, in
 * spheres[nspheres] (not counted in nspheres), by scene_load and by the
 * grader's harness.  Code that reads one sphere too many (a loop to
 * k <= nspheres) meets it wherever a ray hits nothing else, around
 * everything, and draws its colour, a magenta no scene of the kit uses,
 * where the background should be; the grader knows the colour. */
#define SCENE_GUARD_RADIUS 1e9
#define SCENE_GUARD_RED    (127.0 / 128)
#define SCENE_GUARD_GREEN  (1.0 / 128)
#define SCENE_GUARD_BLUE   (127.0 / 128)

static inline Sphere scene_guard_sphere(void)
{
    Sphere s = { vec3(0, 0, 0), SCENE_GUARD_RADIUS, vec3(SCENE_GUARD_RED, SCENE_GUARD_GREEN, SCENE_GUARD_BLUE) };
    return s;
}

/* Loads path into scene (eye at the origin).  Returns 0, or -1 with a
 * message "path:line: reason" (or "path: reason") in err.  On failure the
 * scene holds nothing that needs freeing. */
int scene_load(Scene *scene, const char *path, char *err, size_t errlen);

/* The same, from a string already in memory; name is used in messages and
 * its directory for the paths of meshes. */
int scene_parse(Scene *scene, const char *text, const char *name, char *err, size_t errlen);

void scene_free(Scene *scene);

#endif
