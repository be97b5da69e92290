// libFuzzer target: Quake BSP 29 files (wld/quake/bsp29_reader.h) into a zone.
#include "tests/fuzz/fuzz_support.h"
#include "wld/quake/bsp29_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    fuzz::accepts([&] { fuzz::check_zone(quake::load_bsp29(fuzz::as_bytes(data, size), "fuzz.bsp")); });
    return 0;
}
