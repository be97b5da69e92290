// libFuzzer target: Quake BSP files of every variant (29, BSP2, 2PSB: wld/quake/bsp29_reader.h)
// into a zone; when one loads with a PVS, its ambient sound levels from that PVS and the file
// written back with them (ambient_sounds.h, bsp29_vis_writer.h) read the same hostile bytes again.
#include "tests/fuzz/fuzz_support.h"
#include "wld/quake/ambient_sounds.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/bsp29_vis_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    fuzz::accepts([&] {
        const auto bytes = fuzz::as_bytes(data, size);
        const Zone zone = quake::load_bsp29(bytes, "fuzz.bsp");
        fuzz::check_zone(zone);
        if (zone.baked_pvs) {
            const auto levels = quake::compute_ambient_levels(bytes, *zone.baked_pvs, {}, "fuzz.bsp");
            quake::write_bsp29_vis(bytes, *zone.baked_pvs, "fuzz.bsp", nullptr, levels);
        }
    });
    return 0;
}
