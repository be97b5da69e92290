#include "visibility/bit_row.h"

#include <algorithm>

namespace pvs::bits {

void fill(std::span<uint64_t> words, size_t bit_count)
{
    std::fill(words.begin(), words.end(), 0);
    const size_t full = bit_count / 64;
    std::fill(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(full), ~uint64_t{0});
    if (bit_count % 64 != 0)
        words[full] = (uint64_t{1} << (bit_count % 64)) - 1;
}

void from_bytes(std::span<const uint8_t> bytes, size_t bit_count, std::span<uint64_t> words)
{
    std::fill(words.begin(), words.end(), 0);
    const size_t byte_count = std::min(bytes.size(), bytes_for(bit_count));
    for (size_t i = 0; i < byte_count; ++i)
        words[i >> 3] |= uint64_t{bytes[i]} << ((i & 7) * 8);
    // Drop padding bits past the last region.
    if (bit_count % 64 != 0 && bit_count / 64 < words.size())
        words[bit_count / 64] &= (uint64_t{1} << (bit_count % 64)) - 1;
}

void to_bytes(std::span<const uint64_t> words, size_t bit_count, std::span<uint8_t> bytes)
{
    const size_t byte_count = std::min(bytes.size(), bytes_for(bit_count));
    for (size_t i = 0; i < byte_count; ++i)
        bytes[i] = static_cast<uint8_t>(words[i >> 3] >> ((i & 7) * 8));
    if (bit_count % 8 != 0 && byte_count == bytes_for(bit_count))
        bytes[byte_count - 1] &= static_cast<uint8_t>((1u << (bit_count % 8)) - 1);
}

} // namespace pvs::bits
