// Player starts read from the maps' entities: checked against the entity text found here by a
// plain string search, and against the tree (the eye is in an open region of every shared map).
// Doom starts (Freedoom): the eye 41 units over the floor of the sector that holds the thing,
// found here by crossing counts over the sector's own lines, not by the GL nodes or the tree.
#include "tests/support/freedoom.h"
#include "tests/support/test_data.h"
#include "visibility/region_lookup.h"
#include "wld/common/read_file.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"
#include "wld/player_start.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

namespace pvs {
namespace {

// The origin of the first info_player_start block in the file's bytes, found without a parser:
// the "origin" pair of the { ... } block around the classname.
std::optional<glm::vec3> origin_by_search(const std::vector<uint8_t>& bytes)
{
    const std::string text(bytes.begin(), bytes.end());
    const size_t at = text.find("\"info_player_start\"");
    if (at == std::string::npos)
        return std::nullopt;
    const size_t open = text.rfind('{', at), close = text.find('}', at);
    const std::string block = text.substr(open, close - open);
    const size_t key = block.find("\"origin\"");
    if (key == std::string::npos)
        return std::nullopt;
    glm::vec3 v;
    if (std::sscanf(block.c_str() + key + 8, " \"%f %f %f\"", &v.x, &v.y, &v.z) != 3)
        return std::nullopt;
    return v;
}

class PlayerStartOf : public ::testing::TestWithParam<const char*> {};

TEST_P(PlayerStartOf, IsTheEntitysOriginAtEyeHeightInAnOpenRegion)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const std::vector<uint8_t> bytes = test::read_bytes(path);
    const std::optional<PlayerStart> start = find_player_start(bytes);
    ASSERT_TRUE(start);
    const std::optional<glm::vec3> origin = origin_by_search(bytes);
    ASSERT_TRUE(origin);
    EXPECT_EQ(start->eye, *origin + glm::vec3(0.0f, 0.0f, kQuakeViewHeight));
    const Zone zone = load_zone(path);
    EXPECT_TRUE(locate_point(zone.tree, start->eye).in_region());
}

INSTANTIATE_TEST_SUITE_P(Maps, PlayerStartOf,
                         ::testing::Values("quake/e1m1.bsp", "quake/start.bsp", "modern-quake/q1/lq_e1m1.bsp",
                                           "modern-quake/q2/lqdm2-q2.bsp"),
                         [](const auto& p) { return test::param_name(p.param); });

TEST(PlayerStart, OtherFilesAndBrokenLumpsHaveNone)
{
    EXPECT_FALSE(find_player_start(std::vector<uint8_t>{'P', 'W', 'A', 'D', 0, 0, 0, 0}));
    // A BSP 29 header (version, then 15 lumps of offset and length) and its entity lump.
    std::vector<uint8_t> bsp(400, 0);
    bsp[0] = 29;
    bsp[4] = 200; // entities at 200 ...
    bsp[8] = 250; // ... for 250 bytes: past the end
    EXPECT_FALSE(find_player_start(bsp));
    const std::string broken = "{ \"classname\" \"info_player_start\" \"origin\" \"1 2"; // no closing quote
    bsp[8] = uint8_t(broken.size());
    std::copy(broken.begin(), broken.end(), bsp.begin() + 200);
    EXPECT_FALSE(find_player_start(bsp));
    const std::string good = "{ \"classname\" \"info_player_start\" \"origin\" \"1 2 3\" \"angle\" \"180\" }";
    bsp[8] = uint8_t(good.size());
    std::copy(good.begin(), good.end(), bsp.begin() + 200);
    const std::optional<PlayerStart> start = find_player_start(bsp);
    ASSERT_TRUE(start) << "the same header with a whole entity: so the refusals above were the lump's";
    EXPECT_EQ(start->eye, glm::vec3(1.0f, 2.0f, 3.0f + kQuakeViewHeight));
    EXPECT_EQ(start->yaw_degrees, 180.0f);
    EXPECT_FALSE(find_player_start(std::string("/no/such/map.bsp")));
    // From a file: a header whose entity lump lies past the end is refused before it is read.
    const std::string file = (std::filesystem::temp_directory_path() / "pvscope-start-test.bsp").string();
    bsp[4] = 0xF0;
    bsp[5] = 0xFF;
    bsp[9] = 0xFF;
    bsp[10] = 0xFF;
    write_whole_file(file, bsp);
    EXPECT_FALSE(find_player_start(file));
    bsp[4] = 200;
    bsp[5] = 0;
    bsp[9] = 0;
    bsp[10] = 0;
    write_whole_file(file, bsp);
    EXPECT_TRUE(find_player_start(file)) << "the same file with the lump in place";
    std::filesystem::remove(file);
}

// The sector holding (x, y): the one whose boundary lines (those with it on exactly one side) a ray
// towards +x crosses an odd number of times.
std::optional<uint32_t> sector_by_crossings(const doom::DoomMap& map, double x, double y)
{
    std::optional<uint32_t> found;
    for (uint32_t s = 0; s < map.sectors.size(); ++s) {
        int crossings = 0;
        for (const doom::Linedef& line : map.linedefs) {
            const auto side_in = [&](int k) {
                return line.side[k] >= 0 && map.sidedefs[size_t(line.side[k])].sector == s;
            };
            if (side_in(0) == side_in(1))
                continue;
            const doom::MapVertex a = map.vertices[line.v1], b = map.vertices[line.v2];
            if ((a.y > y) == (b.y > y))
                continue;
            if (a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y) > x)
                ++crossings;
        }
        if (crossings % 2 == 1) {
            if (found)
                return std::nullopt; // two sectors claim the point: not a point to test on
            found = s;
        }
    }
    return found;
}

