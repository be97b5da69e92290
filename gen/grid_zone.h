// A zone from a voxel level on a grid (procedural zones, stability cases): the kd BSP tree of
// the cells (kd_bsp.h), one region per open leaf box with its flags (water, lava, slime, PvP,
// zone line), and a mesh on every boundary between open and solid space or between media, with
// the procedural materials (gen_textures.h). No PVS, no source description: callers add those.
//
// Regions come in the order of the tree's open leaves; region r's bounds are its leaf box.
// Deterministic: the same level, axes and labels give the same zone.
#pragma once

#include "visibility/zone.h"
#include "gen/grid_axes.h"
#include "gen/voxel_level.h"

#include <cstdint>
#include <span>

namespace pvs::gen {

// labels: as build_kd_bsp's (optional; cells of one label never share a region with another's).
Zone build_grid_zone(const VoxelLevel& level, const GridAxes& axes, std::span<const uint32_t> labels = {});

} // namespace pvs::gen
