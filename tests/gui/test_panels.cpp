// The panels with ImGui's null backend (as imgui's example_null): a context with the font atlas
// built and io.DisplaySize set, NewFrame / draw / Render, no window and no GPU. Checks that every
// panel draws, that the viewport panel drives the state (render size, keys, picking) and that
// the culling panel's switches reach it.
#include "tests/gui/headless_imgui.h"
#include "ui/gui/panels.h"
#include "visibility/bit_row.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <imgui_internal.h>

namespace pvs {
namespace {

using gui::InspectorPanels;
using gui::InspectorState;

struct NullBackend : ::testing::Test {
    void SetUp() override
    {
        test::create_headless_imgui_context();
        panels.viewport.upload = [this](const ui::Image& image) {
            ++uploads;
            last_upload = {image.width, image.height};
            return ImTextureID(&uploads); // any non-null id: nothing draws it
        };
        state.open_demo();
    }
    void TearDown() override { ImGui::DestroyContext(); }

    // One whole ImGui frame around `draw`.
    template <typename Draw>
    const ImDrawData* frame(Draw draw)
    {
        ImGui::NewFrame();
        draw();
        ImGui::Render();
        return ImGui::GetDrawData();
    }

    InspectorState state;
    InspectorPanels panels;
    int uploads = 0;
    std::pair<uint32_t, uint32_t> last_upload{0, 0};
};

TEST_F(NullBackend, EveryPanelDraws)
{
    for (int i = 0; i < 3; ++i) { // the first frames size and place the windows
        const ImDrawData* data = frame([&] {
            ImGui::SetNextWindowSize({400, 300}, ImGuiCond_FirstUseEver);
            gui::draw_viewport_panel(state, panels.viewport, 1.0f / 30.0f);
            gui::draw_zone_panel(state, panels.zone);
            gui::draw_culling_panel(state, panels.culling);
            gui::draw_region_panel(state, panels.region);
            gui::draw_bsp_panel(state, panels.bsp);
            gui::draw_bake_panel(state, panels.bake);
        });
        ASSERT_NE(data, nullptr);
        EXPECT_TRUE(data->Valid);
        if (i == 2) {
            EXPECT_GT(data->TotalVtxCount, 1000); // text and widgets of six panels
            EXPECT_GE(data->CmdListsCount, 6);     // and their lists' child windows
        }
    }
    for (const char* name : {"Viewport", "Zone", "Culling", "Region", "BSP", "Bake"})
        EXPECT_NE(ImGui::FindWindowByName(name), nullptr) << name;
    EXPECT_EQ(state.totals().frames, 3u); // the viewport rendered once per frame
    EXPECT_EQ(uploads, 3);
    EXPECT_EQ(last_upload.first, state.image().width);
    EXPECT_GE(panels.region.lists_region, -1);
}

TEST_F(NullBackend, ViewportRendersAtItsSizeAndTakesKeys)
{
    for (int i = 0; i < 2; ++i)
        frame([&] { gui::draw_inspector(state, panels, 1.0f / 30.0f); });
    const ImGuiWindow* viewport = ImGui::FindWindowByName("Viewport");
    ASSERT_NE(viewport, nullptr);
    const ImVec2 inner = viewport->ContentRegionRect.GetSize();
    EXPECT_NEAR(float(state.image().width), inner.x, 1.0f);
    EXPECT_NEAR(float(state.image().height), inner.y, 1.0f);
    EXPECT_GT(state.image().width, 300u);

    // W held while the viewport has focus: the camera flies forward one frame's worth.
    const glm::vec3 start = state.view_camera().position;
    const glm::vec3 forward = state.view_camera().forward();
    ImGui::GetIO().KeysDown['W'] = true;
    frame([&] {
        ImGui::SetNextWindowFocus();
        gui::draw_viewport_panel(state, panels.viewport, 0.5f);
    });
    ImGui::GetIO().KeysDown['W'] = false;
    const glm::vec3 moved = state.view_camera().position - start;
    EXPECT_NEAR(glm::dot(moved, forward), state.move_speed() * 0.5f, 1e-2f);
}

TEST_F(NullBackend, ClickInTheViewportPicks)
{
    for (int i = 0; i < 2; ++i)
        frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    const ImGuiWindow* viewport = ImGui::FindWindowByName("Viewport");
    ASSERT_NE(viewport, nullptr);
    const ImVec2 centre = viewport->ContentRegionRect.GetCenter();
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = centre;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); }); // hover first
    io.MouseDown[0] = true;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    io.MouseDown[0] = false;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    EXPECT_NE(state.selection().face, ui::kNoFace);
    EXPECT_GE(state.selection().region, 0);
    EXPECT_EQ(state.shown_region(), state.selection().region);
}

