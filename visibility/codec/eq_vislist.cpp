#include "visibility/codec/eq_vislist.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <bit>

namespace pvs {
namespace {

constexpr size_t max_u16_run = 65535;

// Sets bits [begin, end) a word at a time (include runs can be 65535 long).
void set_range(std::span<uint64_t> words, size_t begin, size_t end)
{
    while (begin < end) {
        const size_t word = begin >> 6;
        const size_t lo = begin & 63;
        const size_t hi = std::min<size_t>(64, lo + (end - begin));
        const uint64_t mask = (hi == 64 ? ~uint64_t{0} : (uint64_t{1} << hi) - 1) & (~uint64_t{0} << lo);
        words[word] |= mask;
        begin += hi - lo;
    }
}

// First position >= from whose bit equals `value`, or bit_count if none. Padding bits past
// bit_count are never reported, whatever they hold.
size_t find_next(std::span<const uint64_t> row, size_t bit_count, size_t from, bool value)
{
    if (from >= bit_count)
        return bit_count;
    const size_t word_count = bits::words_for(bit_count);
    size_t w = from >> 6;
    uint64_t word = (value ? row[w] : ~row[w]) & (~uint64_t{0} << (from & 63));
    for (;;) {
        if (word != 0)
            return std::min(bit_count, w * 64 + static_cast<size_t>(std::countr_zero(word)));
        if (++w >= word_count)
            return bit_count;
        word = value ? row[w] : ~row[w];
    }
}

// Set bits below bit_count (padding ignored).
size_t count_below(std::span<const uint64_t> row, size_t bit_count)
{
    const size_t full = bit_count / 64;
    size_t total = bits::count(row.first(full));
    if (bit_count % 64 != 0)
        total += static_cast<size_t>(std::popcount(row[full] & ((uint64_t{1} << (bit_count % 64)) - 1)));
    return total;
}

// Feeds the §8.2 byte form of a row to sink(uint8_t).
template <class Sink>
void encode_bytes(std::span<const uint64_t> row, size_t region_count, bool packed, Sink&& sink)
{
    // One run in its unpacked form: short code, or u16 code, split at 65535.
    auto emit_run = [&](bool include, size_t len) {
        const uint8_t long_code = include ? 0xFF : 0x3F;
        while (len > max_u16_run) {
            sink(long_code);
            sink(uint8_t{0xFF});
            sink(uint8_t{0xFF});
            len -= max_u16_run;
        }
        if (len >= 63) {
            sink(long_code);
            sink(static_cast<uint8_t>(len & 0xFF));
            sink(static_cast<uint8_t>(len >> 8));
        } else if (len > 0) {
            sink(static_cast<uint8_t>(include ? 0xC0 + len : len));
        }
    };

    // Runs alternate (skip, include, skip, ...). With packing, a run of 1-7 waits here for the
    // next run; if that one is 1-7 too, both become one byte.
    bool pending = false;
    bool pending_include = false;
    size_t pending_len = 0;
    auto run = [&](bool include, size_t len) {
        if (len == 0)
            return; // only the leading skip can be empty
        if (pending) {
            pending = false;
            if (len <= 7) {
                const size_t first = pending_len;
                sink(static_cast<uint8_t>((pending_include ? 0x80 : 0x40) | (first << 3) | len));
                return;
            }
            emit_run(pending_include, pending_len);
        }
        if (packed && len <= 7) {
            pending = true;
            pending_include = include;
            pending_len = len;
            return;
        }
        emit_run(include, len);
    };

    size_t pos = 0;
    for (;;) {
        const size_t start = find_next(row, region_count, pos, true);
        if (start >= region_count)
            break; // the trailing skip is never written
        const size_t end = find_next(row, region_count, start, false);
        run(false, start - pos);
        run(true, end - start);
        pos = end;
    }
    if (pending)
        emit_run(pending_include, pending_len);
}

} // namespace

EqVislistResult decode_eq_vislist_bytes(std::span<const uint8_t> in, size_t region_count, std::span<uint64_t> out)
{
    std::fill(out.begin(), out.end(), 0);
    size_t r = 0; // saturates at region_count: nothing past it can be set
    auto skip = [&](size_t n) { r += std::min(n, region_count - r); };
    auto include = [&](size_t n) {
        const size_t end = r + std::min(n, region_count - r);
        set_range(out, r, end);
        r = end;
    };

    size_t pos = 0;
    while (pos < in.size()) {
        const uint8_t b = in[pos];
        if (b == 0x3F || b == 0xFF) {
            if (in.size() - pos < 3)
                return {false, pos}; // u16 operand cut short: malformed, stop
            const size_t w = size_t{in[pos + 1]} | (size_t{in[pos + 2]} << 8);
            if (b == 0x3F)
                skip(w);
            else
                include(w);
            pos += 3;
            continue;
        }
        ++pos;
        if (b < 0x3F) {
            skip(b);
        } else if (b < 0x80) {
            skip((b >> 3) & 7);
            include(b & 7);
        } else if (b < 0xC0) {
            include((b >> 3) & 7);
            skip(b & 7);
        } else {
            include(b - 0xC0u);
        }
    }
    return {true, pos};
}

void encode_eq_vislist_bytes(std::span<const uint64_t> row, size_t region_count, std::vector<uint8_t>& out,
                             bool packed)
{
    encode_bytes(row, region_count, packed, [&](uint8_t b) { out.push_back(b); });
}

size_t eq_vislist_bytes_size(std::span<const uint64_t> row, size_t region_count, bool packed)
{
    size_t size = 0;
    encode_bytes(row, region_count, packed, [&](uint8_t) { ++size; });
    return size;
}

EqVislistResult decode_eq_vislist_words(std::span<const uint8_t> in, size_t region_count, std::span<uint64_t> out)
{
    std::fill(out.begin(), out.end(), 0);
    const size_t even = in.size() & ~size_t{1};
    for (size_t pos = 0; pos < even; pos += 2) {
        const size_t region = size_t{in[pos]} | (size_t{in[pos + 1]} << 8);
        if (region < region_count)
            bits::set(out, region);
    }
    return {even == in.size(), even};
}

bool encode_eq_vislist_words(std::span<const uint64_t> row, size_t region_count, std::vector<uint8_t>& out)
{
    constexpr size_t word_limit = 65536; // regions a u16 can name
    if (region_count > word_limit && find_next(row, region_count, word_limit, true) < region_count)
        return false;
    bits::for_each_set(row.first(bits::words_for(region_count)), [&](size_t i) {
        if (i < region_count) {
            out.push_back(static_cast<uint8_t>(i & 0xFF));
            out.push_back(static_cast<uint8_t>(i >> 8));
        }
    });
    return true;
}

size_t eq_vislist_words_size(std::span<const uint64_t> row, size_t region_count)
{
    return 2 * count_below(row, region_count);
}

} // namespace pvs
