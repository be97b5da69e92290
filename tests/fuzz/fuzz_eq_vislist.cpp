// libFuzzer target: the EverQuest VISLIST codec (visibility/codec/eq_vislist.h), byte and word
// forms. The first two bytes choose the region count, the third the form; the rest is the list.
// Decoding never reads past the list; a decoded row encodes (packed and plain, within the
// bound and at the size the size functions predict) and decodes back to itself.
#include "tests/fuzz/fuzz_support.h"
#include "visibility/bit_row.h"
#include "visibility/codec/eq_vislist.h"

#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    if (size < 3)
        return 0;
    const size_t regions = size_t(data[0]) | size_t(data[1]) << 8; // 0 .. 65535
    const bool byte_form = (data[2] & 1) == 0;
    const std::span<const uint8_t> in(data + 3, size - 3);
    const size_t words = bits::words_for(regions);
    std::vector<uint64_t> row(words, ~uint64_t(0));
    const EqVislistResult result =
        byte_form ? decode_eq_vislist_bytes(in, regions, row) : decode_eq_vislist_words(in, regions, row);
    fuzz::fuzz_check(result.consumed <= in.size(), "consumed within the input");
    fuzz::fuzz_check(!result.well_formed || result.consumed == in.size(), "well formed means all consumed");
    if (regions % 64 != 0)
        fuzz::fuzz_check((row.back() >> (regions % 64)) == 0, "padding bits cleared");
    for (bool packed : {true, false}) {
        std::vector<uint8_t> list;
        encode_eq_vislist_bytes(row, regions, list, packed);
        fuzz::fuzz_check(list.size() == eq_vislist_bytes_size(row, regions, packed), "predicted byte size");
        fuzz::fuzz_check(list.size() <= eq_vislist_bytes_bound(regions), "byte form within the bound");
        std::vector<uint64_t> again(words, ~uint64_t(0));
        const EqVislistResult back = decode_eq_vislist_bytes(list, regions, again);
        fuzz::fuzz_check(back.well_formed && again == row, "byte form round-trips");
    }
    std::vector<uint8_t> list;
    if (encode_eq_vislist_words(row, regions, list)) {
        fuzz::fuzz_check(list.size() == eq_vislist_words_size(row, regions), "predicted word size");
        std::vector<uint64_t> again(words, ~uint64_t(0));
        const EqVislistResult back = decode_eq_vislist_words(list, regions, again);
        fuzz::fuzz_check(back.well_formed && again == row, "word form round-trips");
    }
    return 0;
}
