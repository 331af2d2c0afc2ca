/* A PNG file, as `make compare` reads a student's picture (labs/kit/png.c). */
#include "fuzz.h"
#include "../../labs/kit/png.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Image img;
    char err[512];
    if (png_decode(data, size, &img, err, sizeof err) == 0)
        image_free(&img);
    return 0;
}
