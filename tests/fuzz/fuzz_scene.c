/* A scene file (labs/kit/scene.c), as a student writes one; its meshes are
 * looked for beside labs/scenes/, where cracks.obj is. */
#include "fuzz.h"
#include "../../labs/kit/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = fuzz_text(data, size), err[512];
    Scene scene;
    if (scene_parse(&scene, text, "labs/scenes/fuzz.scene", err, sizeof err) == 0)
        scene_free(&scene);
    free(text);
    return 0;
}
