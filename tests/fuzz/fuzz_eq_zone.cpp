// libFuzzer target: whole EverQuest zones (wld/eq/eq_zone_reader.h): a PFS archive, its WLD,
// meshes, materials, textures (DDS, BMP) and VISLISTs into a zone.
#include "tests/fuzz/fuzz_support.h"
#include "wld/eq/eq_zone_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    fuzz::accepts([&] { fuzz::check_zone(eq::load_eq_zone(fuzz::as_bytes(data, size), "fuzz.s3d")); });
    return 0;
}
