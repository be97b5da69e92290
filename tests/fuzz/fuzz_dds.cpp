// libFuzzer target: DDS textures (wld/eq/dds_decode.h). The decoder never throws: nullopt with a
// reason is its error report; a decoded image must be width * height RGBA texels.
#include "tests/fuzz/fuzz_support.h"
#include "wld/eq/dds_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    std::string why;
    if (const auto image = decode_dds(fuzz::as_bytes(data, size), &why))
        fuzz::fuzz_check(image->rgba.size() == size_t(image->width) * image->height * 4, "RGBA size");
    else
        fuzz::fuzz_check(!why.empty(), "a refusal says why");
    return 0;
}
