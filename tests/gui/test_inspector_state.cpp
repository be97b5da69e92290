// The inspector's state logic, headless (no window, no GL): opening zones, the fly camera, the
// culling-camera lock, mode switches, picking against an independent ID render, the statistics
// export and the frame-time ring.
#include "tests/support/test_data.h"
#include "ui/gui/inspector_state.h"
#include "render/software_renderer.h"
#include "visibility/culler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

namespace pvs {
namespace {

using gui::CameraInput;
using gui::InspectorState;

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance)
{
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// Everything a culled frame decides (not its times).
void expect_same_cull(const CullStats& a, const CullStats& b)
{
    EXPECT_EQ(a.camera, b.camera);
    EXPECT_EQ(a.region, b.region);
    EXPECT_EQ(a.pvs_used, b.pvs_used);
    EXPECT_EQ(a.regions_total, b.regions_total);
    EXPECT_EQ(a.regions_after_pvs, b.regions_after_pvs);
    EXPECT_EQ(a.regions_after_frustum, b.regions_after_frustum);
    EXPECT_EQ(a.triangles_after_pvs, b.triangles_after_pvs);
    EXPECT_EQ(a.triangles_after_frustum, b.triangles_after_frustum);
}

CullStats cull_alone(const Zone& zone, const Camera& camera, CullMode mode, std::vector<uint32_t>* visible = nullptr)
{
    Culler culler(zone, zone.baked_pvs ? &*zone.baked_pvs : nullptr);
    std::vector<uint32_t> kept;
    const CullStats stats = culler.cull(camera, {mode, true}, kept);
    if (visible)
        *visible = kept;
    return stats;
}

// One CSV line (RFC 4180 quoting) into its fields, quotes removed.
std::vector<std::string> split_csv_line(const std::string& line)
{
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
            fields.back() += line[++i];
        else if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            fields.emplace_back();
        else
            fields.back() += c;
    }
    return fields;
}

struct DemoInspector : ::testing::Test {
    void SetUp() override
    {
        state.set_viewport_size(160, 120);
        state.open_demo();
    }
    InspectorState state;
};

TEST_F(DemoInspector, OpensWithTheCameraInARegion)
{
    ASSERT_TRUE(state.has_zone());
    EXPECT_GT(state.zone().region_count(), 10u);
    EXPECT_EQ(state.zone_stats().regions, state.zone().region_count());
    const CullStats& s = state.frame();
    EXPECT_EQ(s.camera, CameraPlace::InRegion);
    EXPECT_GE(s.region, 0);
    EXPECT_EQ(state.image().width, 160u);
    EXPECT_EQ(state.image().height, 120u);
    EXPECT_FLOAT_EQ(state.view_camera().aspect, 160.0f / 120.0f);
    EXPECT_EQ(state.shown_region(), s.region);
}

TEST_F(DemoInspector, FlyCameraMovesAsScripted)
{
    Camera& view = state.view_camera();
    view.position = {0, 0, 0};
    view.yaw_degrees = 0;
    view.pitch_degrees = 0;
    state.set_move_speed(100.0f);

    CameraInput forward;
    forward.forward = true;
    state.step_camera(forward, 0.5f); // +x at 100 u/s for half a second
    expect_near(view.position, {50, 0, 0}, 1e-3f);

    CameraInput right;
    right.right = true;
    state.step_camera(right, 1.0f); // looking along +x with z up, right is -y
    expect_near(view.position, {50, -100, 0}, 1e-3f);

    CameraInput up_fast;
    up_fast.up = true;
    up_fast.fast = true;
    state.step_camera(up_fast, 0.25f); // E: +z, shift: 4x
    expect_near(view.position, {50, -100, 100}, 1e-3f);

    CameraInput look;
    look.look = {100.0f, -20.0f}; // mouse right and up: turn right, look up
    state.step_camera(look, 0.0f);
    EXPECT_NEAR(view.yaw_degrees, -100.0f * gui::kLookDegreesPerPixel, 1e-4f);
    EXPECT_NEAR(view.pitch_degrees, 20.0f * gui::kLookDegreesPerPixel, 1e-4f);
    expect_near(view.position, {50, -100, 100}, 1e-3f); // looking does not move

    // W follows the view direction, pitch included.
    const glm::vec3 before = view.position;
    state.step_camera(forward, 1.0f);
    expect_near(view.position, before + view.forward() * 100.0f, 1e-2f);

    look.look = {0.0f, -10000.0f};
    state.step_camera(look, 0.0f);
    EXPECT_FLOAT_EQ(view.pitch_degrees, gui::kMaxPitchDegrees);

    CameraInput wheel;
    wheel.wheel = 2.0f;
    state.step_camera(wheel, 0.0f);
    EXPECT_NEAR(state.move_speed(), 100.0f * gui::kSpeedStep * gui::kSpeedStep, 1e-3f);

    // Opposite keys cancel; the culling camera follows while unlocked.
    CameraInput both;
    both.left = both.right = true;
    const glm::vec3 still = view.position;
    state.step_camera(both, 1.0f);
    expect_near(view.position, still, 1e-6f);
    expect_near(state.cull_camera().position, view.position, 0.0f);
}

TEST_F(DemoInspector, LockFreezesTheCullingCamera)
{
    state.cull_mode = CullMode::PvsFrustum;
    state.frame();
    state.set_lock(true);
    const Camera locked = state.cull_camera();

    CameraInput fly;
    fly.back = true;
    fly.look = {300.0f, 0.0f};
    state.step_camera(fly, 0.5f);
    const CullStats& s = state.frame();

    EXPECT_NE(state.view_camera().position, locked.position);
    EXPECT_EQ(state.cull_camera().position, locked.position);
    EXPECT_EQ(state.cull_camera().yaw_degrees, locked.yaw_degrees);
    std::vector<uint32_t> expected_visible;
    expect_same_cull(s, cull_alone(state.zone(), locked, CullMode::PvsFrustum, &expected_visible));
    EXPECT_EQ(state.visible_regions(), expected_visible);
    // The view moved, so culling from it would differ: the lock is what made them equal.
    EXPECT_NE(cull_alone(state.zone(), state.view_camera(), CullMode::PvsFrustum).regions_after_frustum,
              s.regions_after_frustum);

    state.set_lock(false);
    EXPECT_EQ(state.cull_camera().position, state.view_camera().position);
    const CullStats& after = state.frame();
    expect_same_cull(after, cull_alone(state.zone(), state.view_camera(), CullMode::PvsFrustum));
    state.step_camera(fly, 0.5f);
    EXPECT_EQ(state.cull_camera().position, state.view_camera().position);
}

TEST_F(DemoInspector, ModeSwitchesChangeTheStats)
{
    state.cull_mode = CullMode::None;
    const CullStats none = state.frame();
    EXPECT_EQ(none.regions_after_frustum, none.regions_total); // none draws every region
    EXPECT_EQ(state.visible_regions().size(), state.zone().region_count());
    EXPECT_EQ(none.triangles_after_frustum, state.zone_stats().triangles);

    state.cull_mode = CullMode::Frustum;
    const CullStats frustum = state.frame();
    EXPECT_LT(frustum.regions_after_frustum, none.regions_after_frustum);
    EXPECT_GT(frustum.regions_after_frustum, 0u);
    EXPECT_FALSE(frustum.pvs_used);

    // Without a PVS source (the demo zone may carry one: switch it off) the PVS modes fall
    // back to everything / the frustum.
    ASSERT_TRUE(state.set_pvs_source(gui::PvsSource::None));
    state.cull_mode = CullMode::PvsFrustum;
    expect_same_cull(state.frame(), frustum);

    // The render mode changes the picture, not the culling.
    std::vector<uint8_t> textured = state.image().rgba;
    state.render_mode = ui::RenderMode::RegionColors;
    expect_same_cull(state.frame(), frustum);
    EXPECT_NE(state.image().rgba, textured);
    EXPECT_EQ(state.totals().frames, 4u);
}

TEST(InspectorOnE1m1, PvsModesCullMoreThanTheFrustum)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    InspectorState state;
    state.set_viewport_size(160, 120);
    ASSERT_TRUE(state.open_zone(path)) << state.error();
    ASSERT_TRUE(state.zone().baked_pvs);

