// An RGBA picture as the renderers make it and the overlays draw on it, and its PNG file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pvs::ui {

struct Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba; // width*height*4 bytes, rows top to bottom, alpha always 255

    const uint8_t* pixel(uint32_t x, uint32_t y) const { return rgba.data() + (size_t(y) * width + x) * 4; }
};

// Writes an 8-bit RGBA PNG. Throws std::runtime_error naming the path when it cannot.
void save_png(const Image& image, const std::string& path);

} // namespace pvs::ui
