// The one dispatcher: places and draws every panel. No docking (Debian's ImGui 1.86 is built
// without it): a fixed tiling, redone when the display size changes.
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
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const bool resized = display.x != panels.laid_out_for.x || display.y != panels.laid_out_for.y;
    const ImGuiCond condition = resized ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    panels.laid_out_for = display;

    // Side columns of fixed width while the display allows, the viewport takes the rest.
    const float left = std::min(300.0f, display.x * 0.25f), right = std::min(330.0f, display.x * 0.28f);
    const float zone_height = std::floor(display.y * 0.55f);
    // The viewport first: it renders the frame whose stats the other panels then show.
    place({left, 0.0f}, {display.x - left - right, display.y}, condition);
    draw_viewport_panel(state, panels.viewport, dt_seconds);
    place({0.0f, 0.0f}, {left, zone_height}, condition);
    draw_zone_panel(state, panels.zone);
    place({0.0f, zone_height}, {left, display.y - zone_height}, condition);
    draw_region_panel(state, panels.region);
    place({display.x - right, 0.0f}, {right, display.y}, condition);
    draw_culling_panel(state, panels.culling);
}

} // namespace pvs::gui
