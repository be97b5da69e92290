// WLD bytes assembled by hand for the tests in tests/wld, from the tables of
// ../shared/formats/eq-s3d-wld.md (§2.1 header, §2.2 string hash, §2.3 fragments) and
// independent of the code under test: nothing here calls wld/eq, so a test that compares a
// parser's or writer's result with these bytes checks the code against the spec, not against
// itself.
//  - Builder: little-endian fields appended one by one (a fragment body, or anything else).
//  - SpecStrings / spec_wld: a whole file from decoded strings and fragment bodies.
//  - put_u16 / put_u32 / put_f32: overwrite one field of a finished file (bad-input tests).
//  - expect_error / parse_fragment: a parse of changed bytes must throw FileError naming
//    "bad.wld", the absolute offset and the problem.
//  - parses / prefixes_that_parse / random_changes_that_fail: the sweeps (every truncation,
//    300 random changes) in which a file must parse or throw FileError, nothing else.
#pragma once

#include "visibility/file_error.h"
#include "wld/eq/wld_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <map>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace pvs::eq::wld_test {

using Bytes = std::vector<uint8_t>;

struct Builder {
    Bytes out;
    size_t size() const { return out.size(); }
    Builder& u8(uint8_t v)
    {
        out.push_back(v);
        return *this;
    }
    Builder& i8(int8_t v) { return u8(uint8_t(v)); }
    Builder& u16(uint16_t v) { return u8(uint8_t(v)).u8(uint8_t(v >> 8)); }
    Builder& i16(int16_t v) { return u16(uint16_t(v)); }
    Builder& u32(uint32_t v) { return u16(uint16_t(v)).u16(uint16_t(v >> 16)); }
    Builder& i32(int32_t v) { return u32(uint32_t(v)); }
    Builder& f32(float v)
    {
        uint32_t bits;
        std::memcpy(&bits, &v, 4);
        return u32(bits);
    }
    Builder& raw(const Bytes& bytes)
    {
        out.insert(out.end(), bytes.begin(), bytes.end());
        return *this;
    }
};

// §2.2 with the key written out here again, so the tests do not trust wld_xor.
inline Bytes spec_xor(const std::string& decoded)
{
    static const uint8_t key[8] = {0x95, 0x3A, 0xC5, 0x2A, 0x95, 0x7A, 0x95, 0x6A};
    Bytes out(decoded.begin(), decoded.end());
    for (size_t i = 0; i < out.size(); ++i)
        out[i] ^= key[i % 8];
    return out;
}

// Zeros up to a multiple of 4 (§2.3: bodies and the string hash are padded).
inline Bytes padded(Bytes bytes)
{
    bytes.resize((bytes.size() + 3) / 4 * 4, 0);
    return bytes;
}

// The decoded string hash (§2.2): a leading NUL, then each name and its NUL; a name's
// reference is minus its offset.
struct SpecStrings {
    std::string decoded = std::string(1, '\0');
    std::map<std::string, int32_t> refs;

    int32_t add(const std::string& name)
    {
        const auto ref = -int32_t(decoded.size());
        refs[name] = ref;
        decoded += name;
        decoded.push_back('\0');
        return ref;
    }
};

struct SpecFile {
    Bytes file;
    std::vector<uint64_t> header_at; // absolute offset of each fragment's 8-byte header
    std::vector<uint64_t> body_at;   // absolute offset of each body (its name_ref)
};

