// Depth-tested overlay lines (ui/overlay_lines.h with ui/picture_occlusion.h), the mesh tracer's
// face filter under them, the inspector's hover against its ID-render pick, portals built on a
// background thread and the hand-edited pairs on the overlay.
//
// Known answers are worked out from the geometry: a wall square at distance 10 of half-size 5
// seen by a 90-degree camera covers exactly the middle half of a square picture, so a line
// behind it is hidden exactly over that half (up to half a depth-test piece at each end).
#include "ui/gui/inspector_state.h"
#include "render/overlay_lines.h"
#include "render/picture_occlusion.h"
#include "render/zone_overlays.h"
#include "visibility/portal/portalize.h"
#include "visibility/reference/mesh_tracer.h"

#include <gtest/gtest.h>

#include <chrono>
#include <glm/geometric.hpp>
#include <thread>

namespace pvs {
namespace {

using ui::Image;

// One region: the square x = 10, y and z in [-5, 5], its front facing -x (the camera's side).
Zone wall_zone()
{
    Zone zone;
    const glm::vec3 a{10, 5, -5}, b{10, -5, -5}, c{10, -5, 5}, d{10, 5, 5};
    zone.mesh.positions = {a, b, c, d};
    zone.mesh.uvs.assign(4, glm::vec2(0.0f));
    zone.mesh.indices = {0, 1, 2, 0, 2, 3};
    zone.mesh.faces.push_back({0, 2, 0});
    EXPECT_LT(glm::cross(b - a, c - a).x, 0.0f) << "the wall must face -x";
    zone.regions.resize(1);
    zone.regions[0].bounds.grow({0, -5, -5});
    zone.regions[0].bounds.grow({10, 5, 5});
    zone.region_faces = {0};
    zone.region_face_offsets = {0, 1};
    zone.materials.push_back({"plain", 0, 0, {}, 0});
    return zone;
}

Camera square_camera() // at the origin looking along +x, 90 degrees, square picture
{
    Camera c;
    c.fov_y_degrees = 90;
    c.aspect = 1;
    c.near_distance = 1;
    c.far_distance = 1000;
    return c;
}

Image black(uint32_t size)
{
    Image image;
    image.width = image.height = size;
    image.rgba.assign(size_t(size) * size * 4, 0);
    for (size_t i = 3; i < image.rgba.size(); i += 4)
        image.rgba[i] = 255;
    return image;
}

// Columns of row `y` whose red channel equals `red` (the lines below are yellow on black).
std::vector<uint32_t> columns_with_red(const Image& image, uint32_t y, uint8_t red)
{
    std::vector<uint32_t> columns;
    for (uint32_t x = 0; x < image.width; ++x)
        if (image.pixel(x, y)[0] == red)
            columns.push_back(x);
    return columns;
}

TEST(MeshTracerFilter, DrawnFacesAndFrontSidesOnly)
{
    const Zone zone = wall_zone();
    const MeshTracer tracer(zone);
    const uint8_t drawn[1] = {1}, not_drawn[1] = {0};
    const MeshTracer::FaceFilter all{}, only_drawn{drawn, true}, none_drawn{not_drawn, true};
    const MeshTracer::FaceFilter any_side{drawn, false};
    EXPECT_TRUE(tracer.occluded({0, 0, 0}, {1, 0, 0}, 20.0f, all));
    EXPECT_TRUE(tracer.occluded({0, 0, 0}, {1, 0, 0}, 20.0f, only_drawn));
    EXPECT_FALSE(tracer.occluded({0, 0, 0}, {1, 0, 0}, 9.9f, only_drawn)) << "short of the wall";
    EXPECT_FALSE(tracer.occluded({0, 0, 0}, {1, 0, 0}, 20.0f, none_drawn)) << "a face not drawn hides nothing";
    // From behind, the wall shows its back: a renderer culling back faces draws nothing there.
    EXPECT_FALSE(tracer.occluded({20, 0, 0}, {-1, 0, 0}, 20.0f, only_drawn));
    EXPECT_TRUE(tracer.occluded({20, 0, 0}, {-1, 0, 0}, 20.0f, any_side));
    const MeshTracer::Hit hit = tracer.first_hit({0, 1, 1}, {1, 0, 0}, 100.0f, only_drawn);
    ASSERT_TRUE(hit.hit);
    EXPECT_EQ(hit.face, 0u);
    EXPECT_NEAR(hit.t, 10.0f, 1e-4f);
    EXPECT_FALSE(tracer.first_hit({0, 1, 1}, {1, 0, 0}, 100.0f, none_drawn).hit);
}

struct DepthTestedLine : ::testing::Test {
    void SetUp() override { occlusion.set_frame(zone, square_camera(), 100, 100, std::vector<uint32_t>{0}); }
    // The line y = -15 .. 15 at x = 20, z = 0 projects to columns 12.5 .. 87.5 of row 50; the wall
    // hides columns 25 .. 75 of it.
    Image draw(ui::HiddenLines mode, float x = 20.0f)
    {
        Image image = black(100);
        ui::LineProjection lines(square_camera());
        lines.occlusion = &occlusion;
        lines.hidden_lines = mode;
        ui::draw_line_3d(image, lines, {x, 15, 0}, {x, -15, 0}, 0xFFFF00);
        return image;
    }
    Zone zone = wall_zone();
    ui::PictureOcclusion occlusion{zone};
};

TEST_F(DepthTestedLine, TheHiddenPartIsTheWallsProjection)
{
    const uint32_t slack = ui::kDepthPiecePixels / 2 + 1;
    const Image hidden = draw(ui::HiddenLines::Hidden);
    const std::vector<uint32_t> full = columns_with_red(hidden, 50, 255);
    ASSERT_FALSE(full.empty());
    for (uint32_t x : full)
        EXPECT_TRUE(x < 25 + slack || x >= 75 - slack) << "column " << x << " is behind the wall";
    EXPECT_LE(full.front(), 13u);
    EXPECT_GE(full.back(), 86u);
    EXPECT_GT(occlusion.rays(), 5u);

    const Image faint = draw(ui::HiddenLines::Faint);
    const auto faint_red = uint8_t((255u * ui::kFaintLineAlpha + 127u) / 255u);
    const std::vector<uint32_t> dim = columns_with_red(faint, 50, faint_red);
    ASSERT_FALSE(dim.empty());
    for (uint32_t x : dim)
        EXPECT_TRUE(x >= 25 - slack && x < 75 + slack) << "column " << x << " is in sight";
    EXPECT_GE(dim.size(), 50u - 2 * slack);
    EXPECT_EQ(columns_with_red(faint, 50, 255), full) << "the parts in sight are drawn the same";

    const Image shown = draw(ui::HiddenLines::Shown);
    EXPECT_EQ(columns_with_red(shown, 50, 255).size(), 76u) << "no depth test: columns 12 .. 87";
}

TEST_F(DepthTestedLine, LinesInFrontOfOrOnTheWallStayInSight)
{
    EXPECT_EQ(columns_with_red(draw(ui::HiddenLines::Hidden, 9.0f), 50, 255).size(),
              columns_with_red(draw(ui::HiddenLines::Shown, 9.0f), 50, 255).size());
    // On the wall itself (x = 10, inside its square): within the depth bias, so not hidden.
    Image image = black(100);
    ui::LineProjection lines(square_camera());
    lines.occlusion = &occlusion;
    lines.hidden_lines = ui::HiddenLines::Hidden;
    ui::draw_line_3d(image, lines, {10, 4, 0}, {10, -4, 0}, 0xFFFF00);
    EXPECT_EQ(columns_with_red(image, 50, 255).size(), 41u) << "columns 30 .. 70";
    // A wall not drawn this frame hides nothing.
    occlusion.set_frame(zone, square_camera(), 100, 100, std::vector<uint32_t>{});
    EXPECT_EQ(columns_with_red(draw(ui::HiddenLines::Hidden), 50, 255).size(), 76u);
}

TEST_F(DepthTestedLine, FaceUnderTheMouseIsTheWallInsideItsSquareOnly)
{
    const auto hit = occlusion.face_under({1, 0.2f, -0.3f});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->face, 0u);
    EXPECT_NEAR(hit->distance, 10.0f * glm::length(glm::vec3(1, 0.2f, -0.3f)), 1e-3f);
    EXPECT_FALSE(occlusion.face_under({1, 0.6f, 0}));  // beside the wall (|y| = 6 > 5 at x = 10)
    EXPECT_FALSE(occlusion.face_under({-1, 0, 0}));    // behind the eye
    EXPECT_FALSE(occlusion.face_under({0, 0, 0}));     // no direction
}

// ---- In the inspector, on the demo zone ----------------------------------------------------------

struct DepthInspector : ::testing::Test {
    void SetUp() override
    {
        state.set_viewport_size(160, 120);
        state.open_demo();
        ASSERT_TRUE(state.has_zone());
        state.overlays = {};
        state.overlays.zone_lines = false;
    }
    gui::InspectorState state;
};

TEST_F(DepthInspector, HoverNamesTheFaceAnIdRenderPicks)
{
    state.frame();
    size_t compared = 0, agreed = 0;
    for (uint32_t y = 3; y < 120; y += 9)
        for (uint32_t x = 3; x < 160; x += 9) {
            const auto picked = state.pick(x, y);
            const auto hovered = state.hover(x, y);
            if (!picked && !hovered)
                continue;
            ++compared;
            if (picked && hovered && picked->face == hovered->face) {
                ++agreed;
                EXPECT_TRUE(std::equal(hovered->regions.begin(), hovered->regions.end(),
                                       picked->face_regions.begin(), picked->face_regions.end()));
                uint32_t flags = 0;
                for (uint32_t r : picked->face_regions)
                    flags |= state.zone().regions[r].flags;
                EXPECT_EQ(hovered->flags, flags);
            }
        }
    ASSERT_GT(compared, 100u);
    // A ray and a rasteriser disagree only on pixels a face edge crosses.
    EXPECT_GE(double(agreed), 0.97 * double(compared)) << agreed << " of " << compared;
    EXPECT_FALSE(state.hover(500, 10)) << "outside the picture";
}

TEST_F(DepthInspector, LinesBehindWallsAreDimmedOrHiddenByTheToggle)
{
    state.overlays.region_bounds = true;
    state.overlays.hidden_lines = ui::HiddenLines::Shown;
    state.frame();
    const Image shown = state.image();
    EXPECT_EQ(state.overlay_depth_rays(), 0u);
    state.overlays.hidden_lines = ui::HiddenLines::Hidden;
    state.frame();
    const Image hidden = state.image();
    EXPECT_GT(state.overlay_depth_rays(), 50u);
    state.overlays.hidden_lines = ui::HiddenLines::Faint;
    state.frame();
    const Image faint = state.image();
    // The demo camera stands in a room: most region boxes lie behind its walls.
    size_t differ_hidden = 0, differ_faint = 0;
    for (size_t i = 0; i < shown.rgba.size(); i += 4) {
        differ_hidden += shown.rgba[i] != hidden.rgba[i] || shown.rgba[i + 1] != hidden.rgba[i + 1] ? 1 : 0;
        differ_faint += shown.rgba[i] != faint.rgba[i] || shown.rgba[i + 1] != faint.rgba[i + 1] ? 1 : 0;
    }
    EXPECT_GT(differ_hidden, 50u);
    EXPECT_GT(differ_faint, 50u);
}

TEST_F(DepthInspector, PortalsAreBuiltInTheBackgroundAndDrawnWhenReady)
{
    ASSERT_FALSE(state.zone().portals) << "the demo zone's portals come from its tree";
    state.overlays.portals = true;
    state.frame(); // starts the build
    EXPECT_TRUE(state.portals_building() || state.portals_ready());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!state.portals_ready() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        state.frame(); // takes the finished set
    }
    ASSERT_TRUE(state.portals_ready());
    const PortalSet direct = build_zone_portals(state.zone());
    EXPECT_EQ(state.ready_portals()->portals.size(), direct.portals.size());
    EXPECT_EQ(state.ready_portals()->points.size(), direct.points.size());
    EXPECT_GT(direct.portals.size(), 10u);
}

