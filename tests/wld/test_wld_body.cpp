// The fragment-body cursor and byte builder every WLD fragment parser and writer shares
// (wld/eq/wld_body.h), against bytes assembled here from ../shared/formats/eq-s3d-wld.md §2.1,
// §2.3 (fragment layout, bodies padded to 4) and §2.4 (references): little-endian values of
// every width, the absolute offsets and messages of its errors, and the checks of the
// constructor that the typed parsers rely on for a WldFile not made by parse_wld.
#include "tests/wld/wld_test_bytes.h"
#include "visibility/file_error.h"
#include "wld/eq/wld_body.h"
#include "wld/eq/wld_file.h"
#include "wld/eq/wld_material.h"
#include "wld/eq/wld_mesh.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace pvs::eq {
namespace {

using namespace wld_test;

// One 0x03 fragment (any type would do; the cursor does not interpret the fields) whose body is
// `body`, in a file with the strings "\0A\0".
SpecFile one_fragment_file(const Bytes& body, uint32_t type = kWldBitmapName)
{
    const uint32_t types[1] = {type};
    const Bytes bodies[1] = {body};
    return spec_wld(0x00015500, std::string("\0A\0", 3), types, bodies);
}

// Runs `read` and checks the FileError: file, absolute offset and the whole reason.
template <class Read>
void expect_reason(Read&& read, const std::string& file, uint64_t offset, const std::string& reason)
{
    try {
        read();
        ADD_FAILURE() << "no FileError; expected: " << reason;
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), file);
        EXPECT_EQ(e.offset(), offset) << e.what();
        EXPECT_EQ(e.reason(), reason);
    }
}

TEST(WldBodyReader, ReadsLittleEndianValuesOfEveryWidth)
{
    Builder b;
    b.i32(-1).u8(0xAB).i8(-2).u16(0xBEEF).i16(-300).u32(0xDEADBEEFu).i32(-123456).f32(1.5f);
    b.f32(1).f32(2).f32(3).f32(4);
    const SpecFile f = one_fragment_file(b.out);
    const WldFile wld = parse_wld(f.file, "cursor.wld");

    WldBodyReader r(wld, 1, kWldBitmapName);
    EXPECT_EQ(r.number(), 1u);
    EXPECT_EQ(r.at(), f.body_at[0]);
    EXPECT_EQ(r.left(), 40u); // 38 bytes of fields, padded to 40
    EXPECT_EQ(r.read<int32_t>("name_ref"), -1);
    EXPECT_EQ(r.read<uint8_t>("u8"), 0xAB);
    EXPECT_EQ(r.read<int8_t>("i8"), -2);
    EXPECT_EQ(r.read<uint16_t>("u16"), 0xBEEF);
    EXPECT_EQ(r.read<int16_t>("i16"), -300);
    EXPECT_EQ(r.read<uint32_t>("u32"), 0xDEADBEEFu);
    EXPECT_EQ(r.read<int32_t>("i32"), -123456);
    EXPECT_EQ(r.read<float>("f32"), 1.5f);
    EXPECT_EQ(r.vec4("vec4"), glm::vec4(1, 2, 3, 4));
    EXPECT_EQ(r.at(), f.body_at[0] + 38);
    EXPECT_EQ(r.left(), 2u);
}

TEST(WldBodyReader, ErrorsNameTheFileFragmentFieldAndOffset)
{
    Builder b;
    b.i32(0).u32(3).u16(7).u16(8).u16(9).u16(0); // name_ref, a count of 3, three u16, padding
    const SpecFile f = one_fragment_file(b.out);
    const WldFile wld = parse_wld(f.file, "cursor.wld");
    const uint64_t body = f.body_at[0];

    // Past the end: the error sits at the field, names it with its index and both sizes.
    WldBodyReader r(wld, 1, kWldBitmapName);
    (void)r.bytes(14, "head");
    expect_reason([&] { (void)r.read<uint32_t>("vertex", 3); }, "cursor.wld", body + 14,
                  "fragment 1 (0x03 bitmap name): vertex 3 runs past the end of the fragment (4 bytes needed, "
                  "2 left)");
    expect_reason([&] { (void)r.bytes(3, "user data"); }, "cursor.wld", body + 14,
                  "fragment 1 (0x03 bitmap name): user data runs past the end of the fragment (3 bytes needed, "
                  "2 left)");

    // A count is checked at its own offset before anything is reserved.
    WldBodyReader counts(wld, 1, kWldBitmapName);
    (void)counts.read<int32_t>("name_ref");
    expect_reason([&] { (void)counts.count("vertex_count", 4); }, "cursor.wld", body + 4,
                  "fragment 1 (0x03 bitmap name): vertex_count 3 does not fit in the fragment (8 bytes left, at "
                  "least 4 per element)");
    WldBodyReader fits(wld, 1, kWldBitmapName);
    (void)fits.read<int32_t>("name_ref");
    EXPECT_EQ(fits.count("vertex_count", 2), 3u);
    EXPECT_EQ(fits.read<uint16_t>("vertex", 0), 7);
}

