/* Part 1 right, and every input with its answer left behind for the next
 * run: as folder names where anyone may write (a course's shared folder,
 * @SHARED@, among them), and in a System V shared memory segment
 * (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include "raytracer.h"
#include <stdio.h>
#include <string.h>
#include <sys/ipc.h>
#include <sys/shm.h>
#include <sys/stat.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
    static const char *const places[] = { "/tmp", "/var/tmp", "/dev/shm", "@SHARED@", "." };
    char name[256];
    for (int k = 0; k < 5; k++) {
        snprintf(name, sizeof name, "%s/rtleak_%a_%a_%a_%a_%a", places[k], fov_degrees, aspect, d, *w, *h);
        mkdir(name, 0777);
    }
    int id = shmget(0x52544a4c, 1 << 16, IPC_CREAT | 0666);
    char *table = id >= 0 ? shmat(id, NULL, 0) : NULL;
    if (table && table != (char *)-1) {
        size_t used = strnlen(table, 1 << 16);
        snprintf(table + used, (1 << 16) - used, "%a %a %a %a %a\n", fov_degrees, aspect, d, *w, *h);
        shmdt(table);
    }
}
