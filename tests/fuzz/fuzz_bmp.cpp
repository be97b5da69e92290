// libFuzzer target: BMP textures of EverQuest archives and OBJ materials (wld/eq/stb_image_io.h,
// Debian's stb_image underneath). nullopt is the decoder's error report.
#include "tests/fuzz/fuzz_support.h"
#include "wld/eq/stb_image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    if (const auto image = decode_bmp(fuzz::as_bytes(data, size)))
        fuzz::fuzz_check(image->rgba.size() == size_t(image->width) * image->height * 4, "RGBA size");
    return 0;
}
