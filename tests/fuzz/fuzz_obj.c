/* A Wavefront OBJ file, as a scene's mesh names one (labs/kit/obj.c). */
#include "fuzz.h"
#include "../../labs/kit/obj.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(data, size, "mesh.obj");
    Triangle *tris = NULL;
    int n = 0, cap = 0;
    char err[512];
    obj_load(path, 1.5, vec3(0, 0, -5), vec3(1, 1, 1), &tris, &n, &cap, 100000, err, sizeof err);
    free(tris);
    return 0;
}
