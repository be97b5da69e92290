// The overlay geometry (ui/overlay_fill.h) and the overlay painter (ui/zone_overlays.h): pixel
// coverage of a translucent polygon against the area its projection must cover (worked out by
// hand from the camera), near-plane clipping, shared edges covered once, region membership
// classes, the legend following the toggles, and the painter's overlays in the inspector.
#include "tests/support/test_data.h"
#include "ui/gui/inspector_state.h"
#include "render/overlay_fill.h"
#include "render/zone_overlays.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/vec3.hpp>

namespace pvs {
namespace {

using ui::Image;

Image black(uint32_t width, uint32_t height)
{
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(size_t(width) * height * 4, 0);
    for (size_t i = 3; i < image.rgba.size(); i += 4)
        image.rgba[i] = 255;
    return image;
}

// At the origin looking along +x, 90 degrees vertical field of view, square picture: a point
// (d, y, z) lands at NDC (-y/d, z/d), so the picture spans y, z in [-d, d] at distance d.
Camera square_camera()
{
    Camera c;
    c.position = {0, 0, 0};
    c.yaw_degrees = 0;
    c.pitch_degrees = 0;
    c.fov_y_degrees = 90;
    c.aspect = 1;
    c.near_distance = 1;
    c.far_distance = 1000;
    return c;
}

size_t count_colour(const Image& image, uint8_t r, uint8_t g, uint8_t b)
{
    size_t n = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
        n += image.rgba[i] == r && image.rgba[i + 1] == g && image.rgba[i + 2] == b ? 1 : 0;
    return n;
}

TEST(OverlayFill, SquareCoversTheHalfOfThePictureItProjectsTo)
{
    Image image = black(100, 100);
    // At distance 10, y and z in [-5, 5]: NDC [-0.5, 0.5], pixels [25, 75) both ways.
    const std::array<glm::vec3, 4> square{{{10, -5, -5}, {10, 5, -5}, {10, 5, 5}, {10, -5, 5}}};
    const uint32_t alpha = 64;
    EXPECT_EQ(ui::fill_polygon_3d(image, square_camera(), square, 0xFF8000, alpha), 2500u);
    const auto expected_r = uint8_t((255u * alpha + 128u) >> 8), expected_g = uint8_t((128u * alpha + 128u) >> 8);
    EXPECT_EQ(count_colour(image, expected_r, expected_g, 0), 2500u);
    EXPECT_EQ(image.pixel(25, 25)[0], expected_r);
    EXPECT_EQ(image.pixel(74, 74)[0], expected_r);
    EXPECT_EQ(image.pixel(24, 50)[0], 0);
    EXPECT_EQ(image.pixel(75, 50)[0], 0);
    EXPECT_EQ(image.pixel(50, 24)[0], 0);
    EXPECT_EQ(image.pixel(50, 75)[0], 0);
}

TEST(OverlayFill, TwoHalvesSharingAnEdgeCoverEachPixelOnce)
{
    Image image = black(100, 100);
    const std::array<glm::vec3, 4> left{{{10, 0, -5}, {10, 5, -5}, {10, 5, 5}, {10, 0, 5}}};
    const std::array<glm::vec3, 4> right{{{10, -5, -5}, {10, 0, -5}, {10, 0, 5}, {10, -5, 5}}};
    const uint32_t a = ui::fill_polygon_3d(image, square_camera(), left, 0xFFFFFF, 128);
    const uint32_t b = ui::fill_polygon_3d(image, square_camera(), right, 0xFFFFFF, 128);
    EXPECT_EQ(a + b, 2500u);
    EXPECT_EQ(a, 1250u);
    const uint8_t once = uint8_t((255u * 128u + 128u) >> 8);
    EXPECT_EQ(count_colour(image, once, once, once), 2500u); // none blended twice
}

TEST(OverlayFill, BehindTheCameraNothingAcrossTheNearPlaneOnlyTheFrontPart)
{
    Image image = black(100, 100);
    const Camera camera = square_camera();
    const std::array<glm::vec3, 4> behind{{{-10, -5, -5}, {-10, 5, -5}, {-10, 5, 5}, {-10, -5, 5}}};
    EXPECT_EQ(ui::fill_polygon_3d(image, camera, behind, 0xFFFFFF, 256), 0u);
    // A floor under the camera from behind it to far ahead: only the lower half of the picture
    // can show a floor (z < 0 projects below the horizon).
    const std::array<glm::vec3, 4> floor{{{-50, -50, -2}, {500, -50, -2}, {500, 50, -2}, {-50, 50, -2}}};
    const uint32_t covered = ui::fill_polygon_3d(image, camera, floor, 0xFFFFFF, 256);
    EXPECT_GT(covered, 1000u);
    for (uint32_t y = 0; y < 50; ++y)
        for (uint32_t x = 0; x < 100; ++x)
            ASSERT_EQ(image.pixel(x, y)[0], 0) << x << "," << y;
    const std::array<glm::vec3, 3> broken{{{10, 0, 0}, {10, NAN, 1}, {10, 1, 1}}};
    EXPECT_EQ(ui::fill_polygon_3d(image, camera, broken, 0xFFFFFF, 256), 0u);
    EXPECT_EQ(ui::fill_polygon_3d(image, camera, std::span<const glm::vec3>(floor).first(2), 0xFFFFFF, 256), 0u);
}

TEST(OverlayFill, ProjectionAndBoxes)
{
    const Camera camera = square_camera();
    const auto centre = ui::project_to_pixel(camera, 100, 100, {10, 0, 0});
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->x, 50.0f, 1e-3f);
    EXPECT_NEAR(centre->y, 50.0f, 1e-3f);
    const auto corner = ui::project_to_pixel(camera, 100, 100, {10, 5, 5}); // +y is left, +z up
    ASSERT_TRUE(corner);
    EXPECT_NEAR(corner->x, 25.0f, 1e-3f);
    EXPECT_NEAR(corner->y, 25.0f, 1e-3f);
    EXPECT_FALSE(ui::project_to_pixel(camera, 100, 100, {-10, 0, 0}));
    Image image = black(100, 100);
    Aabb box;
    box.grow({10, -5, -5});
    box.grow({20, 5, 5});
    EXPECT_GT(ui::draw_box_3d(image, camera, box, 0x00FF00), 100u);
    EXPECT_EQ(image.pixel(25, 50)[1], 255); // the near face's left edge
    EXPECT_EQ(ui::draw_box_3d(image, camera, Aabb{}, 0x00FF00), 0u);
}

TEST(OverlayFill, PrecomputedMatricesDrawTheSamePixels)
{
    Camera camera = square_camera();
    camera.yaw_degrees = 20;
    camera.pitch_degrees = -15;
    Image a = black(120, 90), b = black(120, 90);
    Aabb box;
    box.grow({8, -6, -4});
    box.grow({30, 7, 3});
    const ui::LineProjection lines(camera);
    EXPECT_EQ(ui::draw_box_3d(a, camera, box, 0xFF0000), ui::draw_box_3d(b, lines, box, 0xFF0000));
    const std::array<glm::vec3, 3> triangle{{{10, -3, -2}, {12, 4, 0}, {9, 0, 5}}};
    EXPECT_EQ(ui::outline_polygon_3d(a, camera, triangle, 0x00FF00), ui::outline_polygon_3d(b, lines, triangle, 0x00FF00));
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_GT(count_colour(a, 0xFF, 0, 0), 50u);
}

TEST(ZoneOverlays, MembershipClasses)
{
    Zone zone;
    zone.regions.resize(5);
    const std::vector<uint32_t> visible{1, 4}, after_pvs{1, 2, 4};
    const auto tint = [](ui::Membership m) { return ui::kMembershipTintBase + uint32_t(m); };
    std::vector<uint32_t> tints;
    ui::membership_tints(zone, 1, visible, after_pvs, tints);
    EXPECT_EQ(tints, (std::vector<uint32_t>{tint(ui::Membership::CulledByPvs), tint(ui::Membership::Current),
                                            tint(ui::Membership::CulledByFrustum), tint(ui::Membership::CulledByPvs),
                                            tint(ui::Membership::Drawn)}));
    ui::membership_tints(zone, -1, visible, after_pvs, tints); // no camera region: 1 is drawn
    EXPECT_EQ(tints[1], tint(ui::Membership::Drawn));
    const std::vector<uint32_t> area_culled{2}; // in the PVS and the frustum, behind a shut door
    ui::membership_tints(zone, 1, visible, after_pvs, tints, area_culled);
    EXPECT_EQ(tints[2], tint(ui::Membership::CulledByArea));
    EXPECT_EQ(tints[4], tint(ui::Membership::Drawn));
}

TEST(ZoneOverlays, LegendFollowsTheToggles)
{
    ui::OverlaySettings settings;
    settings.zone_lines = false;
    settings.locked_frustum = false;
    EXPECT_TRUE(ui::overlay_legend(settings).empty());
    settings.pvs_membership = true;
    EXPECT_EQ(ui::overlay_legend(settings).size(), 4u);
    settings.split_planes = true;
    settings.portals = true;
    const auto legend = ui::overlay_legend(settings);
    EXPECT_EQ(legend.size(), 7u);
    EXPECT_TRUE(std::any_of(legend.begin(), legend.end(), [](const ui::LegendEntry& e) {
        return e.rgb == ui::kPortalColor;
    }));
}

struct OverlayInspector : ::testing::Test {
    void SetUp() override
    {
        state.set_viewport_size(160, 120);
        state.open_demo();
        state.overlays = {};
        state.overlays.zone_lines = false;
        state.overlays.locked_frustum = false;
    }
    size_t changed_pixels(const ui::Image& a, const ui::Image& b)
    {
        size_t n = 0;
        for (size_t i = 0; i < a.rgba.size(); i += 4)
            n += !std::equal(a.rgba.begin() + long(i), a.rgba.begin() + long(i) + 3, b.rgba.begin() + long(i)) ? 1 : 0;
        return n;
    }
    gui::InspectorState state;
};

TEST_F(OverlayInspector, EachOverlayDrawsOnlyWhenOn)
{
    state.frame();
    const ui::Image plain = state.image();
    state.frame();
    EXPECT_EQ(changed_pixels(plain, state.image()), 0u); // the same camera draws the same picture
    for (bool ui::OverlaySettings::*toggle : {&ui::OverlaySettings::pvs_membership, &ui::OverlaySettings::split_planes,
                                              &ui::OverlaySettings::portals, &ui::OverlaySettings::region_bounds}) {
        state.overlays = {};
        state.overlays.zone_lines = false;
        state.overlays.*toggle = true;
        state.wait_for_portals(); // built on a background thread: wait, so this frame has them
        state.frame();
        EXPECT_GT(changed_pixels(plain, state.image()), 20u);
    }
    // IdBuffer pictures stay face codes.
    state.overlays.split_planes = true;
    state.render_mode = ui::RenderMode::IdBuffer;
    state.frame();
    const ui::Image ids = state.image();
    state.overlays = {};
    state.overlays.zone_lines = false;
    state.frame();
    EXPECT_EQ(changed_pixels(ids, state.image()), 0u);
}

TEST_F(OverlayInspector, MembershipSplitsTheRegionsLikeTheCullerStages)
{
    state.overlays.pvs_membership = true;
    state.cull_mode = CullMode::PvsFrustum;
    const CullStats s = state.frame();
    // after_pvs is what the PVS stage kept: as many as the stats count, and a superset of the drawn.
    EXPECT_EQ(state.after_pvs_regions().size(), s.regions_after_pvs);
    EXPECT_TRUE(std::includes(state.after_pvs_regions().begin(), state.after_pvs_regions().end(),
                              state.visible_regions().begin(), state.visible_regions().end()));
}

TEST_F(OverlayInspector, LockedFrustumIsDrawnInYellow)
{
    state.overlays.locked_frustum = true;
    state.frame();
    state.set_lock(true);
    // Step back and up, looking down at where the camera was: the frozen frustum is in view.
    Camera& view = state.view_camera();
    view.position -= view.forward() * 40.0f;
    view.position.z += 30.0f;
    view.pitch_degrees = -20.0f;
    state.frame();
    EXPECT_GT(count_colour(state.image(), 0xFF, 0xFF, 0x00), 20u);
}

TEST_F(OverlayInspector, ZoneLineIsLabelledWithItsTarget)
{
    const Zone& zone = state.zone();
    ASSERT_FALSE(zone.zone_lines.empty());
    const ZoneLine& line = zone.zone_lines[0];
    // Look at the trigger box's centre from a point in front of it.
    Camera& view = state.view_camera();
    view.position = line.bounds.center() + glm::vec3(0, 0, line.bounds.size().z * 0.25f);
    view.position.x -= line.bounds.size().x + 10.0f;
    view.yaw_degrees = 0;
    view.pitch_degrees = 0;
    state.overlays.zone_lines = true;
    state.cull_mode = CullMode::None;
    state.frame();
    ASSERT_FALSE(state.overlay_labels().empty());
    EXPECT_EQ(state.overlay_labels()[0].text, "-> " + line.target);
    state.overlays.zone_lines = false;
    state.frame();
    EXPECT_TRUE(state.overlay_labels().empty());
}

} // namespace
} // namespace pvs

