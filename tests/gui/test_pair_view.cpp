// The inspector's "why does A see B?" (ui/gui/pair_view.cpp), headless: the explanation comes
// back from its thread, the overlay draws the sight line and numbers the chain, and the camera
// button stands at the sight line's eye looking at B.
#include "tests/support/test_data.h"
#include "ui/gui/inspector_state.h"
#include "render/zone_overlays.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace pvs {
namespace {

size_t count_rgb(const ui::Image& image, uint32_t rgb)
{
    size_t n = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4)
        n += image.rgba[i] == ((rgb >> 16) & 0xFF) && image.rgba[i + 1] == ((rgb >> 8) & 0xFF) &&
             image.rgba[i + 2] == (rgb & 0xFF);
    return n;
}

TEST(PairView, ExplainsDrawsAndLooksAlongTheSightLine)
{
    SHARED_DATA_OR_SKIP(path, "quake/e1m1.bsp");
    gui::InspectorState state;
    state.set_viewport_size(320, 240);
    ASSERT_TRUE(state.open_zone(path));
    state.overlays = {};
    state.overlays.zone_lines = false;
    state.overlays.hidden_lines = ui::HiddenLines::Shown; // the chain is seen from outside its walls
    EXPECT_FALSE(state.request_explanation(0, 5000));
    EXPECT_NE(state.error().find("out of range"), std::string::npos) << state.error();

    ASSERT_TRUE(state.request_explanation(300, 200));
    const PairExplanation* e = state.wait_for_explanation();
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->verdict, PairVerdict::Sees) << e->summary;
    ASSERT_TRUE(e->chain);
    ASSERT_TRUE(e->witness);

    // From beside the chain (the inspector's docs screenshot camera), the orange sight line, the
    // green portals and their numbers are drawn; without the toggle, none of them.
    Camera& view = state.view_camera();
    view.position = {700.0f, 2100.0f, -480.0f};
    view.yaw_degrees = 80.0f;
    view.pitch_degrees = 45.0f;
    state.frame();
    EXPECT_GT(count_rgb(state.image(), ui::kSightLineColor), 20u);
    EXPECT_GT(count_rgb(state.image(), ui::kChainPortalColor), 50u);
    size_t numbers = 0;
    for (const ui::OverlayLabel& label : state.overlay_labels())
        numbers += label.rgb == ui::kChainPortalColor;
    EXPECT_EQ(numbers, e->chain->steps.size());
    state.overlays.pair_view = false;
    state.frame();
    EXPECT_EQ(count_rgb(state.image(), ui::kSightLineColor), 0u);
    EXPECT_EQ(count_rgb(state.image(), ui::kChainPortalColor), 0u);

    // The camera button: at the witness's eye, in region A, facing B's end.
    ASSERT_TRUE(state.look_along_witness());
    const CullStats s = state.frame();
    EXPECT_EQ(s.region, 300);
    const glm::vec3 toward = glm::normalize(glm::vec3(e->witness->to - e->witness->from));
    EXPECT_GT(glm::dot(state.view_camera().forward(), toward), 0.999f);

    state.clear_explanation();
    EXPECT_FALSE(state.explanation());
    EXPECT_FALSE(state.look_along_witness());
}

} // namespace
} // namespace pvs
