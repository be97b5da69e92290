// Player starts read from the maps' entities: checked against the entity text found here by a
// plain string search, and against the tree (the eye is in an open region of every shared map).
#include "tests/support/test_data.h"
#include "visibility/region_lookup.h"
#include "wld/player_start.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
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
                         [](const auto& p) {
                             std::string name = test::param_name(p.param); // gtest names: no '-'
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

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
}

} // namespace
} // namespace pvs
