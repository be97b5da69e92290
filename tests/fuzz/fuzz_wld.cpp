// libFuzzer target: a bare EverQuest WLD file (wld/eq/wld_file.h, wld_mesh.h, wld_material.h):
// the container, then every fragment of a type pvscope reads through its typed parser, each on
// its own, and its VISLISTs decoded. What a typed parser accepted is also written back with its
// writer, which may refuse only with std::invalid_argument (values the file form cannot hold).
#include "tests/fuzz/fuzz_support.h"
#include "visibility/bit_row.h"
#include "wld/eq/wld_file.h"
#include "wld/eq/wld_material.h"
#include "wld/eq/wld_mesh.h"

#include <stdexcept>

namespace {

template <class Write>
void write_back(Write&& write)
{
    try {
        (void)write();
    } catch (const std::invalid_argument&) {
    }
}

void parse_fragment(const pvs::eq::WldFile& wld, uint32_t number)
{
    using namespace pvs::eq;
    switch (wld.fragment(number).type) {
    case kWldBspTree: {
        const WldBspTree tree = parse_bsp_tree(wld, number);
        write_back([&] { return write_bsp_tree(tree); });
        break;
    }
    case kWldRegion: {
        const WldRegion region = parse_region(wld, number);
        std::vector<uint64_t> row(pvs::bits::words_for(wld.region_count()));
        for (const WldVisList& list : region.vis_lists)
            (void)decode_vis_list(list, wld.region_count(), row);
        write_back([&] { return write_region(region); });
        break;
    }
    case kWldRegionFlag: {
        const WldRegionFlag flag = parse_region_flag(wld, number);
        write_back([&] { return write_region_flag(flag); });
        break;
    }
    case kWldMesh: {
        const WldMesh mesh = parse_mesh(wld, number);
        (void)face_materials(mesh);
        (void)mesh_bounds(mesh);
        write_back([&] { return write_mesh(mesh); });
        break;
    }
    case kWldBitmapName: {
        const WldBitmapName bitmap = parse_bitmap_name(wld, number);
        write_back([&] { return write_bitmap_name(bitmap); });
        break;
    }
    case kWldSpriteDef: {
        const WldSpriteDef sprite_def = parse_sprite_def(wld, number);
        write_back([&] { return write_sprite_def(sprite_def); });
        break;
    }
    case kWldSprite: {
        const WldSprite sprite = parse_sprite(wld, number);
        write_back([&] { return write_sprite(sprite); });
        break;
    }
    case kWldMaterial: {
        const WldMaterial material = parse_material(wld, number);
        write_back([&] { return write_material(material); });
        break;
    }
    case kWldMaterialPalette: {
        const WldMaterialPalette palette = parse_material_palette(wld, number);
        for (uint32_t i = 0; i < palette.materials.size(); ++i) {
            (void)texture_file_of(wld, number, i);
            (void)material_is_visible(wld, number, i);
        }
        write_back([&] { return write_material_palette(palette); });
        break;
    }
    default:
        (void)fragment_name(wld, wld.fragment(number));
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    eq::WldFile wld;
    if (!fuzz::accepts([&] { wld = eq::parse_wld(fuzz::as_bytes(data, size), "fuzz.wld"); }))
        return 0;
    for (uint32_t number = 1; number <= wld.fragments.size(); ++number)
        fuzz::accepts([&] { parse_fragment(wld, number); });
    return 0;
}
