/* A picture file read by name (labs/kit/image.c): PPM, P3 or P6, or PNG. */
#include "fuzz.h"
#include "../../labs/kit/image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *path = fuzz_file(data, size, "picture.ppm");
    Image img;
    char err[512];
    if (image_read(&img, path, err, sizeof err) == 0)
        image_free(&img);
    return 0;
}
