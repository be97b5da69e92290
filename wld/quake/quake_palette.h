// The Quake palette: the 256-entry RGB table (gfx/palette.lmp in the game data) that maps the
// 8-bit texels of BSP 29 miptex to colors. It is not stored in BSP files, so pvscope carries it
// as a table of facts about the format. Entries 224..255 are fullbright colors; 255 is the
// transparent index of fence textures.
#pragma once

#include <array>
#include <cstdint>

namespace pvs::quake {

extern const std::array<uint8_t, 768> kQuakePalette;

} // namespace pvs::quake
