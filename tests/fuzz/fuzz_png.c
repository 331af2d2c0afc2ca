/* A PNG file, as `make compare` reads a student's picture (labs/kit/png.c). */
#include "fuzz.h"
#include "../../labs/kit/png.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int width, height;
    unsigned char *rgb;
    char err[512];
    if (png_decode(data, size, &width, &height, &rgb, err, sizeof err) == 0)
        free(rgb);
    return 0;
}
