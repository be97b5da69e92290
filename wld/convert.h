// Zone conversion: `pvscope convert IN OUT` and `pvscope gen -o OUT` write a loaded zone as an
// EverQuest .s3d or a Wavefront .obj, chosen by the output's extension (or --to).
//
// An EverQuest zone stores one mesh per region holding exactly the polygons inside the region's
// volume. A zone whose faces are listed by several regions (a Quake BSP's marksurfaces) is first
// re-cut with clip_faces_to_region_cells; a zone already in that layout is written as it is.
#pragma once

#include "visibility/zone.h"

#include <optional>
#include <string>

namespace pvs {

enum class ZoneOutput : uint8_t { S3d, Obj };

// An OBJ is written with its PVS beside it as a .hepvs of the same name (wld/hepvs/hepvs_zone.h):
// a grid zone's own grid, or for a region PVS the HateEngine grid of cells this many grid units
// (16 OBJ units each) wide, the size of the E1M1 sample's.
inline constexpr float kConvertHepvsCell = 8.0f;

// From --to ("s3d", "obj") if given, else from the path's extension; nullopt when neither says.
std::optional<ZoneOutput> zone_output_for(const std::string& path, const std::string& to);

// True when some face is listed by more than one region.
bool faces_shared_between_regions(const Zone& zone);

// Writes the zone; returns notes on what the format could not keep. Throws FileError when the
// file cannot be written and std::invalid_argument when the zone cannot be expressed.
std::vector<std::string> write_zone(const Zone& zone, const std::string& path, ZoneOutput output);

} // namespace pvs
