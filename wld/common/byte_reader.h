// Bounds-checked little-endian reading of untrusted bytes.
//
// Every read checks the range first and throws pvs::FileError naming the file, the absolute
// offset and what was being read, so a truncated or hostile file can never cause an
// out-of-bounds read. Offsets are absolute within the buffer the reader was made for.
#pragma once

#include "visibility/file_error.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>

namespace pvs {

class ByteReader {
public:
    ByteReader(std::span<const uint8_t> bytes, std::string file) : bytes_(bytes), file_(std::move(file)) {}

    size_t size() const { return bytes_.size(); }
    const std::string& file() const { return file_; }

    // Throws unless [offset, offset + length) lies inside the buffer.
    void require(uint64_t offset, uint64_t length, const char* what) const
    {
        if (offset > bytes_.size() || length > bytes_.size() - offset)
            fail(offset, std::string(what) + " runs past the end of the data (" + std::to_string(length) +
                             " bytes needed, " + std::to_string(offset > bytes_.size() ? 0 : bytes_.size() - offset) +
                             " available)");
    }

    template <class T>
    T read(uint64_t offset, const char* what) const
    {
        static_assert(std::is_arithmetic_v<T>);
        require(offset, sizeof(T), what);
        T value;
        std::memcpy(&value, bytes_.data() + offset, sizeof(T)); // the formats are little-endian, as is the host
        return value;
    }

    std::span<const uint8_t> bytes(uint64_t offset, uint64_t length, const char* what) const
    {
        require(offset, length, what);
        return bytes_.subspan(offset, length);
    }

    [[noreturn]] void fail(uint64_t offset, const std::string& reason) const { throw FileError(file_, offset, reason); }

private:
    std::span<const uint8_t> bytes_;
    std::string file_;
};

static_assert(std::endian::native == std::endian::little, "the readers assume a little-endian host");

} // namespace pvs