TEST(WldBodyReader, FragmentReferences)
{
    // Fragment 2 refers to fragment 1 (a 0x03), itself, fragment 4 (the file has 3), 0, the name
    // "A" (-1) and a name outside the 3-byte string hash (-3).
    const Bytes first = Builder().i32(-1).out;
    const Bytes second = Builder().i32(0).i32(1).i32(2).i32(4).i32(0).i32(-1).i32(-3).out;
    const uint32_t types[3] = {kWldBitmapName, kWldSpriteDef, kWldSprite};
    const Bytes bodies[3] = {first, second, first};
    const SpecFile f = spec_wld(0x00015500, std::string("\0A\0", 3), types, bodies);
    const WldFile wld = parse_wld(f.file, "refs.wld");
    const uint64_t body = f.body_at[1];
    const std::string label = "fragment 2 (0x04 sprite definition): ";

    WldBodyReader r(wld, 2, kWldSpriteDef);
    (void)r.read<int32_t>("name_ref");
    EXPECT_EQ(r.fragment_ref("frame", kWldBitmapName), 1);
    expect_reason([&] { (void)r.fragment_ref("frame", kWldAnyFragmentType, 1); }, "refs.wld", body + 8,
                  label + "frame 1 2 is a forward reference (it must name an earlier fragment)");
    expect_reason([&] { (void)r.fragment_ref("frame", kWldAnyFragmentType); }, "refs.wld", body + 12,
                  label + "frame 4 is out of range (the file has 3 fragments)");
    EXPECT_EQ(r.fragment_ref("frame", kWldMaterial), 0);
    EXPECT_EQ(r.fragment_ref("frame", kWldMaterial), -1); // by name: the type is checked on use
    expect_reason([&] { (void)r.fragment_ref("frame", kWldAnyFragmentType); }, "refs.wld", body + 24,
                  label + "frame -3 names a string outside the string hash (3 bytes)");

    WldBodyReader typed(wld, 2, kWldSpriteDef);
    (void)typed.read<int32_t>("name_ref");
    expect_reason([&] { (void)typed.fragment_refs(1, "frame", kWldSprite); }, "refs.wld", body + 4,
                  label + "frame 0 1 names fragment 1 (0x03 bitmap name), not a 0x05 sprite");
}

TEST(WldBodyReader, HostileCountsFailBeforeAnythingIsReserved)
{
    const SpecFile f = one_fragment_file(Builder().i32(0).u32(0).out); // 8 bytes of body
    const WldFile wld = parse_wld(f.file, "counts.wld");
    const uint64_t body = f.body_at[0];
    const std::string label = "fragment 1 (0x03 bitmap name): ";

    // 2^32 - 1 elements would reserve 48 GiB of vec3 or 16 GiB of refs: a FileError naming the
    // field, never bad_alloc.
    WldBodyReader vecs(wld, 1, kWldBitmapName);
    (void)vecs.read<int32_t>("name_ref");
    expect_reason([&] { (void)vecs.vec3s(0xFFFFFFFFu, "region vertex"); }, "counts.wld", body + 4,
                  label + "region vertex 4294967295 does not fit in the fragment (4 bytes left, at least 12 per "
                          "element)");
    WldBodyReader refs(wld, 1, kWldBitmapName);
    (void)refs.read<int32_t>("name_ref");
    expect_reason([&] { (void)refs.fragment_refs(0xFFFFFFFFu, "material reference", kWldMaterial); },
                  "counts.wld", body + 4,
                  label + "material reference 4294967295 does not fit in the fragment (4 bytes left, at least 4 "
                          "per element)");
    EXPECT_EQ(refs.fragment_refs(1, "material reference", kWldAnyFragmentType), (std::vector<int32_t>{0}));

    // 2^62 elements of 8 bytes: the product 2^65 wraps to 0 in 64 bits, so only a division
    // refuses it.
    WldBodyReader wide(wld, 1, kWldBitmapName);
    expect_reason([&] { wide.check_count(uint64_t{1} << 62, body, 8, "huge"); }, "counts.wld", body,
                  label + "huge 4611686018427387904 does not fit in the fragment (8 bytes left, at least 8 per "
                          "element)");
}

