// Bad Doom WADs: overlapping lumps, missing GL lumps, seg and vertex indices out of
// range, a subsector of minisegs only, node children that are not a tree, and sweeps of
// truncations and byte changes of real GL nodes (glbsp's, for the hand-made map) in which the
// reader must succeed or throw FileError naming the file, never crash or read out of bounds.
#include "tests/support/freedoom.h"
#include "tests/wld/doom_test_maps.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>
#include <unistd.h>

namespace {

using namespace pvs;
using namespace pvs::doom;
using pvs::test::GlBuilder;

// The hand-made map's WAD and glbsp's .gwa for it, as bytes.
struct Pair {
    std::vector<uint8_t> wad, gwa;
};

std::optional<Pair> hand_made_pair()
{
    const std::string wad = (std::filesystem::temp_directory_path() /
                             ("pvscope-doom-bad-" + std::to_string(getpid()) + ".wad"))
                                .string();
    write_whole_file(wad, doom_test::hand_made_wad(false));
    const auto gwa = pvs::test::gl_nodes_file(wad, GlBuilder::glbsp_v2);
    if (!gwa)
        return std::nullopt;
    return Pair{read_whole_file(wad), read_whole_file(*gwa)};
}

#define PAIR_OR_SKIP(var)                                                                                     \
    auto var##_opt = hand_made_pair();                                                                        \
    if (!var##_opt) {                                                                                         \
        if (pvs::test::shared_data_required()) {                                                              \
            FAIL() << "glbsp could not build the hand-made map";                                              \
        }                                                                                                     \
        GTEST_SKIP() << "SKIPPED: needs glbsp (apt-get install glbsp)";                                       \
    }                                                                                                         \
    Pair& var = *var##_opt

// Reads the map from (possibly changed) bytes; the error message, or empty when it loaded.
std::string read_error(const std::vector<uint8_t>& wad_bytes, const std::vector<uint8_t>& gwa_bytes)
{
    try {
        const WadFile wad = parse_wad(wad_bytes, "bad.wad");
        const WadFile gwa = parse_wad(gwa_bytes, "bad.gwa");
        const DoomMap map = read_doom_map(wad, &gwa, "MAP01");
        build_doom_zone(map, nullptr);
        return {};
    } catch (const FileError& e) {
        return e.what();
    }
}

// The bytes of lump `name` (the first after the GL marker) in a WAD's bytes.
std::span<uint8_t> lump_bytes(std::vector<uint8_t>& bytes, const std::string& name)
{
    const WadFile wad = parse_wad(bytes, "x");
    const size_t i = *wad.find_from(name, 0);
    return std::span<uint8_t>(bytes).subspan(wad.lumps[i].offset, wad.lumps[i].size);
}

// The same WAD without lump `name` (its first one).
std::vector<uint8_t> without_lump(const std::vector<uint8_t>& bytes, const std::string& name)
{
    const WadFile wad = parse_wad(bytes, "x");
    std::vector<WadLumpData> lumps;
    bool dropped = false;
    for (size_t i = 0; i < wad.lumps.size(); ++i) {
        if (!dropped && wad.lumps[i].name == name) {
            dropped = true;
            continue;
        }
        const auto data = wad.data(i);
        lumps.push_back({wad.lumps[i].name, std::vector<uint8_t>(data.begin(), data.end())});
    }
    return write_wad(wad.iwad, lumps);
}

void put_u16(std::span<uint8_t> at, uint16_t v) { std::memcpy(at.data(), &v, 2); }

TEST(DoomBadInput, TheHandMadeMapLoads)
{
    PAIR_OR_SKIP(p);
    EXPECT_EQ(read_error(p.wad, p.gwa), "");
}

TEST(DoomBadInput, OverlappingLumpsAreNamed)
{
    std::vector<uint8_t> bytes = write_wad(false, std::vector<WadLumpData>{{"ONE", std::vector<uint8_t>(16, 1)},
                                                                            {"TWO", std::vector<uint8_t>(16, 2)}});
    // Point TWO's offset 8 bytes into ONE.
    const int32_t directory = *reinterpret_cast<const int32_t*>(bytes.data() + 8);
    int32_t offset;
    std::memcpy(&offset, bytes.data() + directory, 4);
    offset += 8;
    std::memcpy(bytes.data() + directory + 16, &offset, 4);
    try {
        parse_wad(bytes, "overlap.wad");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "overlap.wad");
        EXPECT_NE(e.reason().find("overlaps lump 'ONE'"), std::string::npos) << e.what();
        EXPECT_NE(e.reason().find("'TWO'"), std::string::npos) << e.what();
    }
}