// §2.1 header (region_count = the 0x22 bodies, max_object_bytes = largest padded body + 8,
// string_count = the names after the leading NUL), §2.2 encoded and padded hash, §2.3 each
// fragment (padded size, type, padded body), then the FF FF FF FF trailer.
inline SpecFile spec_wld(uint32_t version, const std::string& strings, std::span<const uint32_t> types,
                         std::span<const Bytes> bodies)
{
    const Bytes hash = padded(spec_xor(strings));
    size_t max_size = 0;
    uint32_t regions = 0;
    for (size_t i = 0; i < bodies.size(); ++i) {
        max_size = std::max(max_size, padded(bodies[i]).size());
        regions += types[i] == 0x22;
    }
    uint32_t names = 0;
    for (const char c : strings)
        names += c == '\0';
    SpecFile f;
    Builder b;
    b.u32(0x54503D02).u32(version).u32(uint32_t(bodies.size())).u32(regions).u32(uint32_t(max_size + 8));
    b.u32(uint32_t(hash.size())).u32(names - 1);
    b.raw(hash);
    for (size_t i = 0; i < bodies.size(); ++i) {
        f.header_at.push_back(b.size());
        b.u32(uint32_t(padded(bodies[i]).size())).u32(types[i]);
        f.body_at.push_back(b.size());
        b.raw(padded(bodies[i]));
    }
    b.u32(0xFFFFFFFF);
    f.file = std::move(b.out);
    return f;
}

inline void put_u16(Bytes& bytes, uint64_t at, uint16_t value) { std::memcpy(bytes.data() + at, &value, 2); }
inline void put_u32(Bytes& bytes, uint64_t at, uint32_t value) { std::memcpy(bytes.data() + at, &value, 4); }
inline void put_f32(Bytes& bytes, uint64_t at, float value) { std::memcpy(bytes.data() + at, &value, 4); }

// Runs `parse` on the changed file and checks the FileError: file "bad.wld", `offset`, and
// every phrase in the reason.
template <class Parse>
void expect_error(const Bytes& bytes, Parse&& parse, uint64_t offset, std::initializer_list<const char*> phrases)
{
    try {
        parse(bytes);
        ADD_FAILURE() << "no FileError; expected one with: " << *phrases.begin();
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "bad.wld");
        EXPECT_EQ(e.offset(), offset) << e.what();
        for (const char* phrase : phrases)
            EXPECT_NE(e.reason().find(phrase), std::string::npos) << "'" << phrase << "' not in: " << e.reason();
    }
}

// A parse for expect_error: the container as "bad.wld", then fragment `number` with Parser.
template <auto Parser>
auto parse_fragment(uint32_t number)
{
    return [number](const Bytes& b) { (void)Parser(parse_wld(b, "bad.wld"), number); };
}

// `parse_all` parses a file named "sweep.wld" as far as the test knows the format and lets
// FileError escape. true: it parsed; false: FileError naming the file at an offset inside it.
// Any other exception escapes and fails the test.
template <class ParseAll>
bool parses(const Bytes& bytes, ParseAll&& parse_all)
{
    try {
        parse_all(bytes);
        return true;
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "sweep.wld");
        EXPECT_LE(e.offset(), bytes.size());
        return false;
    }
}

// How many of the strict prefixes of `good` (lengths 0 .. size - 1) parse.
template <class ParseAll>
size_t prefixes_that_parse(const Bytes& good, ParseAll&& parse_all)
{
    size_t parsed = 0;
    for (size_t length = 0; length < good.size(); ++length)
        parsed += parses(Bytes(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(length)), parse_all);
    return parsed;
}

// How many of 300 copies of `good`, each with 1 to 4 bytes set to random values (std::mt19937
// seeded with `seed`, so every run changes the same bytes), fail with FileError.
template <class ParseAll>
size_t random_changes_that_fail(const Bytes& good, uint32_t seed, ParseAll&& parse_all)
{
    std::mt19937 rng(seed);
    std::uniform_int_distribution<size_t> where(0, good.size() - 1);
    std::uniform_int_distribution<int> value(0, 255), changes(1, 4);
    size_t errors = 0;
    for (int i = 0; i < 300; ++i) {
        Bytes bytes = good;
        for (int k = changes(rng); k > 0; --k)
            bytes[where(rng)] = static_cast<uint8_t>(value(rng));
        errors += !parses(bytes, parse_all);
    }
    return errors;
}

} // namespace pvs::eq::wld_test
