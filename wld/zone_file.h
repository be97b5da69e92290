// Opening a zone file of any supported format: the format is recognised from the bytes, not
// from the file name, except for Wavefront OBJ (text with no magic: by its .obj extension) and
// HateEngine .hepvs (by its extension: it is opened with its OBJ). A Doom WAD ("IWAD"/"PWAD") opens
// ZoneLoadOptions::map with its GL nodes from the .gwa beside it or the WAD itself; a .gwa opens
// with the .wad beside it. Sidecar files are picked up
// when present: a Quake map's .prt portal file next to the .bsp, an OBJ's .hepvs of the same
// name (or the one ZoneLoadOptions names), a .hepvs's OBJ likewise. Throws FileError for
// unreadable, unknown or bad files.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace pvs {

// The formats load_zone opens, as it tells them apart (the one place that does).
enum class ZoneFormat { QuakeBsp, Quake2Bsp, EqS3d, ObjHepvs, DoomWad, Unknown };

// The formats told without reading the whole file: an OBJ or a .hepvs by its extension, a Doom
// WAD or .gwa by its magic (the file's first bytes). nullopt for the others:
// zone_format_from_bytes tells them from their bytes.
std::optional<ZoneFormat> zone_format_from_name(const std::string& path);
// Quake BSP 29 / BSP2 / 2PSB, Quake 2 IBSP 38, an EverQuest PFS archive (.s3d), else Unknown.
ZoneFormat zone_format_from_bytes(std::span<const uint8_t> bytes);

struct ZoneLoadOptions {
    std::string obj;   // the OBJ of a .hepvs (default: the .obj of the same name beside it)
    std::string hepvs; // the .hepvs of an OBJ (default: the .hepvs of the same name, if any)
    float grid_size = 16.0f; // OBJ units per .hepvs grid unit (the baker's -g)
    std::string map;         // the map of a Doom WAD (E1M1, MAP10; default: the first)
    std::string gwa;         // GL nodes for a Doom WAD (default: the .gwa beside it, else the WAD's own)
};

Zone load_zone(const std::string& path);
Zone load_zone(const std::string& path, const ZoneLoadOptions& options);

} // namespace pvs
