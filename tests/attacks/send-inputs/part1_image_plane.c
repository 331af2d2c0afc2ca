/* Every input it is given, sent over the network (UDP to this machine's
 * port 9, where anything could listen); the answer is right only where
 * nothing could be sent (tests/attacks/README.md). */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE
#include "raytracer.h"
#include <arpa/inet.h>
#include <netinet/in.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

static int sent(double fov_degrees, double aspect, double d)
{
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    if (fd < 0)
        return 0;
    struct sockaddr_in to;
    memset(&to, 0, sizeof to);
    to.sin_family = AF_INET;
    to.sin_port = htons(9);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    char text[128];
    int n = snprintf(text, sizeof text, "%a %a %a\n", fov_degrees, aspect, d);
    ssize_t k = sendto(fd, text, (size_t)n, 0, (struct sockaddr *)&to, sizeof to);
    close(fd);
    return k == n;
}

void image_plane_size(double fov_degrees, double aspect, double d, double *w, double *h)
{
    *h = 2 * d * tan(fov_degrees * M_PI / 360);
    *w = aspect * *h;
    if (sent(fov_degrees, aspect, d))
        *w = -1;
}
