// Reading and writing the bytes of one EverQuest WLD fragment body (../shared/formats/eq-s3d-wld.md
// §2.3 fragment layout, §2.4 references, §7.4 writing rules): the one cursor every typed fragment
// parser (wld_file.cpp, wld_material.cpp, wld_mesh.cpp) reads with, and the one little-endian
// builder every fragment writer and write_wld write with. Internal to wld/eq: the public
// contracts are in wld_file.h, wld_material.h and wld_mesh.h.
//
// WldBodyReader reads fragment `number` front to back, starting at its name_ref (body offset 0).
//  - The constructor throws std::out_of_range for a number outside the file, and FileError when
//    the fragment's body lies outside the WLD bytes or starts before its 8-byte header could
//    fit (parse_wld checks that; a hand-made WldFile may not have been), or when it is not of
//    the expected type.
//  - No read leaves the body: a field that does not fit fails before anything is read.
//  - Counts are checked against the bytes left before anyone reserves memory for them, so a
//    count of 2^32 - 1 fails cleanly instead of allocating.
//  - Every failure throws pvs::FileError(wld.name, absolute offset in the WLD bytes, reason) with
//    a reason starting "fragment N (0xTT name): " and naming the field (and its index, when the
//    field repeats), e.g. "fragment 12 (0x36 mesh): vertex 3 runs past the end of the fragment
//    (2 bytes needed, 0 left)".
//
// WldByteWriter appends little-endian values and pads with zeros to a multiple of 4 (§2.3, §7.4).
// It throws std::invalid_argument when a count does not fit its u32 field.
//
// Both assume a little-endian host, as wld/common/byte_reader.h asserts.
#pragma once

#include "wld/eq/wld_file.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace pvs::eq {

// "0x22".
std::string wld_hex(uint32_t value);
// "0x22 region" ("0x99" for a type pvscope has no name for).
std::string wld_type_label(uint32_t type);
// "fragment 12 (0x36 mesh)": how every error inside a fragment starts.
std::string wld_fragment_label(uint32_t number, uint32_t type);

// True when no component is NaN or infinite: the check parsers make on positions and planes.
inline bool all_finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// fragment_ref's target type for a reference that may name a fragment of any type.
inline constexpr uint32_t kWldAnyFragmentType = 0;

class WldBodyReader {
public:
    WldBodyReader(const WldFile& wld, uint32_t number, uint32_t expected_type);

    const WldFile& wld() const { return wld_; }
    uint32_t number() const { return number_; }
    uint64_t at() const { return body_offset_ + pos_; } // absolute offset of the next byte
    uint64_t left() const { return body_size_ - pos_; }

    // Throws FileError at the absolute `offset` with "fragment N (0xTT name): " + reason.
    [[noreturn]] void fail(uint64_t offset, const std::string& reason) const;

    // The next `length` bytes. `what` (and `index` when >= 0) name the field in the error.
    std::span<const uint8_t> bytes(uint64_t length, const char* what, int64_t index = -1)
    {
        if (length > left())
            fail_past_end(length, what, index);
        const auto span = wld_.bytes.subspan(at(), length);
        pos_ += length;
        return span;
    }

    // One little-endian u8 / i8 / u16 / i16 / u32 / i32 / f32 (any arithmetic type).
    template <class T>
    T read(const char* what, int64_t index = -1)
    {
        static_assert(std::is_arithmetic_v<T>);
        T value;
        std::memcpy(&value, bytes(sizeof(T), what, index).data(), sizeof(T)); // little-endian host
        return value;
    }

    glm::vec2 vec2(const char* what, int64_t index = -1);
    glm::vec3 vec3(const char* what, int64_t index = -1);
    glm::vec4 vec4(const char* what, int64_t index = -1);

    // Fails at `count_at` unless `count` elements of at least `min_bytes` (>= 1; 0 counts as 1)
    // each fit in what is left of the body. Call it before reserving anything for them.
    void check_count(uint64_t count, uint64_t count_at, uint64_t min_bytes, const char* what,
                     int64_t index = -1) const;
    // Reads a u32 count and check_count's it at its own offset.
    uint32_t count(const char* what, uint64_t min_bytes, int64_t index = -1);

    // `count` values read back to back; the count is checked against the bytes left before
    // anything is reserved (at the first element's offset). vec3s names element i "`what` i".
    std::vector<uint32_t> u32s(uint32_t count, const char* what, int64_t index = -1);
    std::vector<glm::vec3> vec3s(uint32_t count, const char* what);

    // A fragment reference (§2.4): 0, an EARLIER fragment (of `target_type` unless that is
    // kWldAnyFragmentType), or a negative reference by name whose string exists.
    int32_t fragment_ref(const char* what, uint32_t target_type, int64_t index = -1);
    // `count` references, the i-th named "`what` i" in errors; the count is checked first, as in
    // vec3s.
    std::vector<int32_t> fragment_refs(uint32_t count, const char* what, uint32_t target_type);

private:
    [[noreturn]] void fail_past_end(uint64_t length, const char* what, int64_t index) const;

    const WldFile& wld_;
    uint32_t number_;
    uint32_t type_;
    uint64_t body_offset_ = 0;
    uint64_t body_size_ = 0;
    uint64_t pos_ = 0;
};

// items.size() as a u32 count; std::invalid_argument ("what: more than 2^32 - 1 elements") when
// it does not fit.
template <class Container>
uint32_t wld_count32(const Container& items, const char* what)
{
    if (items.size() > std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument(std::string(what) + ": more than 2^32 - 1 elements");
    return static_cast<uint32_t>(items.size());
}

class WldByteWriter {
public:
    void reserve(size_t bytes) { out_.reserve(bytes); }
    size_t size() const { return out_.size(); }

    template <class T>
    void put(T value)
    {
        static_assert(std::is_arithmetic_v<T>);
        uint8_t raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T)); // little-endian host
        out_.insert(out_.end(), raw, raw + sizeof(T));
    }
    void put(glm::vec2 v)
    {
        put(v.x);
        put(v.y);
    }
    void put(glm::vec3 v)
    {
        put(v.x);
        put(v.y);
        put(v.z);
    }
    void put(glm::vec4 v)
    {
        put(glm::vec3(v));
        put(v.w);
    }
    // Every element of a container of values put() takes, in order.
    template <class Container>
    void put_each(const Container& values)
    {
        for (const auto& v : values)
            put(v);
    }
    // The container's size as a u32 (wld_count32).
    template <class Container>
    void put_count(const Container& items, const char* what)
    {
        put(wld_count32(items, what));
    }
    void put_bytes(std::span<const uint8_t> bytes) { out_.insert(out_.end(), bytes.begin(), bytes.end()); }
    // Zeros up to the next multiple of 4 (§2.3, §7.4).
    void pad4() { out_.resize((out_.size() + 3) / 4 * 4, 0); }
    // The bytes, padded to a multiple of 4: a fragment body (or a whole file).
    std::vector<uint8_t> finish()
    {
        pad4();
        return std::move(out_);
    }

private:
    std::vector<uint8_t> out_;
};

} // namespace pvs::eq
