/* Self-test of the grader: hostile-ignore-alarm. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <signal.h>
#include <unistd.h>

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    signal(SIGALRM, SIG_IGN);
    signal(SIGTERM, SIG_IGN);
    signal(SIGINT, SIG_IGN);
    alarm(0);
    for (;;)
        pause();
    *w = *h = fov_degrees + aspect + d;
}
