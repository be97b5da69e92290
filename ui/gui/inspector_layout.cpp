// The one dispatcher: draws the menu bar, then places and draws every panel. No docking
// (Debian's ImGui 1.86 is built without it): a fixed tiling under the menu bar, redone when the
// display size changes: zone and region on the left, culling, BSP and bake on the right, the
// viewport between.
#include "ui/gui/panels.h"

#include <algorithm>
#include <cmath>

namespace pvs::gui {

namespace {

void place(ImVec2 position, ImVec2 size, ImGuiCond condition)
{
    ImGui::SetNextWindowPos(position, condition);
    ImGui::SetNextWindowSize(size, condition);
}

} // namespace

void draw_inspector(InspectorState& state, InspectorPanels& panels, float dt_seconds)
{
    // The menu bar first: its height is the top of the tiling.
    const float top = draw_file_menu(state, panels.file);
    const ImVec2 full = ImGui::GetIO().DisplaySize;
    const ImVec2 display{full.x, full.y - top};
    const bool resized = display.x != panels.laid_out_for.x || display.y != panels.laid_out_for.y;
    const ImGuiCond condition = resized ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    panels.laid_out_for = display;

    // Side columns of fixed width while the display allows, the viewport takes the rest.
    const float left = std::min(300.0f, display.x * 0.25f), right = std::min(330.0f, display.x * 0.28f);
    const float zone_height = std::floor(display.y * 0.45f);
    const float culling_height = std::floor(display.y * 0.45f), bsp_height = std::floor(display.y * 0.27f);
    // The viewport first: it renders the frame whose stats the other panels then show.
    place({left, top}, {display.x - left - right, display.y}, condition);
    draw_viewport_panel(state, panels.viewport, dt_seconds);
    place({0.0f, top}, {left, zone_height}, condition);
    draw_zone_panel(state, panels.zone);
    place({0.0f, top + zone_height}, {left, display.y - zone_height}, condition);
    draw_region_panel(state, panels.region);
    // Undo / redo of PVS edits from anywhere but a text field.
    const ImGuiIO& io = ImGui::GetIO();
    if (io.KeyCtrl && !io.WantTextInput) {
        if (ImGui::IsKeyPressed('Z', false))
            state.undo_pvs_edit();
        if (ImGui::IsKeyPressed('Y', false))
            state.redo_pvs_edit();
    }
    place({display.x - right, top}, {right, culling_height}, condition);
    draw_culling_panel(state, panels.culling);
    place({display.x - right, top + culling_height}, {right, bsp_height}, condition);
    draw_bsp_panel(state, panels.bsp);
    place({display.x - right, top + culling_height + bsp_height}, {right, display.y - culling_height - bsp_height},
          condition);
    draw_bake_panel(state, panels.bake);
    // Compare: a wide window over the lower part of the viewport, its chart needs the width.
    place({left, top + std::floor(display.y * 0.55f)}, {display.x - left - right, display.y * 0.45f - top},
          ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowCollapsed(!panels.compare.expanded, ImGuiCond_FirstUseEver); // it covers the viewport
    draw_compare_panel(state, panels.compare);
    place({left, top + std::floor(display.y * 0.50f)}, {display.x - left - right, display.y * 0.50f - top},
          ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowCollapsed(!panels.stability.expanded, ImGuiCond_FirstUseEver);
    draw_stability_panel(state, panels.stability);
    draw_file_dialogs(state, panels.file);
}

} // namespace pvs::gui
