#include "wld/convert.h"

#include "visibility/geometry/split_faces.h"
#include "wld/common/read_file.h"
#include "wld/eq/eq_zone_writer.h"
#include "wld/hepvs/hepvs_zone.h"
#include "wld/obj/obj_writer.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace pvs {

std::optional<ZoneOutput> zone_output_for(const std::string& path, const std::string& to)
{
    std::string kind = to;
    if (kind.empty()) {
        kind = std::filesystem::path(path).extension().string();
        if (!kind.empty())
            kind.erase(0, 1);
    }
    std::transform(kind.begin(), kind.end(), kind.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (kind == "s3d")
        return ZoneOutput::S3d;
    if (kind == "obj")
        return ZoneOutput::Obj;
    return std::nullopt;
}

bool faces_shared_between_regions(const Zone& zone)
{
    std::vector<uint8_t> seen(zone.mesh.faces.size(), 0);
    for (uint32_t f : zone.region_faces)
        if (seen[f]++)
            return true;
    return false;
}

std::vector<std::string> write_zone(const Zone& zone, const std::string& path, ZoneOutput output)
{
    if (output == ZoneOutput::Obj) {
        save_obj(zone, path);
        if (!zone.baked_pvs)
            return {"the zone has no PVS: no .hepvs written"};
        std::filesystem::path hepvs_path(path);
        hepvs_path.replace_extension(".hepvs");
        const HepvsFile hepvs = zone.view_grid ? hepvs_from_zone(zone) : hepvs_over_regions(zone, kConvertHepvsCell);
        write_whole_file(hepvs_path.string(), write_hepvs(hepvs));
        char note[256];
        std::snprintf(note, sizeof note, "PVS written as %s: %u x %u x %u cells of %g grid units%s",
                      hepvs_path.filename().string().c_str(), hepvs.counts.x, hepvs.counts.y, hepvs.counts.z,
                      double(hepvs.cell_size),
                      zone.view_grid ? "" : " (each the union of the rows of the regions touching it)");
        return {note};
    }
    if (!zone.tree.exists())
        throw std::invalid_argument(zone.view_grid ? "an OBJ level's regions are objects over a view grid, with no BSP "
                                                     "tree: an EverQuest zone needs its regions as the leaves of one"
                                                   : "the zone has no BSP tree of regions: an EverQuest zone needs one");
    const std::string name = std::filesystem::path(path).stem().string();
    std::optional<Zone> cut;
    std::vector<std::string> notes;
    if (faces_shared_between_regions(zone)) {
        cut = clip_faces_to_region_cells(zone);
        notes.push_back("faces shared between regions were clipped to each region's cell");
    }
    const Zone& written_zone = cut ? *cut : zone;
    // The old WLD form (i16 uvs, read by every client) unless a face's uvs need the new one's f32.
    eq::EqWriteOptions options;
    if (const std::optional<uint32_t> face = eq::face_beyond_old_wld_form(written_zone)) {
        options.wld_version = eq::kWldVersionNew;
        notes.push_back("face " + std::to_string(*face) + "'s texture coordinates span more than the old WLD form's 256 "
                        "repeats: written as the new WLD version (f32 uvs; clients that read only the old form "
                        "cannot open it)");
    }
    auto written = eq::write_eq_zone_archive(written_zone, name, options);
    write_whole_file(path, written.bytes);
    notes.insert(notes.end(), written.notes.begin(), written.notes.end());
    return notes;
}

} // namespace pvs
