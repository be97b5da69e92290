#include "visibility/codec/quake_rle.h"

#include "visibility/bit_row.h"

#include <algorithm>

namespace pvs {

QuakeRleResult decode_quake_rle(std::span<const uint8_t> in, size_t bit_count, std::span<uint64_t> out)
{
    std::fill(out.begin(), out.end(), 0);
    const size_t row_bytes = bits::bytes_for(bit_count);
    size_t produced = 0;
    size_t pos = 0;
    while (produced < row_bytes) {
        if (pos >= in.size())
            return {false, pos};
        const uint8_t b = in[pos++];
        if (b != 0) {
            out[produced >> 3] |= uint64_t{b} << ((produced & 7) * 8);
            ++produced;
            continue;
        }
        if (pos >= in.size())
            return {false, pos};
        produced += std::min<size_t>(in[pos++], row_bytes - produced);
    }
    if (bit_count % 64 != 0)
        out[bit_count / 64] &= (uint64_t{1} << (bit_count % 64)) - 1;
    return {true, pos};
}

bool quake_rle_test(std::span<const uint8_t> in, size_t bit_count, size_t bit)
{
    if (bit >= bit_count)
        return false;
    const size_t row_bytes = bits::bytes_for(bit_count), target = bit / 8;
    size_t produced = 0, pos = 0;
    while (produced < row_bytes && pos < in.size()) {
        const uint8_t b = in[pos++];
        if (b != 0) {
            if (produced == target)
                return (b >> (bit % 8)) & 1;
            ++produced;
            continue;
        }
        if (pos >= in.size())
            return false;
        produced += std::min<size_t>(in[pos++], row_bytes - produced);
        if (produced > target)
            return false; // inside a zero run
    }
    return false; // the row ended early: the rest is zero
}

void encode_quake_rle(std::span<const uint64_t> row, size_t bit_count, std::vector<uint8_t>& out)
{
    const size_t row_bytes = bits::bytes_for(bit_count);
    auto byte_at = [&](size_t i) {
        uint8_t b = static_cast<uint8_t>(row[i >> 3] >> ((i & 7) * 8));
        if (i == row_bytes - 1 && bit_count % 8 != 0)
            b &= static_cast<uint8_t>((1u << (bit_count % 8)) - 1); // never write padding bits
        return b;
    };
    for (size_t i = 0; i < row_bytes;) {
        const uint8_t b = byte_at(i);
        if (b != 0) {
            out.push_back(b);
            ++i;
            continue;
        }
        // The run, a zero word at a time where one lies whole before the last byte (whose padding
        // bits byte_at masks): sparse rows are mostly zero words.
        size_t run = 1;
        while (i + run < row_bytes && run < 255) {
            const size_t j = i + run;
            if ((j & 7) == 0 && j + 8 < row_bytes && run <= 255 - 8 && row[j >> 3] == 0) {
                run += 8;
                continue;
            }
            if (byte_at(j) != 0)
                break;
            ++run;
        }
        out.push_back(0);
        out.push_back(static_cast<uint8_t>(run));
        i += run;
    }
}

} // namespace pvs
