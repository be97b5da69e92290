#include "visibility/codec/glvis_rows.h"

#include "visibility/bit_row.h"

namespace pvs {

GlvisRowStatus decode_glvis_row(std::span<const uint8_t> lump, size_t subsector_count, size_t row,
                                std::span<uint64_t> out)
{
    if (lump.empty()) {
        bits::fill(out, subsector_count);
        return GlvisRowStatus::empty_lump;
    }
    const size_t row_bytes = glvis_row_bytes(subsector_count);
    // row < lump.size() / row_bytes  <=>  (row + 1) * row_bytes <= lump.size(), without overflow.
    if (row >= subsector_count || row >= lump.size() / row_bytes) {
        bits::fill(out, subsector_count);
        return GlvisRowStatus::short_lump;
    }
    bits::from_bytes(lump.subspan(row * row_bytes, row_bytes), subsector_count, out);
    return GlvisRowStatus::decoded;
}

void encode_glvis_rows(std::span<const uint64_t> rows, size_t subsector_count, std::vector<uint8_t>& out)
{
    const size_t row_words = bits::words_for(subsector_count);
    const size_t row_bytes = glvis_row_bytes(subsector_count);
    const size_t start = out.size();
    out.resize(start + glvis_lump_size(subsector_count));
    for (size_t i = 0; i < subsector_count; ++i)
        bits::to_bytes(rows.subspan(i * row_words, row_words), subsector_count,
                       std::span<uint8_t>(out).subspan(start + i * row_bytes, row_bytes));
}

} // namespace pvs
