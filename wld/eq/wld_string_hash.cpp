#include "wld/eq/wld_string_hash.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace pvs::eq {

void wld_xor(std::span<uint8_t> bytes)
{
    for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] ^= kWldStringKey[i % kWldStringKey.size()];
}

std::vector<char> decode_string_hash(std::span<const uint8_t> encoded)
{
    std::vector<uint8_t> decoded(encoded.begin(), encoded.end());
    wld_xor(decoded);
    // Padding (and anything else after the last NUL) is not part of any string.
    const auto last_nul = std::find(decoded.rbegin(), decoded.rend(), uint8_t{0});
    decoded.resize(static_cast<size_t>(decoded.rend() - last_nul));
    return std::vector<char>(decoded.begin(), decoded.end());
}

std::vector<uint8_t> encode_string_hash(std::span<const char> decoded)
{
    std::vector<uint8_t> encoded(decoded.begin(), decoded.end());
    wld_xor(encoded);
    encoded.resize((encoded.size() + 3) / 4 * 4, 0); // raw zeros, not encoded (as LQ and QL write)
    return encoded;
}

std::string decode_wld_string(std::span<const uint8_t> encoded)
{
    std::vector<uint8_t> decoded(encoded.begin(), encoded.end());
    wld_xor(decoded);
    const auto nul = std::find(decoded.begin(), decoded.end(), uint8_t{0});
    return std::string(decoded.begin(), nul);
}

std::vector<uint8_t> encode_wld_string(std::string_view text)
{
    if (text.find('\0') != std::string_view::npos)
        throw std::invalid_argument("a WLD string cannot contain a NUL");
    std::vector<uint8_t> encoded(text.begin(), text.end());
    encoded.push_back(0);
    wld_xor(encoded);
    return encoded;
}

std::optional<std::string_view> wld_string_at(std::span<const char> strings, int32_t name_ref)
{
    if (name_ref >= 0)
        return std::string_view{};
    const uint64_t offset = uint64_t(-int64_t{name_ref}); // -INT32_MIN does not fit an i32
    if (offset >= strings.size())
        return std::nullopt;
    const auto begin = strings.begin() + static_cast<std::ptrdiff_t>(offset);
    return std::string_view(&*begin, static_cast<size_t>(std::find(begin, strings.end(), '\0') - begin));
}

int32_t WldStringTable::add(std::string_view text)
{
    if (text.empty())
        return 0;
    if (text.find('\0') != std::string_view::npos)
        throw std::invalid_argument("a WLD string cannot contain a NUL");
    const auto found = refs_.find(std::string(text));
    if (found != refs_.end())
        return found->second;
    if (data_.size() + text.size() + 1 > size_t(std::numeric_limits<int32_t>::max()))
        throw std::invalid_argument("the WLD string hash would pass 2^31 - 1 bytes");
    const auto ref = -static_cast<int32_t>(data_.size());
    data_.insert(data_.end(), text.begin(), text.end());
    data_.push_back('\0');
    refs_.emplace(std::string(text), ref);
    return ref;
}

} // namespace pvs::eq