    CullStats by_mode[4];
    const CullMode modes[4] = {CullMode::None, CullMode::Frustum, CullMode::Pvs, CullMode::PvsFrustum};
    for (int i = 0; i < 4; ++i) {
        state.cull_mode = modes[i];
        by_mode[i] = state.frame();
        ASSERT_EQ(by_mode[i].camera, CameraPlace::InRegion);
    }
    const uint32_t total = by_mode[0].regions_total;
    EXPECT_EQ(by_mode[0].regions_after_frustum, total);
    EXPECT_LT(by_mode[1].regions_after_frustum, total);
    EXPECT_TRUE(by_mode[2].pvs_used);
    EXPECT_LT(by_mode[2].regions_after_frustum, total);
    EXPECT_EQ(by_mode[2].regions_after_frustum, by_mode[2].regions_after_pvs);
    EXPECT_LE(by_mode[3].regions_after_frustum, by_mode[2].regions_after_frustum);
    EXPECT_LE(by_mode[3].regions_after_frustum, by_mode[1].regions_after_frustum);
    EXPECT_EQ(by_mode[3].regions_after_pvs, by_mode[2].regions_after_pvs);
}

TEST_F(DemoInspector, PickAtTheCentreSelectsWhatTheIdBufferShows)
{
    state.set_viewport_size(200, 150);
    state.frame();
    const auto selection = state.pick(100, 75);
    ASSERT_TRUE(selection);

    // An independent ID render of the same camera and visible set.
    ui::SoftwareRenderer renderer(200, 150);
    const ui::Image ids =
        renderer.render(state.zone(), state.view_camera(), state.visible_regions(), ui::RenderMode::IdBuffer);
    const uint32_t face = ui::face_at(ids, 100, 75);
    ASSERT_NE(face, ui::kNoFace);
    EXPECT_EQ(selection->face, face);

    std::vector<uint32_t> listing; // the regions whose face list holds the face
    for (uint32_t r = 0; r < state.zone().region_count(); ++r) {
        const auto faces = state.zone().faces_of_region(r);
        if (std::find(faces.begin(), faces.end(), face) != faces.end())
            listing.push_back(r);
    }
    EXPECT_EQ(selection->face_regions, listing);
    ASSERT_GE(selection->region, 0);
    EXPECT_TRUE(std::binary_search(listing.begin(), listing.end(), uint32_t(selection->region)));
    EXPECT_TRUE(std::binary_search(state.visible_regions().begin(), state.visible_regions().end(),
                                   uint32_t(selection->region)));
    EXPECT_EQ(state.shown_region(), selection->region);

    EXPECT_FALSE(state.pick(200, 0)); // outside the picture: no selection
    EXPECT_EQ(state.selection().region, -1);
    state.select_region(3);
    EXPECT_EQ(state.shown_region(), 3);
}

