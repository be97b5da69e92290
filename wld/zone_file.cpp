#include "wld/zone_file.h"

#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/doom/doom_zone.h"
#include "wld/doom/wad_file.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/hepvs/hepvs_zone.h"
#include "wld/obj/obj_reader.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/prt_file.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/ibsp38_zone.h"

#include <filesystem>

namespace pvs {

namespace {

// qbsp writes the portal file next to the map, with the same name: pick it up when present.
// Its leaf k is BSP leaf k+1 = region k, so it must name exactly the map's vis leaves. The map
// does not need it: a portal file that cannot be used (broken, another map's) is left out with
// a note saying why, and the map loads.
void attach_sibling_prt(Zone& zone, const std::string& bsp_path)
{
    std::filesystem::path prt_path(bsp_path);
    prt_path.replace_extension(".prt");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(prt_path, ec))
        return;
    quake::PrtFile prt;
    try {
        prt = quake::load_prt(prt_path.string());
    } catch (const FileError& e) {
        zone.source.notes.push_back(prt_path.filename().string() + " not used: " + e.what());
        return;
    }
    if (prt.leaf_count != zone.region_count()) {
        zone.source.notes.push_back(prt_path.filename().string() + " not used: it names " +
                                    std::to_string(prt.leaf_count) + " leaves but the map has " +
                                    std::to_string(zone.region_count()) + " vis leaves (a portal file of another map?)");
        return;
    }
    if (prt.has_clusters()) { // PRT2 / PRT1-AM: its portals join clusters, not regions
        zone.source.notes.push_back(prt_path.filename().string() +
                                    " is a clustered portal file (PRT2 / PRT1-AM): its portals are not shown");
        return;
    }
    zone.portals = std::move(prt.portals);
    zone.source.notes.push_back("portals from " + prt_path.filename().string());
}

std::string sibling(const std::string& path, const char* extension)
{
    std::filesystem::path p(path);
    p.replace_extension(extension);
    std::error_code ec;
    return std::filesystem::is_regular_file(p, ec) ? p.string() : std::string();
}

bool has_extension(const std::string& path, const char* extension)
{
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return e == extension;
}

// An OBJ level, with its .hepvs when there is one.
Zone load_obj_zone(const std::string& obj_path, std::string hepvs_path, const ZoneLoadOptions& options)
{
    Zone zone = read_obj_zone(read_whole_file(obj_path), obj_path);
    if (hepvs_path.empty())
        hepvs_path = sibling(obj_path, ".hepvs");
    if (hepvs_path.empty()) {
        zone.source.notes.push_back("no PVS: no .hepvs beside it (the culler falls back to the frustum)");
        return zone;
    }
    const HepvsFile hepvs = read_hepvs(read_whole_file(hepvs_path), hepvs_path);
    attach_hepvs(zone, hepvs, hepvs_path, options.grid_size);
    return zone;
}

// Why an "IBSP" file that is not Quake 2's is not opened here.
std::string ibsp_not_supported(std::span<const uint8_t> bytes)
{
    if (bytes.size() < 8)
        return "an IBSP header too short for its version";
    const uint32_t version = uint32_t(bytes[4]) | uint32_t(bytes[5]) << 8 | uint32_t(bytes[6]) << 16 | uint32_t(bytes[7]) << 24;
    if (version == 46)
        return "a Quake 3 map (IBSP 46) is not supported";
    return "IBSP version " + std::to_string(version) + " (neither Quake 2's 38 nor Quake 3's 46) is not supported";
}

} // namespace

std::optional<ZoneFormat> zone_format_from_name(const std::string& path)
{
    if (has_extension(path, ".hepvs") || is_obj_path(path))
        return ZoneFormat::ObjHepvs;
    if (doom::file_looks_like_wad(path)) // a Doom WAD or a .gwa, read with its sibling
        return ZoneFormat::DoomWad;
    return std::nullopt;
}

ZoneFormat zone_format_from_bytes(std::span<const uint8_t> bytes)
{
    if (quake::looks_like_bsp29(bytes))
        return ZoneFormat::QuakeBsp;
    if (quake2::looks_like_ibsp38(bytes))
        return ZoneFormat::Quake2Bsp;
    if (eq::looks_like_pfs(bytes))
        return ZoneFormat::EqS3d;
    return ZoneFormat::Unknown;
}

Zone load_zone(const std::string& path) { return load_zone(path, ZoneLoadOptions{}); }

Zone load_zone(const std::string& path, const ZoneLoadOptions& options)
{
    if (const std::optional<ZoneFormat> named = zone_format_from_name(path)) {
        if (*named == ZoneFormat::DoomWad)
            return doom::load_doom_zone(path, options.map, options.gwa);
        if (!has_extension(path, ".hepvs"))
            return load_obj_zone(path, options.hepvs, options);
        const std::string obj = options.obj.empty() ? sibling(path, ".obj") : options.obj;
        if (obj.empty())
            throw FileError(path, 0, "a .hepvs is opened with its OBJ: none of the same name beside it (pass --obj)");
        return load_obj_zone(obj, path, options);
    }
    const std::vector<uint8_t> bytes = read_whole_file(path);
    if (!options.map.empty() || !options.gwa.empty()) // not silently ignored
        throw FileError(path, 0, std::string(options.map.empty() ? "--gwa" : "--map") +
                                     " names a Doom map's part, and this is not a Doom WAD");
    switch (zone_format_from_bytes(bytes)) {
    case ZoneFormat::QuakeBsp: {
        Zone zone = quake::load_bsp29(bytes, path);
        attach_sibling_prt(zone, path);
        return zone;
    }
    case ZoneFormat::Quake2Bsp: return quake2::load_ibsp38(bytes, path);
    case ZoneFormat::EqS3d: return eq::load_eq_zone(bytes, path);
    default: break;
    }
    if (bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "IBSP"))
        throw FileError(path, 0, ibsp_not_supported(bytes));
    if (bytes.size() >= 4 && (std::equal(bytes.begin(), bytes.begin() + 4, "BSP2") ||
                              std::equal(bytes.begin(), bytes.begin() + 4, "2PSB")))
        throw FileError(path, 0, "a BSP2 / 2PSB file too short for its lump directory");
    if (bytes.size() >= 4 && bytes[0] == 30 && bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 0)
        throw FileError(path, 0, "Half-Life BSP 30 is not supported");
    throw FileError(path, 0, "unknown file format (supported: Quake BSP 29 / BSP2 / 2PSB, Quake 2 IBSP 38, EverQuest S3D, Doom WAD with GL "
                             "nodes, Wavefront .obj with HateEngine .hepvs)");
}

} // namespace pvs
