// The inspector's ImGui panels: each is a small state struct plus one draw function over an
// InspectorState, in its own file (viewport_panel.cpp, zone_panel.cpp, ...). They only show the
// state and call its functions; no logic worth testing lives here that InspectorState does not
// have. None of them touches GLFW or OpenGL: the viewport gets its texture through the upload
// function the application gives it, so every panel can be drawn with a null backend (an ImGui
// context with fonts built and io.DisplaySize set, no GPU), which the tests do.
#pragma once

#include "gen/case_table.h"
#include "ui/gui/file_browser.h"
#include "ui/gui/inspector_state.h"
#include "ui/gui/pvs_rows.h"
#include "ui/gui/recent_files.h"

#include <imgui.h>

#include <cstdint>
#include <functional>
#include <optional>
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
    bool looking = false;  // right button went down over the picture and is still held
    bool orbiting = false; // middle button went down over the picture on a picked point
    int32_t selected_before_click = -1; // the region selected before the last Shift + click
};
void draw_viewport_panel(InspectorState& state, ViewportPanel& panel, float dt_seconds);

// ---- Zone: file, format, counts, PVS, tree, memory; open and export ------------------------------
struct ZonePanel {
    std::string open_path;                 // the path field
    std::string export_base = "pvscope-stats"; // export writes <base>.json / <base>.csv
    std::string message;                   // the last export's result
};
void draw_zone_panel(InspectorState& state, ZonePanel& panel);
// Its Health section (health_section.cpp): `check` on the open zone, failures clickable to their place.
void draw_health_section(InspectorState& state);

// ---- Culling: stage counts and times, history plots, mode switches, lock ------------------------
struct CullingPanel {
    std::vector<float> plot_values; // scratch for the plots, reused
    int go_to_region = 0;           // the "go to region" field
};
void draw_culling_panel(InspectorState& state, CullingPanel& panel);

// ---- Region: the selected or current region, its faces and PVS row ------------------------------
struct RegionPanel {
    // The lists below are for this zone (InspectorState::zone_generation), PVS
    // (pvs_generation) and region; recomputed when one changes.
    uint64_t lists_zone = 0, lists_pvs = 0;
    int32_t lists_region = -1;
    bool lists_neighbours = false; // neighbours were computed (portals were ready)
    bool row_missing = false;      // the region's row was missing in the file (all visible)
    std::vector<uint32_t> row;     // regions it sees, ascending
    PvsColumnScan column;          // regions that see it, read a slice a frame
    std::vector<uint32_t> neighbours; // regions sharing a portal with it
    // PVS editing: pairs both ways, where the edit list is saved, and the last save's message.
    bool edit_both_ways = true;
    char edit_list_path[256] = "pvs-edits.json";
    char save_path[256] = "";
    std::string edit_message;
    int why_target = 0; // the "Why does this region see...?" field
};
void draw_region_panel(InspectorState& state, RegionPanel& panel);
// The Region panel's "Why does A see B?" section (why_panel.cpp): a region field, the verdict,
// the chain and the button that looks along the sight line. `region` is A.
void draw_why_section(InspectorState& state, int& target, int32_t region);
// A context menu on the last item offering to explain the pair (a, b).
void why_context_menu(InspectorState& state, uint32_t a, uint32_t b);

// ---- BSP: the camera's path through the tree, a node browser, the regions under a node ----------
struct BspPanel {
    // The nested tree: the camera's path is opened whenever it changes (the user may close it
    // again); drawn_nodes lists the node ids the last frame drew as lines (tests read it).
    std::vector<uint32_t> open_path;  // the path the tree last opened, root first
    std::vector<uint8_t> on_path;     // per node: on the camera's path now
    std::vector<int32_t> drawn_nodes;
    uint64_t parents_zone = 0;       // the zone parents/depths are for
    std::vector<int32_t> parents;    // per node: its parent node, -1 for the root or unreached
    std::vector<int32_t> depths;     // per node: its depth, -1 when unreached
    uint64_t regions_zone = 0;       // the zone and node `regions` is for
    int32_t regions_node = -1;
    std::vector<uint32_t> regions;   // regions under regions_node, ascending
};
void draw_bsp_panel(InspectorState& state, BspPanel& panel);

