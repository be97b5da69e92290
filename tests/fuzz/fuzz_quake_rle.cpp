// libFuzzer target: the Quake PVS row codec (visibility/codec/quake_rle.h). The first two bytes
// choose the row's bit count, the rest is compressed input. Decoding stays inside the input and
// the row; a decoded row encodes within quake_rle_bound and decodes back to itself.
#include "tests/fuzz/fuzz_support.h"
#include "visibility/bit_row.h"
#include "visibility/codec/quake_rle.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    if (size < 2)
        return 0;
    const size_t bit_count = size_t(data[0]) | size_t(data[1]) << 8; // 0 .. 65535
    const std::span<const uint8_t> in(data + 2, size - 2);
    const size_t words = bits::words_for(bit_count);
    std::vector<uint64_t> row(words, ~uint64_t(0));
    const QuakeRleResult result = decode_quake_rle(in, bit_count, row);
    fuzz::fuzz_check(result.consumed <= in.size(), "consumed within the input");
    if (bit_count % 64 != 0)
        fuzz::fuzz_check((row.back() >> (bit_count % 64)) == 0, "padding bits cleared");
    std::vector<uint8_t> packed;
    encode_quake_rle(row, bit_count, packed);
    fuzz::fuzz_check(packed.size() <= quake_rle_bound(bit_count), "encoded within the bound");
    std::vector<uint64_t> again(words, ~uint64_t(0));
    const QuakeRleResult back = decode_quake_rle(packed, bit_count, again);
    fuzz::fuzz_check(back.complete && back.consumed == packed.size(), "the encoder's row is complete");
    fuzz::fuzz_check(again == row, "Quake RLE round-trips");
    return 0;
}
