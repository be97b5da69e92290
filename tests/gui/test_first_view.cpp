// The first view a zone opens with is one a player would recognise: where the map puts its player
// (Quake's and Quake 2's info_player_start, Doom's player 1 start), else the open region with the longest sight line,
// never a zone line, a liquid or the sky. Its first frame draws at least 20 regions, and at least
// 30 % of its pixels show faces (an ID-buffer frame: not the background), many of them (not one
// wall in front of the camera). Over the shared Quake and Quake 2 levels, Freedoom maps, the demo
// zone and a generated outdoor zone.
#include "gen/generate_outdoor_zone.h"
#include "render/colour_codes.h"
#include "render/render_mode.h"
#include "tests/support/freedoom.h"
#include "tests/support/test_data.h"
#include "ui/gui/inspector_state.h"
#include "wld/convert.h"
#include "wld/player_start.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <unistd.h>

namespace pvs {
namespace {

using gui::InspectorState;

void expect_a_view(InspectorState& state, const std::string& what)
{
    state.render_mode = ui::RenderMode::IdBuffer;
    state.frame();
    EXPECT_GE(state.visible_regions().size(), 20u) << what << ": regions drawn";
    const ui::Image& image = state.image();
    size_t face_pixels = 0;
    std::set<uint32_t> faces;
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x)
            if (const uint32_t face = ui::face_at(image, x, y); face != ui::kNoFace) {
                ++face_pixels;
                faces.insert(face);
            }
    const size_t pixels = size_t(image.width) * image.height;
    EXPECT_GE(face_pixels * 10, pixels * 3) << what << ": " << face_pixels << " of " << pixels << " pixels show faces";
    EXPECT_GE(faces.size(), 10u) << what << ": distinct faces on screen";
}

class SharedLevelFirstView : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedLevelFirstView, SeesTheLevel)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    InspectorState state;
    state.set_viewport_size(320, 240);
    ASSERT_TRUE(state.open_zone(path)) << state.error();
    expect_a_view(state, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Maps, SharedLevelFirstView,
                         ::testing::Values("quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/start.bsp",
                                           "quake/end.bsp", "quake/dm2.bsp", "modern-quake/q1/lqdm2.bsp",
                                           "modern-quake/q1/lqdm5.bsp", "modern-quake/q1/lq_e1m1.bsp",
                                           "modern-quake/q1/lq_e2m2.bsp", "modern-quake/q2/lqdm2-q2.bsp",
                                           "modern-quake/q2/lqdm5-q2.bsp"),
                         [](const auto& p) { return test::param_name(p.param); });

// A Doom map opens at player 1's start (its eye where find_zone_player_start puts it).
TEST(FirstView, ADoomMapOpensAtPlayerOnesStart)
{
    for (const auto& [wad_name, map] : {std::pair{"freedoom1.wad", "E1M1"}, std::pair{"freedoom2.wad", "MAP01"}}) {
        FREEDOOM_OR_SKIP(wad, wad_name);
        GL_NODES_OR_SKIP(gwa, wad, test::GlBuilder::glbsp_v2);
        InspectorState state;
        state.set_viewport_size(320, 240);
        ZoneLoadOptions load;
        load.map = map;
        load.gwa = gwa;
        ASSERT_TRUE(state.open_zone(wad, load)) << state.error();
        const std::optional<PlayerStart> start = find_zone_player_start(state.zone());
        ASSERT_TRUE(start) << map;
        EXPECT_EQ(state.view_camera().position, start->eye) << map;
        expect_a_view(state, map);
    }
}

TEST(FirstView, TheDemoZoneIsSeen)
{
    InspectorState state;
    state.set_viewport_size(320, 240);
    state.open_demo();
    expect_a_view(state, "demo");
}

// The outdoor zone has zone lines all round its edge: the first view is inside, on open ground.
TEST(FirstView, AnOutdoorZoneOpensOnOpenGroundNotOnItsZoneLine)
{
    gen::OutdoorParams params;
    params.size = 2048.0f;
    const std::string path =
        (std::filesystem::temp_directory_path() / ("pvscope-first-view-" + std::to_string(::getpid()) + ".s3d"))
            .string();
    write_zone(gen::generate_outdoor_zone(params), path, ZoneOutput::S3d);
    InspectorState state;
    state.set_viewport_size(320, 240);
    const bool opened = state.open_zone(path);
    std::filesystem::remove(path);
    ASSERT_TRUE(opened) << state.error();
    const CullStats& s = state.frame();
    ASSERT_GE(s.region, 0);
    EXPECT_EQ(state.zone().regions[uint32_t(s.region)].flags & kRegionZoneLine, 0u);
    expect_a_view(state, "outdoor");
}

} // namespace
} // namespace pvs