// "water, zone_line" for a set of RegionFlag bits, "none" for none (the Region panel, the hover).
std::string flag_names(uint32_t flags);

// ---- Bake: portal vis on a background thread, its progress, and the diff with the file's PVS ---
struct BakePanel {
    BakeRequest request;
    // The diff (file PVS vs baked) of one region, and zone-wide counts, for this PVS generation.
    uint64_t diff_pvs = 0;
    int32_t diff_region = -1;
    std::vector<uint32_t> only_file, only_baked;
    uint64_t total_only_file = 0, total_only_baked = 0; // set bits over all rows
};
void draw_bake_panel(InspectorState& state, BakePanel& panel);

// ---- Compare: every method against the reference, the chart, a click culls with a method --------
struct ComparePanel {
    int reference_samples = 512; // the reference's lines per region
    int cameras = 100;           // the walk's cameras (popping and overdraw)
    bool expanded = false;       // open (else collapsed to its title bar under the viewport); set to start open
};
void draw_compare_panel(InspectorState& state, ComparePanel& panel);

// ---- Stability: every method on every crafted case, a click opens the case with that PVS --------
struct StabilityPanel {
    gen::CaseTableOptions options;       // methods and reference lines of the table
    std::optional<gen::CaseTable> table; // the last run
    std::string message;                 // the last error
    bool expanded = false;               // open (else collapsed to its title bar under the viewport); set to start open
};
void draw_stability_panel(InspectorState& state, StabilityPanel& panel);

// ---- File menu (main menu bar): open through a file browser, recent files, the viewport PNG ---
// Load errors open a modal that names the file and the problem; nothing here throws.
struct FileMenu {
    RecentFiles recent;                  // the application gives it its store and loads it
    bool browser_open = false;           // the Open dialog is showing
    bool browser_all_files = false;      // list every file, not only zone files
    std::string browser_field;           // the directory field
    DirectoryListing listing;            // the directory shown
    std::string chosen;                  // the file clicked in the listing
    std::string error;                   // a load error, shown in a modal until dismissed
    bool error_pending = false;          // the modal is to be opened this frame
    bool png_open = false;               // the "Save viewport PNG" dialog is showing
    std::string png_path = "pvscope-viewport.png";
    std::string png_message;             // the last save's result
};
// Opens a zone the way the menu, the browser and drag-and-drop do: on success the file goes to
// the recent files, on failure the error modal shows state.error().
bool open_zone_file(InspectorState& state, FileMenu& menu, const std::string& path);
// Shows `directory` in the browser (its listing, or the error in the dialog).
void browse_to(FileMenu& menu, const std::filesystem::path& directory);
// The main menu bar. Returns its height.
float draw_file_menu(InspectorState& state, FileMenu& menu);
// The dialogs it opens and the error modal. Call after every other window: ImGui 1.86 asserts
// when a window is created after a modal popup in the same frame (ocornut/imgui#4920).
void draw_file_dialogs(InspectorState& state, FileMenu& menu);

// ---- The whole window ----------------------------------------------------------------------------
// Tiles the panels over the display (zone and region on the left, culling on the right, the
// viewport between): again whenever the display size changes, otherwise they stay where the
// user moved them.
struct InspectorPanels {
    ViewportPanel viewport;
    ZonePanel zone;
    CullingPanel culling;
    RegionPanel region;
    BspPanel bsp;
    BakePanel bake;
    ComparePanel compare;
    StabilityPanel stability;
    FileMenu file;
    ImVec2 laid_out_for{0.0f, 0.0f}; // the display size of the last tiling
};
void draw_inspector(InspectorState& state, InspectorPanels& panels, float dt_seconds);

} // namespace pvs::gui
