// Bad input never crashes, hangs or reads out of bounds: every real file (Quake BSP 29 / BSP2 /
// 2PSB, Quake 2 IBSP 38) truncated at 200 cut
// points and with 200 seeded random byte changes either loads into a consistent zone or throws
// FileError naming the file. The CI runs this under AddressSanitizer + UBSan.
// Plus hand-made corruptions, each with the message a user should see.
#include "tests/support/test_data.h"
#include "visibility/file_error.h"
#include "visibility/region_lookup.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/ibsp38_zone.h"
#include "wld/common/read_file.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <cctype>

#include <cstring>
#include <filesystem>
#include <random>
#include <unistd.h>

namespace pvs {
namespace {

// A zone that loaded must be safe to use: every index in range, and a walk that ends.
void expect_consistent(const Zone& zone)
{
    const size_t faces = zone.mesh.faces.size();
    ASSERT_EQ(zone.region_face_offsets.size(), zone.region_count() + 1);
    for (uint32_t f : zone.region_faces)
        ASSERT_LT(f, faces);
    for (uint32_t i : zone.mesh.indices)
        ASSERT_LT(i, zone.mesh.positions.size());
    for (int32_t region : zone.tree.leaf_region)
        ASSERT_LT(region, int32_t(zone.region_count()));
    if (zone.baked_pvs) {
        ASSERT_EQ(zone.baked_pvs->region_count(), zone.region_count());
    }
    const PointLocation at = locate_point(zone.tree, zone.bounds().center());
    ASSERT_LT(at.region, int32_t(zone.region_count()));
}

// Loads the bytes; returns true when they loaded, false when they threw FileError naming `name`.
bool load_or_file_error(const std::vector<uint8_t>& bytes, const std::string& name)
{
    try {
        const Zone zone =
            quake2::looks_like_ibsp38(bytes) ? quake2::load_ibsp38(bytes, name) : quake::load_bsp29(bytes, name);
        expect_consistent(zone);
        return true;
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), name);
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos);
        return false;
    }
}

class BadQuakeFile : public ::testing::TestWithParam<const char*> {};

TEST_P(BadQuakeFile, TruncatedAt200CutPointsLoadsOrThrowsFileError)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const std::vector<uint8_t> original = test::read_bytes(path);
    std::mt19937 rng(7);
    std::uniform_int_distribution<size_t> cut(0, original.size() - 1);
    size_t errors = 0;
    for (int i = 0; i < 200; ++i) {
        // Half evenly spaced, half random; the first cuts hit the header.
        const size_t length = i < 100 ? original.size() * size_t(i) / 100 : cut(rng);
        const std::vector<uint8_t> bytes(original.begin(), original.begin() + static_cast<std::ptrdiff_t>(length));
        errors += !load_or_file_error(bytes, "truncated.bsp");
    }
    EXPECT_GT(errors, 150u); // most cuts remove a lump the header names
}

TEST_P(BadQuakeFile, With200RandomByteChangesLoadsOrThrowsFileError)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const std::vector<uint8_t> original = test::read_bytes(path);
    std::mt19937 rng(11);
    std::uniform_int_distribution<size_t> where(0, original.size() - 1);
    std::uniform_int_distribution<int> value(0, 255);
    for (int i = 0; i < 200; ++i) {
        std::vector<uint8_t> bytes = original;
        // Every fourth case hits the header and lump table, where a change matters most.
        const size_t at = i % 4 == 0 ? where(rng) % 124 : where(rng);
        bytes[at] = static_cast<uint8_t>(value(rng));
        load_or_file_error(bytes, "flipped.bsp");
    }
}

INSTANTIATE_TEST_SUITE_P(
    SharedData, BadQuakeFile,
    ::testing::Values("quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/dm2.bsp", "quake/start.bsp",
                      "quake/end.bsp", "visdemo/example.bsp", "modern-quake/q1/lqdm2-bsp2.ericw-vis.bsp",
                      "modern-quake/q1/lqdm2-2psb.ericw-vis.bsp", "modern-quake/q2/q2_liquids.ericw-vis.bsp",
                      "modern-quake/q2/q2_tjunc_matrix.ericw-vis.bsp", "modern-quake/q2/q2_areaportals.bsp"),
    [](const ::testing::TestParamInfo<const char*>& param) { return test::param_name(param.param); });

// Hand-made corruptions of example.bsp, each checked for the message a user reads.
class CorruptExample : public ::testing::Test {
protected:
    void SetUp() override
    {
        SHARED_DATA_OR_SKIP(path, "visdemo/example.bsp");
        bytes_ = test::read_bytes(path);
    }
    int32_t lump_offset(int lump) const { return get<int32_t>(4 + 8 * lump); }
    template <class T>
    T get(size_t at) const
    {
        T v;
        std::memcpy(&v, bytes_.data() + at, sizeof v);
        return v;
    }
    template <class T>
    void put(size_t at, T v)
    {
        std::memcpy(bytes_.data() + at, &v, sizeof v);
    }
    std::string error() const
    {
        try {
            quake::load_bsp29(bytes_, "example.bsp");
        } catch (const FileError& e) {
            return e.what();
        }
        return "(loaded)";
    }
    std::vector<uint8_t> bytes_;
};

TEST_F(CorruptExample, WrongVersionSaysWhatItFound)
{
    put<int32_t>(0, 30);
    EXPECT_NE(error().find("Half-Life"), std::string::npos) << error();
    std::memcpy(bytes_.data(), "IBSP", 4);
    put<int32_t>(4, 38);
    EXPECT_NE(error().find("Quake 2 IBSP version 38"), std::string::npos) << error();
}