TEST_F(DepthInspector, OpeningAnotherZoneWaitsForTheBuildInFlight)
{
    state.request_portals();
    state.open_demo(); // must not leave the thread reading the old zone
    EXPECT_FALSE(state.portals_ready());
    EXPECT_FALSE(state.portals_building());
    EXPECT_GT(state.wait_for_portals().portals.size(), 10u);
}

TEST_F(DepthInspector, HandEditedPairsAreBoxedWhileTheEditedPvsCulls)
{
    const int32_t camera = state.frame().region;
    ASSERT_GE(camera, 0);
    const Pvs& pvs = *state.active_pvs();
    uint32_t target = UINT32_MAX;
    for (uint32_t r = 0; r < pvs.region_count() && target == UINT32_MAX; ++r)
        if (r != uint32_t(camera) && pvs.visible(uint32_t(camera), r))
            target = r;
    ASSERT_NE(target, UINT32_MAX);
    EXPECT_TRUE(state.edited_pairs().empty());
    ASSERT_TRUE(state.edit_pvs(pair_edit(uint32_t(camera), target, false, false)));
    state.frame();
    EXPECT_EQ(state.edited_pairs(), std::vector<uint32_t>{target});
    EXPECT_TRUE(state.undo_pvs_edit());
    state.frame();
    EXPECT_TRUE(state.edited_pairs().empty()) << "undone: the bit is as before";

    // The painter boxes them in kEditedPairColor, and the legend names the colour.
    Image image = black(160);
    ui::OverlayScene scene;
    scene.zone = &state.zone();
    // Looking along +x at the region's box from outside it.
    const Aabb& box = state.zone().regions[target].bounds;
    scene.view = square_camera();
    scene.view.position = box.center() - glm::vec3(2.0f * (box.max.x - box.min.x) + 10.0f, 0, 0);
    const std::vector<uint32_t> edited{target};
    scene.edited_regions = edited;
    ui::OverlaySettings settings{};
    settings.zone_lines = false;
    std::vector<ui::OverlayLabel> labels;
    ui::paint_overlays(image, settings, scene, labels);
    size_t boxed = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
        boxed += image.rgba[i] == 0xFF && image.rgba[i + 1] == 0x60 && image.rgba[i + 2] == 0xFF ? 1 : 0;
    EXPECT_GT(boxed, 20u);
    bool named = false;
    for (const ui::LegendEntry& e : ui::overlay_legend(settings, false, true))
        named |= e.rgb == ui::kEditedPairColor;
    EXPECT_TRUE(named);
}

} // namespace
} // namespace pvs
