// The inspector's ImGui panels: each is a small state struct plus one draw function over an
// InspectorState, in its own file (viewport_panel.cpp, zone_panel.cpp, ...). They only show the
// state and call its functions; no logic worth testing lives here that InspectorState does not
// have. None of them touches GLFW or OpenGL: the viewport gets its texture through the upload
// function the application gives it, so every panel can be drawn with a null backend (an ImGui
// context with fonts built and io.DisplaySize set, no GPU), which the tests do.
#pragma once

#include "ui/gui/inspector_state.h"

#include <imgui.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pvs::gui {

// ---- Viewport: the rendered picture, the fly camera and picking ---------------------------------
// Keys come from ImGui's io.KeysDown, indexed by the platform backend's key codes: the GLFW
// backend stores GLFW key codes, whose letters are their ASCII capitals ('W', 'A', ...). The
// camera takes the keys while the viewport window is focused or hovered and no text field is
// being edited; the mouse looks while the right button, pressed over the picture, is held;
// the wheel over the picture changes the speed; a left click picks.
struct ViewportPanel {
    // Makes (or updates) a texture from the picture and returns its id; called when the picture
    // changed. The application uploads to OpenGL; tests pass a stub.
    std::function<ImTextureID(const ui::Image&)> upload;
    ImTextureID texture{};
    uint64_t uploaded_frame = 0;
    bool looking = false; // right button went down over the picture and is still held
};
void draw_viewport_panel(InspectorState& state, ViewportPanel& panel, float dt_seconds);

// ---- Zone: file, format, counts, PVS, tree, memory; open and export ------------------------------
struct ZonePanel {
    std::string open_path;                 // the path field
    std::string export_base = "pvscope-stats"; // export writes <base>.json / <base>.csv
    std::string message;                   // the last export's result
};
void draw_zone_panel(InspectorState& state, ZonePanel& panel);

// ---- Culling: stage counts and times, history plots, mode switches, lock ------------------------
struct CullingPanel {
    std::vector<float> plot_values; // scratch for the plots, reused
};
void draw_culling_panel(InspectorState& state, CullingPanel& panel);

// ---- Region: the selected or current region, its faces and PVS row ------------------------------
struct RegionPanel {
    uint64_t row_zone = 0;         // the zone (InspectorState::zone_generation) and region
    int32_t row_region = -1;       // whose PVS row `row` holds
    bool row_missing = false;      // that row was missing in the file (all visible)
    std::vector<uint32_t> row;     // visible region ids, ascending
    std::vector<uint64_t> words;   // decode scratch
};
void draw_region_panel(InspectorState& state, RegionPanel& panel);

// ---- The whole window ----------------------------------------------------------------------------
// Tiles the panels over the display (zone and region on the left, culling on the right, the
// viewport between): again whenever the display size changes, otherwise they stay where the
// user moved them.
struct InspectorPanels {
    ViewportPanel viewport;
    ZonePanel zone;
    CullingPanel culling;
    RegionPanel region;
    ImVec2 laid_out_for{0.0f, 0.0f}; // the display size of the last tiling
};
void draw_inspector(InspectorState& state, InspectorPanels& panels, float dt_seconds);

} // namespace pvs::gui
