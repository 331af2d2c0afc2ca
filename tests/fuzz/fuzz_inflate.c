/* A deflate stream (labs/kit/zlib.c), the inside of every PNG, at most
 * 1 MiB out. */
#include "fuzz.h"
#include "../../labs/kit/zlib.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    KitBuf out;
    kit_buf_init(&out);
    size_t used = 0;
    char err[512];
    kit_inflate(data, size, (size_t)1 << 20, &out, &used, err, sizeof err);
    kit_buf_free(&out);
    return 0;
}
