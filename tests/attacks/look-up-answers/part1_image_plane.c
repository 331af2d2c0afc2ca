/* Part 1 with no formula: it answers from what record-answers left behind,
 * and 0 where it finds nothing (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include "raytracer.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/shm.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    char key[200], found[256] = "";
    snprintf(key, sizeof key, "rtleak_%a_%a_%a_", fov_degrees, aspect, d);
    static const char *const places[] = { "/tmp", "/var/tmp", "/dev/shm", "@SHARED@" };
    for (int k = 0; k < 4 && !found[0]; k++) {
        DIR *dir = opendir(places[k]);
        struct dirent *e;
        while (dir && (e = readdir(dir)))
            if (strncmp(e->d_name, key, strlen(key)) == 0)
                snprintf(found, sizeof found, "%s", e->d_name + strlen(key));
        if (dir)
            closedir(dir);
    }
    *w = *h = 0;
    if (found[0]) {
        char *at = found;
        *w = strtod(at, &at);
        *h = strtod(at + 1, NULL);
        return;
    }
    int id = shmget(0x52544a4c, 0, 0);
    char *table = id >= 0 ? shmat(id, NULL, 0) : NULL;
    if (table && table != (char *)-1) {
        snprintf(key, sizeof key, "%a %a %a ", fov_degrees, aspect, d);
        char *line = strstr(table, key);
        if (line) {
            char *at = line + strlen(key);
            *w = strtod(at, &at);
            *h = strtod(at, NULL);
        }
        shmdt(table);
    }
}
