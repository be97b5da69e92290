// BMP pixels in and out, through stb (Debian libstb-dev: stb_image.h, stb_image_write.h).
//
// EverQuest zone archives store their textures as .bmp members (8-bit palettized in the
// originals, 24-bit from most tools). pvscope decodes them into the zone model's RGBA pixels
// and writes 24-bit BMPs when it builds an archive. Only stb's BMP code is compiled in
// (STBI_ONLY_BMP), in stb_image_io.cpp, the one translation unit that holds stb's
// implementation; the headers' warnings are silenced there and nowhere else.
//
// Hostile input: the header is checked before stb allocates anything (dimensions at most
// kMaxBmpSide on a side, and no more pixels than the file's bytes can describe at the header's
// bit depth), so a 40-byte file cannot ask for gigabytes. Decoding never throws: a file stb
// cannot read gives nullopt and the reason.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace pvs {

inline constexpr uint32_t kMaxBmpSide = 16384;

struct RgbaImage {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba; // width * height * 4 bytes, top row first
};

// Decodes a BMP (1/4/8-bit palettized, 16/24/32-bit) to RGBA, top row first; alpha is 255
// where the file has none. nullopt when it is not a BMP stb can read; `why` (if given) then
// says what is wrong.
std::optional<RgbaImage> decode_bmp(std::span<const uint8_t> bytes, std::string* why = nullptr);

// A 24-bit uncompressed BMP (bottom-up rows, each padded to 4 bytes) of RGBA pixels, top row
// first; alpha is dropped. Lossless for the colour channels. Throws std::invalid_argument for
// an empty image, a side over kMaxBmpSide or a pixel buffer of the wrong size.
std::vector<uint8_t> encode_bmp(uint32_t width, uint32_t height, std::span<const uint8_t> rgba);

} // namespace pvs