TEST_F(CorruptExample, LumpPastTheEndNamesTheLump)
{
    put<int32_t>(4 + 8 * 10 + 4, 1 << 30); // leafs length
    EXPECT_NE(error().find("leafs lump runs past the end"), std::string::npos) << error();
}

TEST_F(CorruptExample, NodeChildOutOfRangeIsReported)
{
    put<uint16_t>(size_t(lump_offset(5)) + 4, uint16_t(65535 - 5000)); // node 0 front child = leaf 5000
    EXPECT_NE(error().find("node child leaf 5000 is out of range"), std::string::npos) << error();
}

TEST_F(CorruptExample, NodeCycleIsReportedInsteadOfHanging)
{
    put<uint16_t>(size_t(lump_offset(5)) + 4, 0); // node 0's front child is node 0
    EXPECT_NE(error().find("reached twice"), std::string::npos) << error();
}

TEST_F(CorruptExample, VisofsOutsideTheLumpIsReported)
{
    put<int32_t>(size_t(lump_offset(10)) + 28 * 1 + 4, 1 << 20);
    EXPECT_NE(error().find("visofs"), std::string::npos) << error();
}

TEST_F(CorruptExample, PvsRowRunningPastTheLumpIsReported)
{
    // Point leaf 1's row at the last byte of the lump, and make that byte a zero with no count.
    const int32_t vis_ofs = lump_offset(4), vis_len = get<int32_t>(4 + 8 * 4 + 4);
    put<int32_t>(size_t(lump_offset(10)) + 28 * 1 + 4, vis_len - 1);
    bytes_[size_t(vis_ofs + vis_len - 1)] = 0;
    EXPECT_NE(error().find("runs past the end of the visibility lump"), std::string::npos) << error();
}

// Found by fuzz_bsp29 in CI: a texture lump of 1-3 bytes made the count check subtract 4 from
// its length, wrap around and accept any count, so the reader resized the materials to 2^31.
TEST_F(CorruptExample, TextureLumpShorterThanItsCountFieldIsReported)
{
    put<int32_t>(size_t(lump_offset(2)), 0x7fffffff); // miptex count
    put<int32_t>(4 + 8 * 2 + 4, 3);                     // textures lump length
    EXPECT_NE(error().find("texture lump is 3 bytes"), std::string::npos) << error();
}

TEST_F(CorruptExample, UnterminatedEntityIsReportedWithItsOffset)
{
    const int32_t ent_ofs = lump_offset(0), ent_len = get<int32_t>(4 + 4);
    for (int32_t i = ent_len - 1; i >= 0; --i)
        if (bytes_[size_t(ent_ofs + i)] == '}') {
            bytes_[size_t(ent_ofs + i)] = ' ';
            break;
        }
    EXPECT_NE(error().find("entity is not closed"), std::string::npos) << error();
}

TEST(ZoneFile, UnknownAndMissingFilesGiveOneClearError)
{
    try {
        load_zone("/nonexistent/zone.bsp");
        FAIL();
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
    }
}

// A broken portal file, or another map's, beside a good map: the map loads, without those portals,
// and a note says why (the map does not need its .prt; info, check and the inspector still work).
TEST(ZoneFile, ABrokenPortalFileBesideAMapIsANoteNotAnError)
{
    SHARED_DATA_OR_SKIP(map, "visdemo/example.bsp");
    SHARED_DATA_OR_SKIP(other_prt, "modern-quake/q2/q2_areaportals.prt");
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("pvscope-prt-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path copy = dir / "example.bsp", prt = dir / "example.prt";
    std::filesystem::copy_file(map, copy, std::filesystem::copy_options::overwrite_existing);
    const auto note_with = [&](const std::string& text) {
        const Zone zone = load_zone(copy.string());
        EXPECT_FALSE(zone.portals.has_value());
        for (const std::string& note : zone.source.notes)
            if (note.find("example.prt not used") != std::string::npos && note.find(text) != std::string::npos)
                return true;
        return false;
    };
    write_whole_file(prt.string(), {'P', 'R', 'T', '1', '\n', '1', '1'});
    EXPECT_TRUE(note_with("example.prt")) << "truncated";
    std::filesystem::copy_file(other_prt, prt, std::filesystem::copy_options::overwrite_existing);
    EXPECT_TRUE(note_with("names 8 leaves but the map has 11")) << "another map's";
    std::filesystem::remove_all(dir);
}

// --map and --gwa name parts of a Doom map: given for another format they are an error, not
// silently ignored.
TEST(ZoneFile, DoomOptionsOnAnotherFormatAreAnError)
{
    SHARED_DATA_OR_SKIP(map, "visdemo/example.bsp");
    ZoneLoadOptions options;
    options.map = "E1M1";
    EXPECT_THROW(load_zone(map, options), FileError);
    options.map.clear();
    options.gwa = map;
    EXPECT_THROW(load_zone(map, options), FileError);
    EXPECT_NO_THROW(load_zone(map, ZoneLoadOptions{}));
}

// A directory opens as a stream on Linux and reports a size of 2^63 - 1: reading it whole once
// threw std::bad_alloc out of every command. Each format's path (by extension or by content)
// names the directory instead.
TEST(ZoneFile, ADirectoryIsNamedNotRead)
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("pvscope-dir-" + std::to_string(::getpid()));
    for (const char* name : {"zone.bsp", "zone.s3d", "zone.wad", "zone.obj", "zone"}) {
        std::filesystem::create_directories(dir / name);
        try {
            load_zone((dir / name).string());
            ADD_FAILURE() << name << " loaded";
        } catch (const FileError& e) {
            EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << name << ": " << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << ": " << e.what();
        }
    }
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace pvs
