// libFuzzer target: the GL_PVS row codec (visibility/codec/glvis_rows.h). The first two bytes
// choose the subsector count, the rest is the lump; every row is decoded, and a whole lump
// decoded row by row encodes back to its own first glvis_lump_size bytes (padding bits zeroed).
#include "tests/fuzz/fuzz_support.h"
#include "visibility/bit_row.h"
#include "visibility/codec/glvis_rows.h"

#include <cstring>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    if (size < 2)
        return 0;
    const size_t count = size_t(data[0]) | size_t(data[1] & 0x0F) << 8; // 0 .. 4095 subsectors
    const std::span<const uint8_t> lump(data + 2, size - 2);
    const size_t words = bits::words_for(count);
    std::vector<uint64_t> rows(words * (count + 1), ~uint64_t(0));
    bool complete = true;
    for (size_t r = 0; r <= count; ++r) { // row `count` is past the end: must be refused, filled
        const GlvisRowStatus status = decode_glvis_row(lump, count, r, std::span(rows).subspan(r * words, words));
        if (r == count)
            fuzz::fuzz_check(status != GlvisRowStatus::decoded, "a row past the count is not decoded");
        else
            complete = complete && status == GlvisRowStatus::decoded;
    }
    if (count > 0 && complete) {
        std::vector<uint8_t> out;
        encode_glvis_rows(std::span(rows).first(words * count), count, out);
        fuzz::fuzz_check(out.size() == glvis_lump_size(count), "encoded lump size");
        const size_t row_bytes = glvis_row_bytes(count);
        for (size_t r = 0; r < count; ++r)
            for (size_t b = 0; b < row_bytes; ++b) {
                uint8_t expected = lump[r * row_bytes + b];
                if (b == row_bytes - 1 && count % 8 != 0)
                    expected = uint8_t(expected & ((1u << (count % 8)) - 1));
                fuzz::fuzz_check(out[r * row_bytes + b] == expected, "GL_PVS rows round-trip");
            }
    }
    return 0;
}
