// glVIS GL_PVS lump rows (Doom GL nodes, ../shared/formats/quake-doom-hepvs.md §4.5).
//
// The lump is numsubsectors rows of glvis_row_bytes(n) = (n + 7) / 8 bytes each, UNcompressed;
// row i (viewer in subsector i) starts at byte i * row_bytes, subsector j is bit j % 8 of byte
// j / 8, least significant bit first. An empty lump means "everything visible" (Vavoom uses one
// all-0xFF row for every subsector). Padding bits in a row's last byte are ignored on read and
// written as zero.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

constexpr size_t glvis_row_bytes(size_t subsector_count) { return (subsector_count + 7) / 8; }
// Size of a complete lump; longer lumps are accepted (the extra bytes are never read).
constexpr size_t glvis_lump_size(size_t subsector_count) { return glvis_row_bytes(subsector_count) * subsector_count; }

enum class GlvisRowStatus : uint8_t {
    decoded,     // the row came from the lump
    empty_lump,  // the lump is empty: everything is visible by convention (row filled)
    short_lump,  // row >= subsector_count, or the lump ends before the row does: row filled
                 // (all visible, the safe answer for a culler); the lump is damaged
};

// Decodes row `row` of a GL_PVS lump into `out` (at least words_for(subsector_count) words, all
// overwritten; padding bits are zero). Never reads past `lump`.
GlvisRowStatus decode_glvis_row(std::span<const uint8_t> lump, size_t subsector_count, size_t row,
                                std::span<uint64_t> out);

// Appends a whole lump: `rows` holds subsector_count rows back to back, each
// words_for(subsector_count) words (bits past subsector_count are not written).
void encode_glvis_rows(std::span<const uint64_t> rows, size_t subsector_count, std::vector<uint8_t>& out);

} // namespace pvs