TEST_F(DemoInspector, GoToRegionPutsTheCameraInIt)
{
    const uint32_t target = uint32_t(state.zone().region_count() / 2);
    state.go_to_region(target);
    EXPECT_EQ(state.frame().region, int32_t(target));
}

TEST_F(DemoInspector, BadFileKeepsTheZoneAndSaysWhy)
{
    const uint64_t generation = state.zone_generation();
    EXPECT_FALSE(state.open_zone("/nonexistent/zone.bsp"));
    EXPECT_FALSE(state.error().empty());
    ASSERT_TRUE(state.has_zone());
    EXPECT_EQ(state.zone_generation(), generation);
    state.open_demo();
    EXPECT_TRUE(state.error().empty());
    EXPECT_EQ(state.zone_generation(), generation + 1);
}

TEST_F(DemoInspector, ExportHasTheZoneReportAndTheCullingStats)
{
    state.cull_mode = CullMode::None;
    state.frame();
    state.cull_mode = CullMode::Frustum;
    const CullStats last = state.frame();

    const auto json = nlohmann::json::parse(state.export_stats_json());
    EXPECT_EQ(json["format"], state.zone().source.format);
    EXPECT_EQ(json["file"], state.zone().source.path);
    EXPECT_EQ(json["counts"]["regions"], state.zone().region_count());
    EXPECT_EQ(json["counts"]["triangles"], state.zone_stats().triangles);
    EXPECT_TRUE(json.contains("pvs"));
    EXPECT_TRUE(json.contains("region_flags"));
    EXPECT_TRUE(json.contains("tree"));
    const auto& culling = json["culling"];
    EXPECT_EQ(culling["frames"], 2);
    const double expected_mean =
        (double(state.zone().region_count()) + double(last.regions_after_frustum)) / 2.0;
    EXPECT_DOUBLE_EQ(culling["mean_regions_drawn"].get<double>(), expected_mean);
    EXPECT_EQ(culling["last_frame"]["mode"], "frustum");
    EXPECT_EQ(culling["last_frame"]["regions_drawn"], last.regions_after_frustum);
    EXPECT_EQ(culling["last_frame"]["region"], last.region);

    const std::string csv = state.export_stats_csv();
    std::istringstream lines(csv);
    std::string header, values, extra;
    ASSERT_TRUE(std::getline(lines, header));
    ASSERT_TRUE(std::getline(lines, values));
    EXPECT_FALSE(std::getline(lines, extra));
    EXPECT_NE(header.find("counts.regions"), std::string::npos);
    EXPECT_NE(header.find("culling.frames"), std::string::npos);
    EXPECT_NE(header.find("culling.last_frame.regions_drawn"), std::string::npos);
    const auto names = split_csv_line(header), fields = split_csv_line(values);
    ASSERT_EQ(names.size(), fields.size());
    const auto field = [&](const std::string& name) {
        const auto at = std::find(names.begin(), names.end(), name);
        return at == names.end() ? std::string("(absent)") : fields[size_t(at - names.begin())];
    };
    EXPECT_EQ(field("file"), state.zone().source.path); // "gen:rooms=60,seed=2026": quoted, comma kept
    EXPECT_EQ(field("counts.regions"), std::to_string(state.zone().region_count()));
    EXPECT_EQ(field("culling.frames"), "2");
    EXPECT_EQ(field("culling.last_frame.mode"), "frustum");
}

TEST(FrameHistory, KeepsTheNewestFramesOldestFirst)
{
    gui::FrameHistory history;
    EXPECT_EQ(history.size(), 0u);
    const size_t pushed = gui::kFrameHistoryCapacity + 10;
    for (size_t i = 0; i < pushed; ++i)
        history.push({float(i), 0, 0, 0});
    ASSERT_EQ(history.size(), gui::kFrameHistoryCapacity);
    EXPECT_EQ(history.at(0).lookup_us, float(pushed - gui::kFrameHistoryCapacity));
    EXPECT_EQ(history.newest().lookup_us, float(pushed - 1));
    for (size_t i = 1; i < history.size(); ++i)
        EXPECT_EQ(history.at(i).lookup_us, history.at(i - 1).lookup_us + 1.0f);
    history.clear();
    EXPECT_EQ(history.size(), 0u);
}

} // namespace
} // namespace pvs
