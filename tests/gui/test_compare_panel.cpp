// The inspector's Compare panel and its job (ui/gui/compare_job.h) headless on the demo zone: the
// compare runs on a background thread, a row's PVS becomes the culling source (a click on the
// chart or the table calls use_compared_pvs), and the panel draws its chart with the null backend.
#include "tests/gui/headless_imgui.h"

#include <imgui_internal.h> // FindWindowByName
#include "ui/gui/inspector_state.h"
#include "ui/gui/panels.h"
#include "ui/gui/pvs_rows.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace pvs {
namespace {

using gui::JobStatus;

ui::CompareOptions small_compare()
{
    ui::CompareOptions options;
    options.methods = {"none", "portal-fast"};
    options.reference_samples = 64;
    options.cameras = 3;
    options.threads = 1;
    return options;
}

void wait(gui::InspectorState& state)
{
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (state.compare_job().poll() == JobStatus::Running && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

TEST(InspectorCompare, ARowsPvsBecomesTheCullingSource)
{
    gui::InspectorState state;
    state.set_viewport_size(64, 48);
    state.open_demo();
    ASSERT_TRUE(state.start_compare(small_compare()));
    EXPECT_FALSE(state.start_compare(small_compare())) << "one compare at a time";
    wait(state);
    ASSERT_EQ(state.compare_job().status(), JobStatus::Done) << state.compare_job().error();
    const ui::CompareResult& result = *state.compare_job().result();
    ASSERT_EQ(result.rows.size(), 3u); // reference (64 lines), none, portal-fast
    EXPECT_EQ(result.rows[2].method, "portal-fast");

    ASSERT_TRUE(state.use_compared_pvs(2));
    EXPECT_EQ(state.pvs_source(), gui::PvsSource::Baked);
    EXPECT_EQ(state.baked_label(), "portal-fast");
    ASSERT_NE(state.active_pvs(), nullptr);
    const Pvs& chosen = *result.rows[2].pvs;
    for (uint32_t r = 0; r < chosen.region_count(); r += 5)
        EXPECT_EQ(gui::pvs_row_regions(*state.active_pvs(), r), gui::pvs_row_regions(chosen, r)) << "row " << r;
    state.cull_mode = CullMode::Pvs;
    EXPECT_TRUE(state.frame().pvs_used);

    ASSERT_TRUE(state.use_compared_pvs(1)); // none
    EXPECT_EQ(state.pvs_source(), gui::PvsSource::None);
    EXPECT_FALSE(state.use_compared_pvs(3));

    state.open_demo(); // a new zone stops and forgets nothing it should not: the job is not running
    EXPECT_NE(state.compare_job().status(), JobStatus::Running);
}

TEST(InspectorCompare, PanelDrawsTheChartWithTheNullBackend)
{
    test::create_headless_imgui_context();
    gui::InspectorState state;
    state.set_viewport_size(64, 48);
    state.open_demo();
    ASSERT_TRUE(state.start_compare(small_compare()));
    wait(state);
    gui::ComparePanel panel;
    int vertices = 0;
    for (int i = 0; i < 2; ++i) {
        ImGui::NewFrame();
        ImGui::SetNextWindowSize({700, 600});
        gui::draw_compare_panel(state, panel);
        ImGui::Render();
        vertices = ImGui::GetDrawData()->TotalVtxCount;
    }
    EXPECT_GT(vertices, 2000) << "the chart's axes, points and labels, and the table";
    EXPECT_NE(ImGui::FindWindowByName("Compare"), nullptr);
    ImGui::DestroyContext();
}

} // namespace
} // namespace pvs
