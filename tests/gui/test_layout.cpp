// The inspector's tiling at the window sizes people use: no window over the viewport, every window
// on the display, and the viewport keeping most of the middle column, with Stability and Compare
// collapsed or open. Checked on the tiling's arithmetic and on the windows ImGui actually placed
// (null backend: the rectangles of the windows after a few frames of draw_inspector).
#include "tests/gui/headless_imgui.h"
#include "ui/gui/inspector_tiling.h"
#include "ui/gui/panels.h"

#include <gtest/gtest.h>

#include <imgui_internal.h>

#include <string>
#include <vector>

namespace pvs {
namespace {

using gui::TileRect;

struct WindowSize {
    float width, height;
};
constexpr WindowSize kSizes[] = {{1024, 768}, {1280, 720}, {1400, 900}, {1920, 1080}, {2560, 1440}};

std::string describe(const TileRect& r)
{
    return std::to_string(int(r.x)) + "," + std::to_string(int(r.y)) + " " + std::to_string(int(r.width)) + "x" +
           std::to_string(int(r.height));
}

TEST(InspectorTiling, NoTileCoversAnotherAndAllFitTheDisplay)
{
    for (const WindowSize s : kSizes)
        for (int open = 0; open < 4; ++open) {
            const gui::InspectorTiling t = gui::inspector_tiling(s.width, s.height, 19.0f, 19.0f, open & 1, open & 2);
            const std::vector<std::pair<const char*, TileRect>> tiles = {
                {"viewport", t.viewport}, {"zone", t.zone},           {"region", t.region},
                {"culling", t.culling},   {"bsp", t.bsp},             {"bake", t.bake},
                {"stability", t.stability}, {"compare", t.compare}};
            float area = 0.0f;
            for (size_t i = 0; i < tiles.size(); ++i) {
                const TileRect& a = tiles[i].second;
                EXPECT_GE(a.x, 0.0f) << tiles[i].first;
                EXPECT_GE(a.y, 19.0f) << tiles[i].first;
                EXPECT_LE(a.right(), s.width) << tiles[i].first;
                EXPECT_LE(a.bottom(), s.height) << tiles[i].first;
                area += a.width * a.height;
                for (size_t j = i + 1; j < tiles.size(); ++j)
                    EXPECT_FALSE(gui::tiles_overlap(a, tiles[j].second))
                        << s.width << "x" << s.height << ": " << tiles[i].first << " " << describe(a) << " and "
                        << tiles[j].first << " " << describe(tiles[j].second);
            }
            EXPECT_FLOAT_EQ(area, s.width * (s.height - 19.0f)) << "the tiles cover the display below the menu";
            EXPECT_GE(t.viewport.height, 0.5f * (s.height - 19.0f)) << "the picture keeps over half the height";
        }
}

TileRect rect_of(const ImGuiWindow* w) { return {w->Pos.x, w->Pos.y, w->Size.x, w->Size.y}; }

struct Placed : ::testing::TestWithParam<WindowSize> {};

// The windows ImGui placed after draw_inspector, collapsed and open.
TEST_P(Placed, NoWindowOverTheViewport)
{
    for (const bool open : {false, true}) {
        test::create_headless_imgui_context();
        ImGui::GetIO().DisplaySize = {GetParam().width, GetParam().height};
        gui::InspectorState state;
        gui::InspectorPanels panels;
        panels.viewport.upload = [](const ui::Image&) { return ImTextureID(&kSizes); };
        panels.stability.expanded = open;
        panels.compare.expanded = open;
        state.open_demo();
        for (int frame = 0; frame < 3; ++frame) {
            ImGui::NewFrame();
            gui::draw_inspector(state, panels, 1.0f / 30.0f);
            ImGui::Render();
        }
        const ImGuiWindow* viewport = ImGui::FindWindowByName("Viewport");
        ASSERT_NE(viewport, nullptr);
        const TileRect picture = rect_of(viewport);
        EXPECT_GE(picture.height, 0.5f * GetParam().height) << "the picture keeps over half the height";
        EXPECT_GE(picture.width, 0.45f * GetParam().width) << "and its column";
        EXPECT_EQ(panels.stability.expanded, open);
        for (const char* name : {"Zone", "Region", "Culling", "BSP", "Bake", "Stability", "Compare"}) {
            const ImGuiWindow* w = ImGui::FindWindowByName(name);
            ASSERT_NE(w, nullptr) << name;
            const TileRect r = rect_of(w);
            EXPECT_FALSE(gui::tiles_overlap(r, picture))
                << GetParam().width << "x" << GetParam().height << (open ? " open: " : " collapsed: ") << name << " "
                << describe(r) << " over the viewport " << describe(picture);
            EXPECT_LE(r.right(), GetParam().width + 0.5f) << name;
            EXPECT_LE(r.bottom(), GetParam().height + 0.5f) << name;
        }
        ImGui::DestroyContext();
    }
}

INSTANTIATE_TEST_SUITE_P(Sizes, Placed, ::testing::ValuesIn(kSizes), [](const auto& p) {
    return std::to_string(int(p.param.width)) + "x" + std::to_string(int(p.param.height));
});

} // namespace
} // namespace pvs
