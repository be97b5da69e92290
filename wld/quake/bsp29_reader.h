// Quake BSP version 29 -> zone model (../shared/formats/quake-doom-hepvs.md §1).
//
// Mapping to the zone model:
//  - Region r is BSP leaf r+1, for leaves 1..models[0].visleafs (the world's vis leaves), so a
//    region id is also its PVS bit (bit j = leaf j+1). Leaf 0, the shared solid leaf, is not a
//    region (BspTree marks it kLeafSolid). Leaves after visleafs belong to brush entities.
//  - Contents water/slime/lava/sky become region flags. A trigger_changelevel's volume marks
//    the regions it touches (found as the engine links entities: a box walk down the tree)
//    with kRegionZoneLine and a ZoneLine naming the target map.
//  - The mesh holds the world's faces (model 0), each triangulated as a fan, counter-clockwise
//    seen from the front; uv in texture repeats. Brush-entity faces (doors, lifts) are not
//    loaded: no world leaf lists them.
//  - Region face lists come from marksurfaces. Materials are the miptex, with mip 0 converted
//    to RGBA through the Quake palette.
//  - The VISIBILITY lump becomes the baked PVS. visofs -1 is a missing row (all visible, as in
//    the engine); an empty lump with no rows means the map was never vised: no baked PVS.
//  - Split ties follow the engine: a point on a plane goes to the back child.
// Every count, index and offset is checked; bad input throws FileError naming file and offset.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <string>

namespace pvs::quake {

// True when the bytes start like a BSP 29 file (version field 29).
bool looks_like_bsp29(std::span<const uint8_t> bytes);

Zone load_bsp29(std::span<const uint8_t> bytes, const std::string& file);

} // namespace pvs::quake
