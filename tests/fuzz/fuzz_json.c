/* JSON (tests/tools/json_read.c), as the kit's checks read results files. */
#include "fuzz.h"
#include "../tools/json_read.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    JsonValue v;
    char err[512];
    if (json_parse((const char *)data, size, &v, err, sizeof err) == 0)
        json_value_free(&v);
    return 0;
}
