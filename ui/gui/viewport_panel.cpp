// The viewport: re-renders at the window's size every frame and shows the picture 1:1, with
// the overlay toggles in its menu bar, the overlays' legend and labels drawn over the picture.
#include "ui/gui/panels.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace pvs::gui {

namespace {

CameraInput gather_input(const ViewportPanel& panel, bool keys_active)
{
    const ImGuiIO& io = ImGui::GetIO();
    CameraInput input;
    if (keys_active) {
        input.forward = ImGui::IsKeyDown('W');
        input.back = ImGui::IsKeyDown('S');
        input.left = ImGui::IsKeyDown('A');
        input.right = ImGui::IsKeyDown('D');
        input.up = ImGui::IsKeyDown('E');
        input.down = ImGui::IsKeyDown('Q');
        input.fast = io.KeyShift;
    }
    if (panel.looking)
        input.look = {io.MouseDelta.x, io.MouseDelta.y};
    return input;
}

void draw_overlay(const InspectorState& state, ImVec2 origin)
{
    const CullStats& s = state.last_cull();
    char text[160];
    const bool grid = state.has_zone() && state.zone().view_grid;
    std::snprintf(text, sizeof text, "%s %d  |  drawn %u / %u %s  |  %s%s%s", grid ? "view cell" : "region",
                  grid ? s.cell : s.region, s.regions_after_frustum, s.regions_total, grid ? "objects" : "regions",
                  cull_mode_name(state.cull_mode), state.locked() ? "  |  LOCKED" : "",
                  state.overlays.portals && state.portals_building() ? "  |  building portals..." : "");
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 at{origin.x + 6.0f, origin.y + 4.0f};
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw->AddRectFilled({at.x - 3.0f, at.y - 1.0f}, {at.x + size.x + 3.0f, at.y + size.y + 1.0f}, IM_COL32(0, 0, 0, 160));
    draw->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

ImU32 to_imgui(uint32_t rgb, uint8_t alpha = 255)
{
    return IM_COL32(uint8_t(rgb >> 16), uint8_t(rgb >> 8), uint8_t(rgb), alpha);
}

void draw_overlay_menu(InspectorState& state)
{
    if (!ImGui::BeginMenuBar())
        return;
    if (ImGui::BeginMenu("Overlays")) {
        ui::OverlaySettings& o = state.overlays;
        ImGui::MenuItem("PVS membership (tinted faces)", nullptr, &o.pvs_membership);
        ImGui::MenuItem("PVS membership boxes", nullptr, &o.pvs_membership_boxes);
        ImGui::MenuItem("BSP split planes on the camera path", nullptr, &o.split_planes);
        ImGui::MenuItem("Portals", nullptr, &o.portals);
        ImGui::MenuItem("Region bounds", nullptr, &o.region_bounds);
        ImGui::MenuItem("Zone lines", nullptr, &o.zone_lines);
        ImGui::MenuItem("Areaportals (Quake 2)", nullptr, &o.area_portals);
        ImGui::MenuItem("Locked culling frustum", nullptr, &o.locked_frustum);
        ImGui::MenuItem("View cell (OBJ + .hepvs zones)", nullptr, &o.view_cell);
        ImGui::Separator();
        ImGui::TextDisabled("lines behind walls");
        for (ui::HiddenLines mode : {ui::HiddenLines::Faint, ui::HiddenLines::Hidden, ui::HiddenLines::Shown})
            if (ImGui::MenuItem(mode == ui::HiddenLines::Shown ? "shown (no depth test)" : ui::hidden_lines_name(mode),
                                nullptr, o.hidden_lines == mode))
                o.hidden_lines = mode;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Draw")) {
        for (ui::RenderMode mode : ui::kRenderModes)
            if (ImGui::MenuItem(ui::render_mode_name(mode), nullptr, state.render_mode == mode))
                state.render_mode = mode;
        ImGui::EndMenu();
    }
    ImGui::EndMenuBar();
}

// The legend, bottom left of the picture, always: the enabled overlays' colours, or a hint.
void draw_legend(const InspectorState& state, ImVec2 origin, ImVec2 size)
{
    const bool edits = state.pvs_source() == PvsSource::Edited && state.pvs_editor() &&
                       state.pvs_editor()->edit_count() > 0;
    const std::vector<ui::LegendEntry> legend =
        ui::overlay_legend(state.overlays, state.has_zone() && state.zone().view_grid.has_value(), edits,
                           state.explanation().has_value(), state.has_zone() && !state.zone().area_portals.empty());
    const float line = ImGui::GetTextLineHeight() + 2.0f, swatch = ImGui::GetTextLineHeight() - 2.0f;
    float width = ImGui::CalcTextSize("no overlays (Overlays menu)").x;
    for (const ui::LegendEntry& e : legend)
        width = std::max(width, swatch + 6.0f + ImGui::CalcTextSize(e.name).x);
    const float height = line * float(std::max<size_t>(legend.size(), 1)) + 4.0f;
    ImVec2 at{origin.x + 6.0f, origin.y + size.y - height - 6.0f};
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled({at.x - 4.0f, at.y - 2.0f}, {at.x + width + 4.0f, at.y + height}, IM_COL32(0, 0, 0, 170));
    if (legend.empty())
        draw->AddText(at, IM_COL32(200, 200, 200, 255), "no overlays (Overlays menu)");
    for (const ui::LegendEntry& e : legend) {
        draw->AddRectFilled({at.x, at.y + 2.0f}, {at.x + swatch, at.y + 2.0f + swatch}, to_imgui(e.rgb));
        draw->AddText({at.x + swatch + 6.0f, at.y}, IM_COL32(255, 255, 255, 255), e.name);
        at.y += line;
    }
}

void draw_labels(const InspectorState& state, ImVec2 origin)
{
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (const ui::OverlayLabel& label : state.overlay_labels()) {
        const ImVec2 at{origin.x + label.pixel.x, origin.y + label.pixel.y};
        const ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
        draw->AddRectFilled({at.x - 2.0f, at.y - 1.0f}, {at.x + size.x + 2.0f, at.y + size.y + 1.0f},
                            IM_COL32(0, 0, 0, 170));
        draw->AddText(at, to_imgui(label.rgb), label.text.c_str());
    }
}


// Hovering names the face under the mouse, its regions and their flags (a ray, not a render).
void draw_hover(InspectorState& state, const ViewportPanel& panel, ImVec2 origin)
{
    if (!ImGui::IsItemHovered() || panel.looking || panel.orbiting)
        return;
    const ImGuiIO& io = ImGui::GetIO();
    const float x = io.MousePos.x - origin.x, y = io.MousePos.y - origin.y;
    if (x < 0.0f || y < 0.0f)
        return;
    const std::optional<HoverInfo> hover = state.hover(uint32_t(x), uint32_t(y));
    if (!hover)
        return;
    std::string regions;
    for (size_t i = 0; i < hover->regions.size() && i < 4; ++i)
        regions += (i ? ", " : "") + std::to_string(hover->regions[i]);
    if (hover->regions.size() > 4)
        regions += ", ... (" + std::to_string(hover->regions.size()) + ")";
    ImGui::SetTooltip("face %u  |  region %s  |  %s  |  %.0f units", hover->face,
                      regions.empty() ? "none" : regions.c_str(), ("flags: " + flag_names(hover->flags)).c_str(),
                      double(hover->distance));
}

// Shift + left click on a face: explain or edit the pair (the camera's region, the clicked face's
// region).
constexpr const char* kPairPopup = "Edit PVS pair";

void draw_pair_popup(InspectorState& state, int32_t selected_before)
{
    if (!ImGui::BeginPopup(kPairPopup))
        return;
    const int32_t camera = state.last_cull().region, region = state.selection().region;
    const Pvs* pvs = state.active_pvs();
    if (camera < 0 || region < 0 || !pvs || uint32_t(camera) >= pvs->row_count() ||
        uint32_t(region) >= pvs->region_count()) {
        ImGui::TextDisabled("no PVS pair to edit here");
    } else {
        const bool sees = pvs->visible(uint32_t(camera), uint32_t(region));
        ImGui::Text("camera's region %d %s region %d", camera, sees ? "sees" : "does not see", region);
        ImGui::Separator();
        for (bool visible : {false, true})
            for (bool both : {false, true}) {
                const std::string label = std::string(visible ? "Show" : "Hide") + (both ? ", both ways" : ", one way");
                if (ImGui::MenuItem(label.c_str()))
                    state.edit_pvs(pair_edit(uint32_t(camera), uint32_t(region), visible, both));
            }
    }
    // Why the camera's region (or the region selected before the click) draws or culls the
    // clicked one: the Region panel answers.
    if (region >= 0 && (camera >= 0 || selected_before >= 0))
        ImGui::Separator();
    for (const int32_t from : {camera, selected_before == camera ? -1 : selected_before}) {
        if (from < 0 || region < 0)
            continue;
        const std::string why = "Why does " + std::to_string(from) + " see " + std::to_string(region) + "?";
        if (ImGui::MenuItem(why.c_str()))
            state.request_explanation(uint32_t(from), uint32_t(region));
    }
    ImGui::EndPopup();
}

// Middle drag orbits about the picked point (the first drag aims the camera at it).
void handle_orbit(InspectorState& state, ViewportPanel& panel)
{
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemClicked(ImGuiMouseButton_Middle) && state.selection().point) {
        state.set_orbit_target(state.selection().point);
        panel.orbiting = true;
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Middle))
        panel.orbiting = false;
    if (panel.orbiting && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
        state.orbit(-io.MouseDelta.x * kOrbitDegreesPerPixel, io.MouseDelta.y * kOrbitDegreesPerPixel);
}

} // namespace

