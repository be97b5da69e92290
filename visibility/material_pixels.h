// A material's texels, kept palettized when the image has at most 256 distinct RGBA colours and
// as RGBA otherwise. Palettizing is lossless: Quake textures and 8-bit BMPs always fit, and a
// texel then takes 1 byte instead of 4, which is most of a zone's texture memory.
//
// Contract:
//  - assign_rgba stores 4 bytes per texel (r, g, b, a); decode_rgba gives exactly those bytes
//    back, whichever form was chosen. The form is a function of the pixels alone (palette in
//    order of first use), so equal images compare equal.
//  - texel(i) is one texel packed as r | g << 8 | b << 16 | a << 24.
//  - Materials set and read pixels through set_material_rgba / material_rgba (zone.h), which
//    also keep the material's width and height in step.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

class MaterialPixels {
public:
    static constexpr size_t kMaxPaletteColors = 256;

    // Stores the texels (rgba.size() must be a multiple of 4), palettized when they fit.
    void assign_rgba(std::span<const uint8_t> rgba);
    // Writes every texel as 4 bytes r, g, b, a into `out` (resized to texel_count() * 4).
    void decode_rgba(std::vector<uint8_t>& out) const;
    uint32_t texel(size_t i) const { return palettized() ? palette_[indices_[i]] : packed_rgba(i); }

    size_t texel_count() const { return palettized() ? indices_.size() : rgba_.size() / 4; }
    bool empty() const { return texel_count() == 0; }
    bool palettized() const { return !palette_.empty(); }
    size_t palette_size() const { return palette_.size(); }
    // Heap bytes held (capacity of the vectors).
    size_t memory_bytes() const;
    void shrink_to_fit();

    bool operator==(const MaterialPixels&) const = default;

private:
    uint32_t packed_rgba(size_t i) const
    {
        const uint8_t* p = &rgba_[4 * i];
        return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    }

    std::vector<uint8_t> indices_;  // one palette index per texel, when palettized
    std::vector<uint32_t> palette_; // packed colours, in order of first use; empty when RGBA
    std::vector<uint8_t> rgba_;     // 4 bytes per texel, when not palettized
};

} // namespace pvs
