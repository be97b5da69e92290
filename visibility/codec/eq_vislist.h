// EverQuest region visibility lists (WLD fragment 0x22 VisList, ../shared/formats/eq-s3d-wld.md
// §4.3-§4.5, known answers §8.1, encoder rules §8.2).
//
// A VisList is a u16 range_count followed by range_count elements. Fragment flag bit 7 picks
// the element type:
// * set   - BYTE form (§4.4): a run-length list of region runs, NOT a bitmask. A cursor starts at
//           position 0 and each code skips or includes a run of positions:
//             00-3E skip b            3F lo hi  skip u16 LE
//             40-7F skip (b>>3)&7, then include b&7
//             80-BF include (b>>3)&7, then skip b&7
//             C0-FE include b-0xC0    FF lo hi  include u16 LE
// * clear - WORD form (§4.5): range_count u16 LE words, each an explicit 0-based region number
//           (the only interpretation found, quail's; never seen in EverQuest's own files).
// Position p is the p-th 0x22 fragment in file order counted from 0 (BSP region p + 1).
//
// Decoded rows are bit rows of region_count bits (visibility/bit_row.h). Decoders take the raw
// element bytes of ONE list (range_count bytes, or 2 * range_count bytes for the word form),
// never throw, never read out of bounds, never allocate, drop positions >= region_count and
// report a cut-short stream as a result value.
//
// range_count is a u16: a list can hold at most 65535 elements. The encoders return whatever
// the row needs; the CALLER must check that the byte form fits in 65535 bytes (or the word form
// in 65535 words) before writing a fragment. Some readers (LanternExtractor, willeq, eqsage)
// read range_count as i16, so lists of 32768 elements or more are only safe with libeq/quail.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

struct EqVislistResult {
    // false: the stream is malformed (byte form: a 0x3F/0xFF code without its two u16 bytes;
    // word form: an odd trailing byte). Decoding stopped there; what came before is kept.
    bool well_formed = false;
    // Input bytes that belong to complete codes / words (== input size when well_formed).
    size_t consumed = 0;
};

// Decodes a byte-form list into `out` (at least words_for(region_count) words; all of `out` is
// overwritten, padding bits past region_count are zero). Positions >= region_count are dropped;
// the cursor saturates at region_count, so any number of 0x3F FF FF / FF FF FF codes is safe.
// The whole stream is read even after the cursor passes region_count, so `well_formed` covers
// the whole list. An empty list decodes to an empty row (willeq reads range_count = 0 as "no PVS
// data, show everything"; that policy belongs to the caller).
EqVislistResult decode_eq_vislist_bytes(std::span<const uint8_t> in, size_t region_count, std::span<uint64_t> out);

// Appends the byte form of the set bits [0, region_count) of `row` (words_for(region_count)
// words; padding bits are ignored) following §8.2: runs longer than 65535 are split into
// 3F FF FF / FF FF FF pieces, runs of 63 or more use the u16 codes, no trailing skip is written,
// and with `packed` a run of 1-7 followed by a run of 1-7 of the other kind is merged into one
// 0x40-0xBF byte (greedily, left to right, which is optimal). An empty row produces no bytes.
void encode_eq_vislist_bytes(std::span<const uint64_t> row, size_t region_count, std::vector<uint8_t>& out,
                             bool packed = true);

// Exact number of bytes encode_eq_vislist_bytes would append (no allocation).
size_t eq_vislist_bytes_size(std::span<const uint64_t> row, size_t region_count, bool packed = true);

// Upper bound of the byte form of any row of region_count bits: a run of length L never costs
// more than L bytes and the trailing skip costs nothing, so the list is at most region_count
// bytes. The packed form is never longer than the plain form.
constexpr size_t eq_vislist_bytes_bound(size_t region_count) { return region_count; }

// Decodes a word-form list: `in` is the raw 2 * range_count bytes, each u16 LE a 0-based region
// number. Words >= region_count are dropped; duplicates and any order are accepted. An odd
// trailing byte is malformed (ignored; consumed excludes it).
EqVislistResult decode_eq_vislist_words(std::span<const uint8_t> in, size_t region_count, std::span<uint64_t> out);

// Appends the word form (ascending u16 LE region numbers, 2 bytes per set bit of
// [0, region_count)). A word can only name regions 0-65535: if a higher bit is set, nothing is
// appended and the function returns false.
bool encode_eq_vislist_words(std::span<const uint64_t> row, size_t region_count, std::vector<uint8_t>& out);

// Bytes encode_eq_vislist_words appends: 2 * (set bits below region_count). range_count is half.
size_t eq_vislist_words_size(std::span<const uint64_t> row, size_t region_count);

} // namespace pvs
