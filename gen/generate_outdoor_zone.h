// Procedural outdoor zones: `pvscope gen --outdoor`. A terrain zone (terrain_level.h: hills,
// a walled town with buildings, a lake with a bridge, a lava pit, a rock arch, zone lines at two
// edges) with the region tree as EverQuest's open zones have it: axis-aligned splits down to
// single cells, one region per open cell (cells under the ground are solid, not regions), meshes
// on the boundaries with procedural textures, region flags for water, lava and the zone lines.
//
// Size: `size` world units a side in cells of `cell_size`; the defaults (4096 units, 64-unit
// cells, 14 cells high) give 64 x 64 columns and about 20 000 - 30 000 regions.
// PVS: with `bake`, the terrain method (visibility/terrain/terrain_vis.h: a horizon over the
// ground) - conservative, and on open ground both quicker and tighter than base portal vis, the
// only portal method that finishes there in useful time (docs/outdoor.md); the zone's notes say so. Off unless asked (`pvscope gen --outdoor` asks unless --no-bake).
// Deterministic: the same parameters give the same zone.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <functional>

namespace pvs::gen {

struct OutdoorParams {
    float size = 4096.0f;     // world units along x and y
    float cell_size = 64.0f;  // world units per cell
    int height = 14;          // cells along z (up)
    uint64_t seed = 1;
    bool bake = false;
    unsigned bake_threads = 0;
    std::function<bool(double fraction)> bake_progress = nullptr;
};

// Throws std::invalid_argument when size / cell_size is outside the terrain's column range
// (terrain_level.h), the height is out of range, or a size is not positive.
Zone generate_outdoor_zone(const OutdoorParams& params);

} // namespace pvs::gen
