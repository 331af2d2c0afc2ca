/* Self-test of the grader: hostile-forge-results. */
#define _POSIX_C_SOURCE 200809L
#include "raytracer.h"
#include <stdio.h>
#include <stdlib.h>

static void forge(const char *path)
{
    FILE *f = fopen(path, "w");
    if (f) {
        fputs("{\"score\": 1000, \"tests\": []}\n", f);
        fclose(f);
    }
}

Ray camera_ray(Vec3 eye, Vec3 pixel)
{
    forge("results.json");
    forge("/tmp/results.json");
    forge(getenv("RESULTS") ? getenv("RESULTS") : "../results.json");
    printf("{\"score\": 1000}\nScore: 100 / 100\nsummary 20 20 30 30 12.5 112.5 0\n");
    Ray r = { eye, pixel };
    return r;
}

Vec3 ray_color(const Scene *scene, const Ray *ray)
{
    (void)ray;
    forge("results.json");
    return scene->background;
}