namespace pvs {
namespace {

// A Quake 2 map's doors: shutting the areaportal between the camera's area and the next drops
// that area's regions from the frame (as the engine's areabits), and the overlay marks the door.
TEST(Quake2AreaPortals, AShutDoorDropsTheAreaBehindItAndShowsRed)
{
    SHARED_DATA_OR_SKIP(path, "modern-quake/q2/q2_areaportals.ericw-vis.bsp");
    gui::InspectorState state;
    state.set_viewport_size(160, 120);
    ASSERT_TRUE(state.open_zone(path));
    const Zone& zone = state.zone();
    ASSERT_EQ(state.closed_area_portals.size(), zone.area_portals.size());
    state.cull_mode = CullMode::Pvs; // every region of the row, whatever the view
    uint32_t in_area_1 = 0;
    while (in_area_1 < zone.region_count() && zone.region_areas[in_area_1] != 1)
        ++in_area_1;
    ASSERT_LT(in_area_1, zone.region_count());
    state.go_to_region(in_area_1);
    const CullStats open = state.frame();
    ASSERT_EQ(open.region, int32_t(in_area_1));
    EXPECT_EQ(state.last_area_dropped(), 0u);
    for (size_t p = 0; p < zone.area_portals.size(); ++p)
        if (zone.area_portals[p].areas[0] == 1 || zone.area_portals[p].areas[1] == 1)
            state.closed_area_portals[p] = 1;
    const CullStats shut = state.frame();
    EXPECT_GT(state.last_area_dropped(), 0u);
    EXPECT_EQ(shut.regions_after_frustum + state.last_area_dropped(), open.regions_after_frustum);
    // The dropped regions: each in a region's area the shut doors cut off, none of them drawn, and
    // each tinted as such (not "culled by frustum": they are in the frustum).
    ASSERT_EQ(state.last_area_culled().size(), state.last_area_dropped());
    std::vector<uint32_t> tints;
    ui::membership_tints(zone, shut.region, state.visible_regions(), state.after_pvs_regions(), tints,
                         state.last_area_culled());
    for (uint32_t r : state.last_area_culled()) {
        EXPECT_NE(zone.region_areas[r], 1);
        EXPECT_FALSE(std::binary_search(state.visible_regions().begin(), state.visible_regions().end(), r));
        EXPECT_EQ(tints[r], ui::kMembershipTintBase + uint32_t(ui::Membership::CulledByArea));
    }
    const auto legend = ui::overlay_legend(state.overlays, false, false, false, true);
    EXPECT_TRUE(std::any_of(legend.begin(), legend.end(),
                            [](const ui::LegendEntry& e) { return e.rgb == ui::kClosedAreaPortalColor; }));
    ui::OverlaySettings membership = state.overlays;
    membership.pvs_membership = true;
    const auto tinted_legend = ui::overlay_legend(membership, false, false, false, true);
    EXPECT_TRUE(std::any_of(tinted_legend.begin(), tinted_legend.end(),
                            [](const ui::LegendEntry& e) { return e.rgb == ui::kAreaCulledColor; }));
    const auto other_zones = ui::overlay_legend(membership, false, false, false, false);
    EXPECT_FALSE(std::any_of(other_zones.begin(), other_zones.end(),
                             [](const ui::LegendEntry& e) { return e.rgb == ui::kAreaCulledColor; }));
}

} // namespace
} // namespace pvs
