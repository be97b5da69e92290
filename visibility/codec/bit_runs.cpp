#include "visibility/codec/bit_runs.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <bit>

namespace pvs {
namespace {

void put_varint(uint64_t value, std::vector<uint8_t>& out)
{
    while (value >= 0x80) {
        out.push_back(uint8_t(value | 0x80));
        value >>= 7;
    }
    out.push_back(uint8_t(value));
}

// Reads the varint at in[i], advancing i. False when `in` ends inside it or it is longer than
// 64 bits can hold.
bool get_varint(std::span<const uint8_t> in, size_t& i, uint64_t& value)
{
    value = 0;
    for (unsigned shift = 0;; shift += 7) {
        if (i >= in.size() || shift > 63)
            return false;
        const uint8_t byte = in[i++];
        value |= uint64_t(byte & 0x7f) << shift;
        if (!(byte & 0x80))
            return true;
    }
}

// Sets bits [begin, end) of `out`.
void set_range(std::span<uint64_t> out, size_t begin, size_t end)
{
    if (begin >= end)
        return;
    const size_t first = begin / 64, last = (end - 1) / 64;
    const uint64_t head = ~uint64_t{0} << (begin % 64);
    const uint64_t tail = ~uint64_t{0} >> (63 - (end - 1) % 64);
    if (first == last) {
        out[first] |= head & tail;
        return;
    }
    out[first] |= head;
    std::fill(out.begin() + ptrdiff_t(first + 1), out.begin() + ptrdiff_t(last), ~uint64_t{0});
    out[last] |= tail;
}

// The first bit at or after `from` (below bit_count) whose value differs from `value`, or bit_count.
size_t next_change(std::span<const uint64_t> row, size_t bit_count, size_t from, bool value)
{
    size_t word = from / 64;
    uint64_t w = (value ? ~row[word] : row[word]) & (~uint64_t{0} << (from % 64));
    while (w == 0) {
        if (++word >= row.size() || word * 64 >= bit_count)
            return bit_count;
        w = value ? ~row[word] : row[word];
    }
    return std::min(bit_count, word * 64 + size_t(std::countr_zero(w)));
}

} // namespace

void encode_bit_runs(std::span<const uint64_t> row, size_t bit_count, std::vector<uint8_t>& out)
{
    size_t at = 0;
    bool value = false;
    while (at < bit_count) {
        const size_t end = next_change(row, bit_count, at, value);
        put_varint(end - at, out);
        at = end;
        value = !value;
    }
    if (bit_count == 0)
        put_varint(0, out);
}

bool decode_bit_runs(std::span<const uint8_t> in, size_t bit_count, std::span<uint64_t> out)
{
    std::fill(out.begin(), out.begin() + ptrdiff_t(bits::words_for(bit_count)), 0);
    size_t at = 0, i = 0;
    bool value = false;
    while (at < bit_count) {
        uint64_t run = 0;
        if (!get_varint(in, i, run))
            return false;
        if (run > bit_count - at) {
            if (value)
                set_range(out, at, bit_count);
            return false;
        }
        if (value)
            set_range(out, at, at + run);
        at += run;
        value = !value;
    }
    return true;
}

bool bit_runs_test(std::span<const uint8_t> in, size_t bit_count, size_t bit)
{
    if (bit >= bit_count)
        return false;
    size_t at = 0, i = 0;
    bool value = false;
    while (at < bit_count) {
        uint64_t run = 0;
        if (!get_varint(in, i, run))
            return false; // decode_bit_runs leaves the rest clear
        if (run > bit_count - at)
            return value; // decode_bit_runs sets the rest when the last run overruns set
        if (bit < at + run)
            return value;
        at += run;
        value = !value;
    }
    return false;
}

} // namespace pvs
