// libFuzzer target: Doom WADs with GL nodes (wld/doom/wad_file.h, doom_map.h, doom_zone.h): the
// directory, then every map with its GL group (V1, V2, V3, V5) and GL_PVS read from the same WAD
// and built into a zone. Textures are left out here (fuzz_doom_textures covers them).
#include "tests/fuzz/fuzz_support.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    doom::WadFile wad;
    if (!fuzz::accepts([&] { wad = doom::parse_wad(std::vector<uint8_t>(data, data + size), "fuzz.wad"); }))
        return 0;
    for (const doom::WadLump& lump : wad.lumps)
        fuzz::fuzz_check(uint64_t(lump.offset) + lump.size <= wad.bytes.size(), "lump inside the file");
    for (const std::string& name : doom::map_names(wad))
        fuzz::accepts([&] {
            const doom::DoomMap map = doom::read_doom_map(wad, nullptr, name);
            fuzz::check_zone(doom::build_doom_zone(map, nullptr));
        });
    return 0;
}
