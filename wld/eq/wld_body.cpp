#include "wld/eq/wld_body.h"

#include "visibility/file_error.h"
#include "wld/eq/wld_string_hash.h"

#include <algorithm>
#include <cstdio>

namespace pvs::eq {

namespace {

// "vertex" or "vertex 3": a repeated field carries its index.
std::string indexed(const char* what, int64_t index)
{
    return index < 0 ? std::string(what) : std::string(what) + " " + std::to_string(index);
}

} // namespace

std::string wld_hex(uint32_t value)
{
    char text[16];
    std::snprintf(text, sizeof text, "0x%02X", value);
    return text;
}

std::string wld_type_label(uint32_t type)
{
    const char* name = wld_fragment_type_name(type);
    return wld_hex(type) + (*name ? " " : "") + name;
}

std::string wld_fragment_label(uint32_t number, uint32_t type)
{
    return "fragment " + std::to_string(number) + " (" + wld_type_label(type) + ")";
}

// ---- WldBodyReader ----

WldBodyReader::WldBodyReader(const WldFile& wld, uint32_t number, uint32_t expected_type)
    : wld_(wld), number_(number)
{
    const WldFragment& f = wld.fragment(number); // std::out_of_range outside the file
    type_ = f.type; // errors name the type the fragment has
    body_offset_ = f.body_offset;
    body_size_ = f.body_size;
    // Bounds first: a hand-made WldFragment may put its body before the 8-byte header could fit,
    // and the type field's offset below is computed from it.
    const uint64_t size = wld.bytes.size();
    if (f.body_offset < kWldFragmentHeaderSize)
        fail(f.body_offset, "fragment body starts at " + std::to_string(f.body_offset) + ", before its " +
                                std::to_string(kWldFragmentHeaderSize) + "-byte header could fit");
    if (f.body_offset > size || f.body_size > size - f.body_offset)
        fail(f.body_offset, "fragment body runs past the end of the data (" + std::to_string(f.body_size) +
                                " bytes needed, " + std::to_string(f.body_offset > size ? 0 : size - f.body_offset) +
                                " available)");
    if (f.type != expected_type)
        fail(f.body_offset - kWldFragmentHeaderSize + 4, "expected a " + wld_type_label(expected_type) + " fragment");
}

void WldBodyReader::fail(uint64_t offset, const std::string& reason) const
{
    throw FileError(wld_.name, offset, wld_fragment_label(number_, type_) + ": " + reason);
}

void WldBodyReader::fail_past_end(uint64_t length, const char* what, int64_t index) const
{
    fail(at(), indexed(what, index) + " runs past the end of the fragment (" + std::to_string(length) +
                   " bytes needed, " + std::to_string(left()) + " left)");
}

glm::vec2 WldBodyReader::vec2(const char* what, int64_t index)
{
    const auto x = read<float>(what, index); // named: the order of brace-init reads is then plain
    const auto y = read<float>(what, index);
    return {x, y};
}

glm::vec3 WldBodyReader::vec3(const char* what, int64_t index)
{
    const glm::vec2 xy = vec2(what, index);
    const auto z = read<float>(what, index);
    return {xy, z};
}

glm::vec4 WldBodyReader::vec4(const char* what, int64_t index)
{
    const glm::vec3 xyz = vec3(what, index);
    const auto w = read<float>(what, index);
    return {xyz, w};
}

void WldBodyReader::check_count(uint64_t count, uint64_t count_at, uint64_t min_bytes, const char* what,
                                int64_t index) const
{
    // Divided, not multiplied: count * min_bytes could overflow for a hostile count.
    if (count > left() / std::max<uint64_t>(min_bytes, 1))
        fail(count_at, indexed(what, index) + " " + std::to_string(count) + " does not fit in the fragment (" +
                           std::to_string(left()) + " bytes left, at least " + std::to_string(min_bytes) +
                           " per element)");
}

uint32_t WldBodyReader::count(const char* what, uint64_t min_bytes, int64_t index)
{
    const uint64_t count_at = at();
    const auto value = read<uint32_t>(what, index);
    check_count(value, count_at, min_bytes, what, index);
    return value;
}

std::vector<uint32_t> WldBodyReader::u32s(uint32_t count, const char* what, int64_t index)
{
    const auto raw = bytes(uint64_t{count} * 4, what, index);
    std::vector<uint32_t> values(count);
    if (count != 0) // memcpy from/to a null pointer is undefined even for 0 bytes
        std::memcpy(values.data(), raw.data(), raw.size()); // little-endian host
    return values;
}

std::vector<glm::vec3> WldBodyReader::vec3s(uint32_t count, const char* what)
{
    check_count(count, at(), 12, what); // before reserving: a hostile count must not allocate
    std::vector<glm::vec3> values;
    values.reserve(count);
    for (uint32_t i = 0; i < count; ++i)
        values.push_back(vec3(what, i));
    return values;
}

int32_t WldBodyReader::fragment_ref(const char* what, uint32_t target_type, int64_t index)
{
    const uint64_t ref_at = at();
    const auto ref = read<int32_t>(what, index);
    // Built only for an error: references are read once per palette entry and frame.
    const auto name = [&] { return indexed(what, index) + " " + std::to_string(ref); };
    if (ref > 0 && uint32_t(ref) > wld_.fragments.size())
        fail(ref_at, name() + " is out of range (the file has " + std::to_string(wld_.fragments.size()) +
                         " fragments)");
    if (ref > 0 && uint32_t(ref) >= number_)
        fail(ref_at, name() + " is a forward reference (it must name an earlier fragment)");
    if (ref > 0 && target_type != kWldAnyFragmentType && wld_.fragments[uint32_t(ref) - 1].type != target_type)
        fail(ref_at, name() + " names " + wld_fragment_label(uint32_t(ref), wld_.fragments[uint32_t(ref) - 1].type) +
                         ", not a " + wld_type_label(target_type));
    if (ref < 0 && !wld_string_at(wld_.strings, ref))
        fail(ref_at, name() + " names a string outside the string hash (" + std::to_string(wld_.strings.size()) +
                         " bytes)");
    return ref;
}

std::vector<int32_t> WldBodyReader::fragment_refs(uint32_t count, const char* what, uint32_t target_type)
{
    check_count(count, at(), 4, what); // before reserving: a hostile count must not allocate
    std::vector<int32_t> refs;
    refs.reserve(count);
    for (uint32_t i = 0; i < count; ++i)
        refs.push_back(fragment_ref(what, target_type, i));
    return refs;
}

} // namespace pvs::eq
