// DDS textures (DirectDraw Surface, DXT1 / DXT3 / DXT5 block compression) to RGBA, for the
// textures of EverQuest archives that hold .dds members (later clients), through Debian's
// libsquish (libsquish-dev).
//
// The header is parsed here, not by squish, with every field checked before anything is
// allocated or decoded:
//   offset 0    magic "DDS "
//   offset 4    header size, must be 124
//   offset 12   height, offset 16 width: each 1 .. kMaxDdsSide
//   offset 76   pixel format size, must be 32
//   offset 80   pixel format flags: DDPF_FOURCC (0x4) must be set
//   offset 84   FourCC "DXT1", "DXT3" or "DXT5" (DX10 extended headers and uncompressed
//               formats are refused)
//   offset 128  the top mip level's blocks: ceil(w/4) * ceil(h/4) blocks of 8 (DXT1) or 16
//               bytes, which must all be in the file. Further mip levels are ignored.
// Decoding never throws and never reads out of bounds: bad input gives nullopt and, in `why`,
// the offset and the problem ("offset 84: FourCC 'DXT2' is not DXT1, DXT3 or DXT5").
#pragma once

#include "wld/eq/stb_image_io.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace pvs {

inline constexpr uint32_t kMaxDdsSide = 16384;
inline constexpr size_t kDdsHeaderBytes = 128; // magic + the 124-byte header

// True when the bytes start with the magic "DDS ".
bool looks_like_dds(std::span<const uint8_t> bytes);

// The top mip level as RGBA, top row first (DXT1 texels with the transparent code get alpha 0).
std::optional<RgbaImage> decode_dds(std::span<const uint8_t> bytes, std::string* why = nullptr);

} // namespace pvs
