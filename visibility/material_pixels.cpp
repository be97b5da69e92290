#include "visibility/material_pixels.h"

#include <array>
#include <stdexcept>
#include <string>

namespace pvs {

namespace {

uint32_t pack(const uint8_t* p)
{
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// Colour -> palette index, open addressing in a fixed table twice the palette's size: the loop
// over texels allocates nothing.
class ColorIndex {
public:
    // The colour's index, added when new; -1 when the palette is full.
    int find_or_add(uint32_t color, std::vector<uint32_t>& palette)
    {
        uint32_t slot = (color * 0x9E3779B1u) >> (32 - kBits);
        while (used_[slot]) {
            if (palette[index_[slot]] == color)
                return index_[slot];
            slot = (slot + 1) & (kSlots - 1);
        }
        if (palette.size() == MaterialPixels::kMaxPaletteColors)
            return -1;
        used_[slot] = 1;
        index_[slot] = static_cast<uint8_t>(palette.size());
        palette.push_back(color);
        return index_[slot];
    }

private:
    static constexpr uint32_t kBits = 9;
    static constexpr uint32_t kSlots = 1u << kBits;
    std::array<uint8_t, kSlots> used_{};
    std::array<uint8_t, kSlots> index_{};
};

} // namespace

void MaterialPixels::assign_rgba(std::span<const uint8_t> rgba)
{
    if (rgba.size() % 4 != 0)
        throw std::invalid_argument("MaterialPixels: " + std::to_string(rgba.size()) +
                                    " bytes of RGBA is not a whole number of texels");
    const size_t count = rgba.size() / 4;
    indices_.clear();
    palette_.clear();
    rgba_.clear();
    indices_.resize(count);
    ColorIndex colors;
    uint32_t last_color = 0;
    int last_index = -1; // neighbouring texels often repeat: skip the table for them
    for (size_t i = 0; i < count; ++i) {
        const uint32_t color = pack(&rgba[4 * i]);
        if (last_index < 0 || color != last_color) {
            last_index = colors.find_or_add(color, palette_);
            last_color = color;
            if (last_index < 0) { // more than 256 colours: keep RGBA
                indices_ = {};
                palette_ = {};
                rgba_.assign(rgba.begin(), rgba.end());
                return;
            }
        }
        indices_[i] = static_cast<uint8_t>(last_index);
    }
    if (count == 0)
        indices_ = {};
}

void MaterialPixels::decode_rgba(std::vector<uint8_t>& out) const
{
    if (!palettized()) {
        out = rgba_;
        return;
    }
    out.resize(indices_.size() * 4);
    uint8_t* o = out.data();
    for (const uint8_t index : indices_) {
        const uint32_t c = palette_[index];
        o[0] = uint8_t(c);
        o[1] = uint8_t(c >> 8);
        o[2] = uint8_t(c >> 16);
        o[3] = uint8_t(c >> 24);
        o += 4;
    }
}

size_t MaterialPixels::memory_bytes() const
{
    return indices_.capacity() + palette_.capacity() * sizeof(uint32_t) + rgba_.capacity();
}

void MaterialPixels::shrink_to_fit()
{
    indices_.shrink_to_fit();
    palette_.shrink_to_fit();
    rgba_.shrink_to_fit();
}

} // namespace pvs
