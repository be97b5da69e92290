// Simple procedural textures for generated zones: 64x64, made from the texture's own small hash
// noise so they are identical on every machine (no std:: distributions, whose output is
// implementation-defined). Each keeps to at most 256 colours, so it is stored palettized.
#pragma once

#include "visibility/zone.h"

#include <vector>

namespace pvs::gen {

enum class Surface : uint8_t { Wall = 0, Floor, Ceiling, Water, Lava, Slime, Pvp, ZoneLine, Count };

// One material per Surface, in Surface order.
std::vector<Material> make_gen_materials();

} // namespace pvs::gen
