/*
 * harness_load.c - see harness_load.h.  POSIX dlopen and dlsym.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (built only on Linux today) */
#include "harness_load.h"
#include "contract.h"

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

void (*load_image_plane_size)(double, double, double, double *, double *);
Vec3 (*load_pixel_coordinates)(int, int, int, int, double, double, double);
bool (*load_sphere_intersect)(const Sphere *, const Ray *, double *);
Ray (*load_camera_ray)(Vec3, Vec3);
Vec3 (*load_ray_color)(const Scene *, const Ray *);
bool (*load_plane_intersect)(const Plane *, const Ray *, double *);
bool (*load_triangle_intersect)(const Triangle *, const Ray *, double *);

/* The runner keeps libm whether or not its own code needs it: the
 * student's object finds tan, sqrt and the rest there. */
double (*volatile harness_keep_libm)(double) = tan;

static const char *const stages[] = { CONTRACT_STAGE_NAMES };
static const struct {
    const char *name;
    int part;                       /* counted from 0, as contract.h counts */
    void *slot;
} functions[] = {
#define ROW(function, part) { #function, part, &load_##function },
    CONTRACT_FUNCTIONS(ROW)
#undef ROW
};

/* dlerror's text without the object's path, which names a temporary
 * directory the student never saw. */
static void say_dlerror(char *why, size_t whylen)
{
    const char *e = dlerror();
    if (!e)
        e = "the object could not be loaded";
    const char *colon = strstr(e, ".so: ");
    const char *text = colon ? colon + 5 : e;
    /* In the words of the linker students run themselves. */
    if (strncmp(text, "undefined symbol: ", 18) == 0)
        snprintf(why, whylen, "undefined reference to `%s' (no file of the program defines it)", text + 18);
    else
        snprintf(why, whylen, "%s", text);
}

int harness_load(int part, bool refs, const char *path, char *why, size_t whylen)
{
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        say_dlerror(why, whylen);
        return -1;
    }
    if (dlsym(h, "main")) {
        snprintf(why, whylen, "multiple definition of `main': the program this part is graded with "
                              "has its own (so has make render's); remove yours, and test your code "
                              "in a file of its own");
        return -1;
    }
    for (size_t k = 0; k < sizeof functions / sizeof functions[0]; k++) {
        void *f = dlsym(h, functions[k].name);
        if (functions[k].part == part) {
            if (!f) {
                snprintf(why, whylen, "undefined reference to `%s'", functions[k].name);
                return -1;
            }
            memcpy(functions[k].slot, &f, sizeof f);
        } else if (f && refs) {
            snprintf(why, whylen, "multiple definition of `%s': it belongs in %s.c, which this "
                     "part is graded with; define it only there", functions[k].name,
                     stages[functions[k].part]);
            return -1;
        }
    }
    return 0;
}
