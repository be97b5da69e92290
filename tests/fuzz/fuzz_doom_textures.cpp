// libFuzzer target: the textures of a Doom WAD (wld/doom/doom_textures.h): PLAYPAL, flats,
// PNAMES, TEXTURE1/TEXTURE2 and the patches every texture is composed from.
#include "tests/fuzz/fuzz_support.h"
#include "wld/doom/doom_textures.h"

#include <optional>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    doom::WadFile wad;
    if (!fuzz::accepts([&] { wad = doom::parse_wad(std::vector<uint8_t>(data, data + size), "fuzz.wad"); }))
        return 0;
    std::optional<doom::DoomTextures> textures;
    if (!fuzz::accepts([&] { textures.emplace(wad); }))
        return 0;
    auto check = [](const std::optional<doom::DoomImage>& image) {
        if (image)
            fuzz::fuzz_check(image->rgba.size() == size_t(image->width) * image->height * 4, "RGBA size");
    };
    for (const std::string& name : textures->flat_names())
        check(textures->flat(name));
    for (const std::string& name : textures->wall_names())
        fuzz::accepts([&] { check(textures->wall(name)); });
    return 0;
}