// Shift + click on a face opens the pair popup; its "Hide, both ways" hides the pair.
TEST_F(NullBackend, ShiftClickInTheViewportEditsThePair)
{
    for (int i = 0; i < 2; ++i)
        frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    const ImGuiWindow* viewport = ImGui::FindWindowByName("Viewport");
    ASSERT_NE(viewport, nullptr);
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = viewport->ContentRegionRect.GetCenter();
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    io.KeyShift = true;
    io.MouseDown[0] = true;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    io.MouseDown[0] = false;
    io.KeyShift = false;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    const int32_t camera = state.last_cull().region, region = state.selection().region;
    ASSERT_GE(camera, 0);
    ASSERT_GE(region, 0);
    ASSERT_TRUE(state.active_pvs()->visible(uint32_t(camera), uint32_t(region))) << "it was drawn";
    ASSERT_EQ(ImGui::GetCurrentContext()->OpenPopupStack.Size, 1) << "the pair popup is open";
    const ImGuiWindow* popup = ImGui::GetCurrentContext()->OpenPopupStack.back().Window;
    ASSERT_NE(popup, nullptr);
    // Click the popup's second item ("Hide, both ways"): below a text line, a separator (1 pixel)
    // and the first item, each followed by the item spacing.
    const float line = ImGui::GetTextLineHeight(), spacing = ImGui::GetStyle().ItemSpacing.y;
    ImVec2 item = popup->DC.CursorStartPos;
    item.x += 20.0f;
    item.y += (line + spacing) + (1.0f + spacing) + (line + spacing) + line * 0.5f;
    io.MousePos = item;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    io.MouseDown[0] = true;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    io.MouseDown[0] = false;
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    ASSERT_EQ(state.pvs_source(), gui::PvsSource::Edited);
    ASSERT_NE(state.pvs_editor(), nullptr);
    EXPECT_EQ(state.pvs_editor()->edit_count(), 1u);
    if (region != camera) {
        EXPECT_FALSE(state.active_pvs()->visible(uint32_t(camera), uint32_t(region)));
        EXPECT_FALSE(state.active_pvs()->visible(uint32_t(region), uint32_t(camera)));
    }
}

TEST_F(NullBackend, RegionPanelListsTheRowAndColumnOfTheActivePvs)
{
    for (int i = 0; i < 2; ++i)
        frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    const int32_t region = state.shown_region();
    ASSERT_GE(region, 0);
    EXPECT_EQ(panels.region.lists_region, region);
    // Independently: the row and column from whole decoded rows.
    std::vector<uint32_t> row, column;
    if (const Pvs* pvs = state.active_pvs()) {
        std::vector<uint64_t> words(pvs->words_per_row());
        pvs->decode_row(uint32_t(region), words);
        for (uint32_t r = 0; r < pvs->region_count(); ++r)
            if (bits::test(words, r))
                row.push_back(r);
        for (uint32_t r = 0; r < pvs->region_count(); ++r) {
            pvs->decode_row(r, words);
            if (bits::test(words, uint32_t(region)))
                column.push_back(r);
        }
    }
    EXPECT_EQ(panels.region.row, row);
    EXPECT_EQ(panels.region.column.regions, column); // the demo's column is read in one frame
    // With no PVS source the panel lists nothing.
    ASSERT_TRUE(state.set_pvs_source(gui::PvsSource::None));
    frame([&] { gui::draw_inspector(state, panels, 0.0f); });
    EXPECT_TRUE(panels.region.row.empty());
    EXPECT_TRUE(panels.region.column.regions.empty());
}

// The BSP panel is a nested tree with the camera's path open: every node of the path is drawn
// (so each of its ancestors was open), and after the camera moves to another region the new
// path is drawn too. Independent of the panel: the path comes from walking the tree.
TEST_F(NullBackend, BspTreeOpensTheCamerasPath)
{
    auto draw = [&] {
        frame([&] {
            ImGui::SetNextWindowSize({400, 600}, ImGuiCond_Always);
            gui::draw_bsp_panel(state, panels.bsp);
        });
    };
    auto path_drawn = [&] {
        state.frame();
        draw();
        draw(); // the second frame draws inside what the first opened
        std::vector<int32_t> drawn = panels.bsp.drawn_nodes;
        std::sort(drawn.begin(), drawn.end());
        size_t found = 0;
        for (const PathStep& step : state.camera_path())
            found += std::binary_search(drawn.begin(), drawn.end(), int32_t(step.node)) ? 1 : 0;
        return std::pair(found, state.camera_path().size());
    };
    const auto [found, length] = path_drawn();
    ASSERT_GT(length, 2u);
    EXPECT_EQ(found, length);
    EXPECT_LT(panels.bsp.drawn_nodes.size(), state.zone().tree.nodes.size()) << "closed subtrees are not visited";

    const std::vector<PathStep> before = state.camera_path();
    const Zone& zone = state.zone();
    for (uint32_t r = 0; r < zone.region_count(); ++r) { // the farthest region: another path
        state.go_to_region(uint32_t(zone.region_count()) - 1 - r);
        state.frame();
        if (state.camera_path().size() > 2 && state.camera_path().back().node != before.back().node)
            break;
    }
    ASSERT_NE(state.camera_path().back().node, before.back().node);
    const auto [found2, length2] = path_drawn();
    EXPECT_EQ(found2, length2);
}

} // namespace
} // namespace pvs
