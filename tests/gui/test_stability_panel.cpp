// The inspector's Stability panel (ui/gui/stability_panel.cpp) headless: a cell opens its case at
// the case's camera and culls with that method's PVS, the pairs the method misses are listed
// against the case's truth (the reference misses the 0.1 crack: its beam cannot pass it), opening
// another zone forgets the case, and the panel draws its grid with the null backend.
#include "tests/gui/headless_imgui.h"

#include <imgui_internal.h> // FindWindowByName
#include "ui/gui/inspector_state.h"
#include "ui/gui/panels.h"
#include "gen/stability_cases.h"

#include <gtest/gtest.h>

namespace pvs {
namespace {

TEST(InspectorStability, ACellOpensItsCaseWithThatMethodsPvs)
{
    gui::InspectorState state;
    state.set_viewport_size(64, 48);
    ASSERT_TRUE(state.open_stability_case("crack-0.1", "portal-full"));
    EXPECT_EQ(state.zone().source.path, "case:crack-0.1");
    EXPECT_EQ(state.stability_case_name(), "crack-0.1");
    EXPECT_EQ(state.baked_label(), "portal-full on case crack-0.1");
    EXPECT_EQ(state.pvs_source(), gui::PvsSource::Baked);
    EXPECT_TRUE(state.stability_case_missing().empty());
    const gen::StabilityCase crafted = gen::make_stability_case("crack-0.1");
    EXPECT_EQ(state.view_camera().position, crafted.camera.position);
    state.cull_mode = CullMode::Pvs;
    const CullStats stats = state.frame();
    EXPECT_TRUE(stats.pvs_used);
    EXPECT_EQ(stats.regions_after_pvs, 3u); // A sees the crack and B

    ASSERT_TRUE(state.open_stability_case("crack-0.1", "reference"));
    EXPECT_EQ(state.stability_case_missing().size(), 6u); // A, D, B: every pair but the diagonal
    EXPECT_FALSE(state.open_stability_case("crack-0.1", "file"));
    EXPECT_FALSE(state.open_stability_case("no-such-case", "portal-full"));
    EXPECT_EQ(state.stability_case_name(), "crack-0.1"); // a refused cell keeps the open case

    state.open_demo();
    EXPECT_TRUE(state.stability_case_name().empty());
}

TEST(InspectorStability, PanelDrawsTheGridWithTheNullBackend)
{
    test::create_headless_imgui_context();
    gui::InspectorState state;
    state.set_viewport_size(64, 48);
    gui::StabilityPanel panel;
    panel.options.cases = {"wall-0.1", "crack-0.1"};
    panel.options.reference_samples = 128;
    panel.table = gen::run_case_table(panel.options);
    ASSERT_EQ(panel.table->rows.size(), 2u * panel.options.methods.size());
    int vertices = 0;
    for (int i = 0; i < 2; ++i) {
        ImGui::NewFrame();
        ImGui::SetNextWindowSize({700, 400});
        gui::draw_stability_panel(state, panel);
        ImGui::Render();
        vertices = ImGui::GetDrawData()->TotalVtxCount;
    }
    EXPECT_GT(vertices, 400) << "the grid's header and eight cells";
    EXPECT_NE(ImGui::FindWindowByName("Stability"), nullptr);
    ImGui::DestroyContext();
}

} // namespace
} // namespace pvs