TEST(DoomBadInput, MissingGlLumpsAreNamed)
{
    PAIR_OR_SKIP(p);
    for (const char* name : {"GL_VERT", "GL_SEGS", "GL_SSECT", "GL_NODES"}) {
        const std::string error = read_error(p.wad, without_lump(p.gwa, name));
        EXPECT_NE(error.find(name), std::string::npos) << name << ": " << error;
    }
    const std::string no_group = read_error(p.wad, without_lump(p.gwa, "GL_MAP01"));
    EXPECT_NE(no_group.find("no GL nodes"), std::string::npos) << no_group;
}

TEST(DoomBadInput, IndicesOutOfRangeAreNamedWithTheirLump)
{
    PAIR_OR_SKIP(p);
    {
        std::vector<uint8_t> gwa = p.gwa;
        put_u16(lump_bytes(gwa, "GL_SEGS"), 0x7FFF); // VERTEXES index 32767 (flag bit clear)
        const std::string e = read_error(p.wad, gwa);
        EXPECT_NE(e.find("GL_SEGS"), std::string::npos) << e;
        EXPECT_NE(e.find("vertex 32767 out of range"), std::string::npos) << e;
    }
    {
        std::vector<uint8_t> gwa = p.gwa;
        put_u16(lump_bytes(gwa, "GL_SEGS").subspan(4), 999); // linedef 999 of 20
        const std::string e = read_error(p.wad, gwa);
        EXPECT_NE(e.find("linedef 999 out of range"), std::string::npos) << e;
    }
    {
        std::vector<uint8_t> gwa = p.gwa;
        put_u16(lump_bytes(gwa, "GL_SSECT").subspan(2), 9999); // first seg past the end
        const std::string e = read_error(p.wad, gwa);
        EXPECT_NE(e.find("GL_SSECT"), std::string::npos) << e;
    }
    {
        std::vector<uint8_t> gwa = p.gwa;
        auto nodes = lump_bytes(gwa, "GL_NODES");
        put_u16(nodes.subspan(nodes.size() - 4), 0x7FFE); // the root's right child: a later node
        const std::string e = read_error(p.wad, gwa);
        EXPECT_NE(e.find("GL_NODES"), std::string::npos) << e;
    }
    {
        std::vector<uint8_t> wad = p.wad;
        put_u16(lump_bytes(wad, "SIDEDEFS").subspan(28), 77); // sector 77 of 5
        const std::string e = read_error(wad, p.gwa);
        EXPECT_NE(e.find("SIDEDEFS"), std::string::npos) << e;
        EXPECT_NE(e.find("sector 77 out of range"), std::string::npos) << e;
    }
}

TEST(DoomBadInput, ASubsectorOfMinisegsOnlyIsRefused)
{
    PAIR_OR_SKIP(p);
    std::vector<uint8_t> gwa = p.gwa;
    auto ssect = lump_bytes(gwa, "GL_SSECT");
    uint16_t count, first;
    std::memcpy(&count, ssect.data(), 2);
    std::memcpy(&first, ssect.data() + 2, 2);
    auto segs = lump_bytes(gwa, "GL_SEGS");
    for (uint16_t k = 0; k < count; ++k)
        put_u16(segs.subspan(size_t(first + k) * 10 + 4), 0xFFFF);
    const std::string e = read_error(p.wad, gwa);
    EXPECT_NE(e.find("only minisegs"), std::string::npos) << e;
    EXPECT_NE(e.find("GL_SSECT"), std::string::npos) << e;
}

TEST(DoomBadInput, EveryTruncationAndRandomChangesFailCleanly)
{
    PAIR_OR_SKIP(p);
    size_t loaded = 0, refused = 0;
    for (size_t n = 0; n < p.gwa.size(); ++n) {
        const std::vector<uint8_t> cut(p.gwa.begin(), p.gwa.begin() + ptrdiff_t(n));
        (read_error(p.wad, cut).empty() ? loaded : refused)++;
    }
    EXPECT_EQ(loaded, 0u) << "a truncated .gwa loses its directory";
    std::mt19937 rng(15);
    for (int round = 0; round < 400; ++round) {
        std::vector<uint8_t> gwa = p.gwa, wad = p.wad;
        std::vector<uint8_t>& target = round % 2 ? gwa : wad;
        for (int k = 0; k < 4; ++k)
            target[rng() % target.size()] = uint8_t(rng());
        (read_error(wad, gwa).empty() ? loaded : refused)++;
    }
    EXPECT_GT(refused, p.gwa.size());
    EXPECT_GT(loaded, 0u) << "some changes (texture names, heights) leave a loadable map";
}

} // namespace
