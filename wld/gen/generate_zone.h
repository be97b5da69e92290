// Procedural demo zones: `pvscope gen --rooms N --seed S`. An indoor zone on a grid (see
// voxel_level.h) with a proper BSP tree (kd_bsp.h), one region per open convex box, meshes on
// the boundaries between open and solid space with procedural textures (gen_textures.h), and
// region flags for the water pool, lava pit, slime channel, PvP arena and zone-line doorway.
//
// A generated zone carries no PVS until a baker exists; the culler then falls back to the
// frustum, and the zone's notes say so. N runs from 5 to 5000 so benchmarks can show how costs
// grow with the size of a zone. Deterministic: the same (rooms, seed) gives the same zone.
#pragma once

#include "visibility/zone.h"

#include <cstdint>

namespace pvs::gen {

struct GenParams {
    int rooms = 40;
    uint64_t seed = 1;
    float cell_size = 32.0f; // world units per grid cell (a room is 3 cells high)
};

// Throws std::invalid_argument for rooms outside [5, 5000] or a non-positive cell size.
Zone generate_zone(const GenParams& params);

// The built-in demo zone (the README's first command opens it).
inline GenParams demo_zone_params() { return {60, 2026, 32.0f}; }

} // namespace pvs::gen
