/* A weights file (tests/grader/config.c), as an instructor edits
 * tests/weights.conf. */
#include "fuzz.h"
#include "../grader/config.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(data, size, "weights.conf");
    GradeConfig cfg;
    char err[512];
    config_read(&cfg, path, err, sizeof err);
    return 0;
}
