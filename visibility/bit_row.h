// Bit rows: one bit per region, stored LSB-first in 64-bit words (bit i lives in word i/64 at
// position i%64). This is the decoded form of every PVS row, whatever the file stored.
//
// Free functions over spans, so hot code works on caller-owned flat buffers with no allocation;
// BitSet is the owning convenience type for code that is not hot.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace pvs::bits {

constexpr size_t words_for(size_t bit_count) { return (bit_count + 63) / 64; }
constexpr size_t bytes_for(size_t bit_count) { return (bit_count + 7) / 8; }

inline bool test(std::span<const uint64_t> words, size_t i) { return (words[i >> 6] >> (i & 63)) & 1u; }
inline void set(std::span<uint64_t> words, size_t i) { words[i >> 6] |= uint64_t{1} << (i & 63); }
inline void clear(std::span<uint64_t> words, size_t i) { words[i >> 6] &= ~(uint64_t{1} << (i & 63)); }

// Set bits of one word, inline. The build targets baseline x86-64 (no -mpopcnt), where
// std::popcount is a call into libgcc: hot loops that count a word at a time use this instead.
constexpr uint32_t popcount(uint64_t x)
{
    x = x - ((x >> 1) & 0x5555555555555555u);
    x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu;
    return uint32_t((x * 0x0101010101010101u) >> 56);
}

inline size_t count(std::span<const uint64_t> words)
{
    size_t total = 0;
    for (uint64_t w : words)
        total += popcount(w); // inline: the culler counts a row every frame
    return total;
}

// Calls visit(i) for every set bit i in ascending order.
template <class Visit>
void for_each_set(std::span<const uint64_t> words, Visit&& visit)
{
    for (size_t w = 0; w < words.size(); ++w) {
        uint64_t word = words[w];
        while (word != 0) {
            visit(w * 64 + static_cast<size_t>(std::countr_zero(word)));
            word &= word - 1;
        }
    }
}

// Sets bits [0, bit_count) and clears the padding bits above bit_count.
void fill(std::span<uint64_t> words, size_t bit_count);

// Byte rows as Quake and glVIS store them (bit i in byte i/8 at position i%8). Bits at or past
// bit_count are dropped (files may leave garbage in the padding of the last byte).
void from_bytes(std::span<const uint8_t> bytes, size_t bit_count, std::span<uint64_t> words);
void to_bytes(std::span<const uint64_t> words, size_t bit_count, std::span<uint8_t> bytes);

} // namespace pvs::bits

namespace pvs {

// Owning bit set of a fixed size, for code that is not on a per-frame path.
class BitSet {
public:
    BitSet() = default;
    explicit BitSet(size_t bit_count) : size_(bit_count), words_(bits::words_for(bit_count), 0) {}

    size_t size() const { return size_; }
    bool test(size_t i) const { return bits::test(words_, i); }
    void set(size_t i) { bits::set(words_, i); }
    void clear(size_t i) { bits::clear(words_, i); }
    size_t count() const { return bits::count(words_); }
    std::span<uint64_t> words() { return words_; }
    std::span<const uint64_t> words() const { return words_; }
    bool operator==(const BitSet&) const = default;

private:
    size_t size_ = 0;
    std::vector<uint64_t> words_;
};

} // namespace pvs
