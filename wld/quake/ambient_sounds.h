// The ambient sound levels Quake's vis writes into each leaf (../shared/formats/quake-doom-hepvs.md
// §3.9; the engines play water and wind loops by them): computed from a PVS and the map's
// surfaces exactly as ericw-tools' vis computes them, so the bytes match.
//
// For each world vis leaf L (leaves 1..models[0].visleafs; region r = leaf r+1), every leaf its
// PVS row holds is scanned, and every marksurface of those leaves is classified by its texture's
// name (case-insensitive prefix, first match wins):
//   "sky" -> sky;  "*water", "*04water" -> water;  "*slime" -> water (vis sends slime to the water
//   channel: the slime channel is never set);  "*lava" -> lava.
// A channel is 255 when some visible surface falls in it, else 0. (vis computes a distance from
// L to each surface and a volume that falls off with it, but sets the distance to a constant
// 0.25 before using it, and its fall-off reads the slime channel's distance, which stays at its
// start of 1020; so the only values it writes are 0 and 255.)
// AmbientOptions turns a texture class off as vis's -noambientsky, -noambientwater,
// -noambientslime and -noambientlava do: its surfaces are not classified. So -noambientslime
// keeps the water channel's water surfaces, and -noambientwater keeps its slime surfaces.
// -noambient turns all four off: every level 0.
// Leaves after visleafs (brush entities') are not given levels. Every offset and index is
// checked: bad input throws FileError naming the file, the offset and the problem.
#pragma once

#include "visibility/pvs.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace pvs::quake {

enum AmbientChannel : uint32_t { kAmbientWater = 0, kAmbientSky = 1, kAmbientSlime = 2, kAmbientLava = 3 };

struct AmbientOptions {
    bool water = true, sky = true, slime = true, lava = true; // texture classes that count

    static AmbientOptions none() { return {false, false, false, false}; }
};

using AmbientLevels = std::array<uint8_t, 4>; // water, sky, slime, lava: a leaf record's bytes

// The levels of every world vis leaf of the BSP (29, BSP2 or 2PSB) in `bytes`, from `pvs` (one row
// per vis leaf, as bsp29_reader.h numbers them). Throws std::invalid_argument when the PVS does not
// have visleafs rows.
std::vector<AmbientLevels> compute_ambient_levels(std::span<const uint8_t> bytes, const Pvs& pvs,
                                                  const AmbientOptions& options, const std::string& file);

// A copy of the file with leaf r+1's four ambient bytes set to levels[r], every other byte as it
// was (what `pvscope vis --ambient-only` writes). Throws std::invalid_argument when there is not
// one entry per vis leaf.
std::vector<uint8_t> with_ambient_levels(std::span<const uint8_t> bytes, std::span<const AmbientLevels> levels,
                                         const std::string& file);

// The levels stored in the file's leaves 1..visleafs (what a vis wrote there).
std::vector<AmbientLevels> read_ambient_levels(std::span<const uint8_t> bytes, const std::string& file);

} // namespace pvs::quake
