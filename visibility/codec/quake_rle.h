// Quake PVS row compression (BSP 29 VISIBILITY lump, ../shared/formats/quake-doom-hepvs.md §1.10).
//
// A row is bytes_for(bit_count) bytes, bit j of the row in byte j/8 at position j%8.
// Compressed form: a non-zero byte is copied; a zero byte is followed by a count c of zero
// BYTES (not bits). Rows are compressed one at a time; runs never cross rows.
//
// Both functions work on the decoded form as 64-bit words (visibility/bit_row.h), so a PVS row
// goes from the file to the culler with no intermediate byte buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

struct QuakeRleResult {
    bool complete = false; // false: the input ended before the row was full (the rest is zero)
    size_t consumed = 0;   // compressed bytes read
};

// Decodes one row of bit_count bits from `in` into `out` (words_for(bit_count) words, fully
// overwritten; padding bits past bit_count are cleared). Safe on untrusted input: a zero-run
// count larger than the room left in the row is clamped (as robust engines do), and reading
// stops at the end of `in`. A zero run with no count byte is incomplete.
QuakeRleResult decode_quake_rle(std::span<const uint8_t> in, size_t bit_count, std::span<uint64_t> out);

// Bit `bit` (< bit_count) of the row decode_quake_rle would give, read without decoding the rest:
// the walk stops at the byte that holds it (a column of a PVS costs a walk per row, not a row).
bool quake_rle_test(std::span<const uint8_t> in, size_t bit_count, size_t bit);

// Appends the compressed form of a row of bit_count bits to `out`. Zero runs are split into
// pieces of at most 255 bytes and never run past the row, exactly as id's and ericw's vis write them.
void encode_quake_rle(std::span<const uint64_t> row, size_t bit_count, std::vector<uint8_t>& out);

// Largest compressed size of a row of bit_count bits.
constexpr size_t quake_rle_bound(size_t bit_count) { return 2 * ((bit_count + 7) / 8); }

} // namespace pvs