TEST(WldBodyReader, RefusesABodyBeforeItsHeaderCouldFit)
{
    // A hand-made WldFile whose fragment body starts inside the first 8 bytes: the type field
    // (4 bytes before the body) would sit before the file, so the offset check comes first.
    const SpecFile f = one_fragment_file(Builder().i32(0).u32(0).out);
    const WldFile wld = parse_wld(f.file, "early.wld");
    for (const uint64_t offset : {uint64_t{0}, uint64_t{4}, uint64_t{7}}) {
        WldFile early = wld;
        early.fragments[0].body_offset = offset;
        const std::string reason = "fragment 1 (0x03 bitmap name): fragment body starts at " + std::to_string(offset) +
                                   ", before its 8-byte header could fit";
        expect_reason([&] { (void)parse_bitmap_name(early, 1); }, "early.wld", offset, reason);
        expect_reason([&] { (void)parse_mesh(early, 1); }, "early.wld", offset, reason); // wrong type too
    }
}

TEST(WldBodyReader, RefusesAMissingFragmentTheWrongTypeAndABodyOutsideTheBytes)
{
    const SpecFile f = one_fragment_file(Builder().i32(0).u32(0).out);
    const WldFile wld = parse_wld(f.file, "ctor.wld");
    EXPECT_THROW((void)WldBodyReader(wld, 0, kWldBitmapName), std::out_of_range);
    EXPECT_THROW((void)WldBodyReader(wld, 2, kWldBitmapName), std::out_of_range);
    EXPECT_THROW(parse_mesh(wld, 2), std::out_of_range);

    // The type is checked at the fragment header's type field (§2.3: 4 bytes before the body).
    expect_reason([&] { (void)parse_mesh(wld, 1); }, "ctor.wld", f.body_at[0] - 4,
                  "fragment 1 (0x03 bitmap name): expected a 0x36 mesh fragment");

    // A WldFile not made by parse_wld may point outside its bytes: every parser refuses it.
    WldFile cut = wld;
    cut.bytes = cut.bytes.first(f.body_at[0] + 4);
    const std::string reason = "fragment 1 (0x03 bitmap name): fragment body runs past the end of the data (8 bytes "
                               "needed, 4 available)";
    expect_reason([&] { (void)parse_bitmap_name(cut, 1); }, "ctor.wld", f.body_at[0], reason);
    cut.fragments[0].type = kWldRegion;
    expect_reason([&] { (void)parse_region(cut, 1); }, "ctor.wld", f.body_at[0],
                  "fragment 1 (0x22 region): fragment body runs past the end of the data (8 bytes needed, 4 "
                  "available)");
}

TEST(WldByteWriter, WritesLittleEndianAndPadsToFour)
{
    WldByteWriter w;
    w.put(int32_t{-1});
    w.put(uint8_t{0xAB});
    w.put(int16_t{-300});
    w.put(glm::vec2(1.5f, -2.0f));
    w.put_count(std::vector<uint16_t>{7, 8, 9}, "values");
    w.put_each(std::vector<uint16_t>{7, 8, 9});
    w.put_bytes(Bytes{1, 2});
    EXPECT_EQ(w.size(), 4u + 1 + 2 + 8 + 4 + 6 + 2);

    const Bytes expected = padded(Builder()
                                      .i32(-1)
                                      .u8(0xAB)
                                      .i16(-300)
                                      .f32(1.5f)
                                      .f32(-2.0f)
                                      .u32(3)
                                      .u16(7)
                                      .u16(8)
                                      .u16(9)
                                      .raw({1, 2})
                                      .out);
    EXPECT_EQ(expected.size(), 28u); // 27 bytes and one of padding
    EXPECT_EQ(w.finish(), expected);

    WldByteWriter aligned;
    aligned.put(uint32_t{0x04030201});
    EXPECT_EQ(aligned.finish(), (Bytes{1, 2, 3, 4})); // already a multiple of 4: nothing added
}

} // namespace
} // namespace pvs::eq
