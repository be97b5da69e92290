// The one dispatcher: draws the menu bar, then places and draws every panel. No docking
// (Debian's ImGui 1.86 is built without it): the fixed tiling of inspector_tiling.h under the menu
// bar, applied every frame, so no window can be moved over the viewport; Stability and Compare
// open and close in the strip under it.
#include "ui/gui/inspector_tiling.h"
#include "ui/gui/panels.h"

namespace pvs::gui {

namespace {

void place(const TileRect& r)
{
    ImGui::SetNextWindowPos({r.x, r.y}, ImGuiCond_Always);
    ImGui::SetNextWindowSize({r.width, r.height}, ImGuiCond_Always);
}

} // namespace

void draw_inspector(InspectorState& state, InspectorPanels& panels, float dt_seconds)
{
    // The menu bar first: its height is the top of the tiling.
    const float top = draw_file_menu(state, panels.file);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Stability and Compare as they were last frame (a click on a title bar shows next frame).
    const InspectorTiling tiles = inspector_tiling(display.x, display.y, top, ImGui::GetFrameHeight(),
                                                   panels.stability.expanded, panels.compare.expanded);
    // The viewport first: it renders the frame whose stats the other panels then show.
    place(tiles.viewport);
    draw_viewport_panel(state, panels.viewport, dt_seconds);
    place(tiles.zone);
    draw_zone_panel(state, panels.zone);
    place(tiles.region);
    draw_region_panel(state, panels.region);
    // Undo / redo of PVS edits from anywhere but a text field.
    const ImGuiIO& io = ImGui::GetIO();
    if (io.KeyCtrl && !io.WantTextInput) {
        if (ImGui::IsKeyPressed('Z', false))
            state.undo_pvs_edit();
        if (ImGui::IsKeyPressed('Y', false))
            state.redo_pvs_edit();
    }
    place(tiles.culling);
    draw_culling_panel(state, panels.culling);
    place(tiles.bsp);
    draw_bsp_panel(state, panels.bsp);
    place(tiles.bake);
    draw_bake_panel(state, panels.bake);
    place(tiles.stability);
    ImGui::SetNextWindowCollapsed(!panels.stability.expanded, ImGuiCond_FirstUseEver);
    draw_stability_panel(state, panels.stability);
    place(tiles.compare);
    ImGui::SetNextWindowCollapsed(!panels.compare.expanded, ImGuiCond_FirstUseEver);
    draw_compare_panel(state, panels.compare);
    draw_file_dialogs(state, panels.file);
}

} // namespace pvs::gui