void draw_viewport_panel(InspectorState& state, ViewportPanel& panel, float dt_seconds)
{
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0.0f, 0.0f});
    // No background: the picture covers the window, and a software GL driver pays for every
    // pixel it fills (the background was a fifth of a frame's fill on llvmpipe).
    const bool open = ImGui::Begin("Viewport", nullptr,
                                   ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse |
                                       ImGuiWindowFlags_MenuBar | ImGuiWindowFlags_NoBackground);
    ImGui::PopStyleVar();
    if (open)
        draw_overlay_menu(state);
    if (!open || !state.has_zone()) {
        if (open)
            ImGui::TextUnformatted("No zone: open one in the Zone panel, or drop a file on the window.");
        ImGui::End();
        return;
    }

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    state.set_viewport_size(uint32_t(std::max(avail.x, 1.0f)), uint32_t(std::max(avail.y, 1.0f)));
    const ImGuiIO& io = ImGui::GetIO();
    const bool keys_active =
        (ImGui::IsWindowFocused() || ImGui::IsWindowHovered() || panel.looking) && !io.WantTextInput;
    state.step_camera(gather_input(panel, keys_active), dt_seconds);
    state.frame();

    const ui::Image& image = state.image();
    if (panel.upload && state.frame_number() != panel.uploaded_frame && !image.rgba.empty()) {
        panel.texture = panel.upload(image);
        panel.uploaded_frame = state.frame_number();
    }
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size{float(std::max(image.width, 1u)), float(std::max(image.height, 1u))};
    // A button over the picture owns the clicks, so dragging on it never moves the window.
    ImGui::InvisibleButton("picture", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    if (panel.texture)
        ImGui::GetWindowDrawList()->AddImage(panel.texture, origin, {origin.x + size.x, origin.y + size.y});
    draw_labels(state, origin);
    draw_overlay(state, origin);
    draw_legend(state, origin, size);
    handle_orbit(state, panel);
    draw_hover(state, panel, origin);

    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
        CameraInput wheel;
        wheel.wheel = io.MouseWheel;
        state.step_camera(wheel, 0.0f);
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Right))
        panel.looking = true;
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
        const float x = io.MousePos.x - origin.x, y = io.MousePos.y - origin.y;
        panel.selected_before_click = state.selection().region;
        if (x >= 0.0f && y >= 0.0f && state.pick(uint32_t(x), uint32_t(y)) && io.KeyShift &&
            state.selection().region >= 0 && state.last_cull().region >= 0)
            ImGui::OpenPopup(kPairPopup);
    }
    draw_pair_popup(state, panel.selected_before_click);
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Right))
        panel.looking = false;
    ImGui::End();
}

} // namespace pvs::gui