struct DoomStartCase {
    const char* wad;
    const char* map;
};

class DoomPlayerStart : public ::testing::TestWithParam<DoomStartCase> {};

TEST_P(DoomPlayerStart, IsThingOneAtEyeHeightOverItsSectorsFloor)
{
    FREEDOOM_OR_SKIP(wad, GetParam().wad);
    GL_NODES_OR_SKIP(gwa, wad, test::GlBuilder::glbsp_v2);
    const doom::OpenedMap opened = doom::open_doom_map(wad, GetParam().map, gwa);
    const Zone zone = doom::build_doom_zone(opened.map, nullptr);
    const std::optional<PlayerStart> start = find_zone_player_start(zone);
    ASSERT_TRUE(start);
    // Thing 1 in the map's THINGS, read here record by record (x, y, angle, type, flags).
    const std::span<const uint8_t> things = opened.wad.data(opened.map.source.map_marker + 1);
    std::optional<glm::vec3> thing;
    for (size_t at = 0; at + 10 <= things.size() && !thing; at += 10) {
        const auto field = [&](size_t k) { return int16_t(things[at + 2 * k] | things[at + 2 * k + 1] << 8); };
        if (field(3) == 1)
            thing = glm::vec3(field(0), field(1), field(2));
    }
    ASSERT_TRUE(thing);
    EXPECT_EQ(start->eye.x, thing->x);
    EXPECT_EQ(start->eye.y, thing->y);
    EXPECT_EQ(start->yaw_degrees, thing->z);
    const std::optional<uint32_t> sector = sector_by_crossings(opened.map, thing->x + 0.25, thing->y + 0.25);
    ASSERT_TRUE(sector);
    EXPECT_EQ(start->eye.z, float(opened.map.sectors[*sector].floor_height) + kDoomViewHeight);
    EXPECT_TRUE(locate_point(zone.tree, start->eye).in_region());
}

INSTANTIATE_TEST_SUITE_P(Freedoom, DoomPlayerStart,
                         ::testing::Values(DoomStartCase{"freedoom1.wad", "E1M1"},
                                           DoomStartCase{"freedoom2.wad", "MAP01"},
                                           DoomStartCase{"freedoom2.wad", "MAP10"}),
                         [](const auto& p) { return std::string(p.param.map); });

TEST(PlayerStart, ADoomWadWithoutTheMapHasNone)
{
    EXPECT_FALSE(find_doom_thing_start("/no/such/doom.wad", "MAP01"));
    FREEDOOM_OR_SKIP(wad, "freedoom2.wad");
    EXPECT_FALSE(find_doom_thing_start(wad, "E9M9"));
    EXPECT_TRUE(find_doom_thing_start(wad, "MAP01")) << "so the refusal above was the map name's";
}

} // namespace
} // namespace pvs
