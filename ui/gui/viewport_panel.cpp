// The viewport: re-renders at the window's size every frame and shows the picture 1:1.
#include "ui/gui/panels.h"

#include <algorithm>
#include <cstdio>

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
    std::snprintf(text, sizeof text, "region %d  |  drawn %u / %u regions  |  %s%s", s.region, s.regions_after_frustum,
                  s.regions_total, cull_mode_name(state.cull_mode), state.locked() ? "  |  LOCKED" : "");
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 at{origin.x + 6.0f, origin.y + 4.0f};
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw->AddRectFilled({at.x - 3.0f, at.y - 1.0f}, {at.x + size.x + 3.0f, at.y + size.y + 1.0f}, IM_COL32(0, 0, 0, 160));
    draw->AddText(at, IM_COL32(255, 255, 255, 255), text);
}

} // namespace

void draw_viewport_panel(InspectorState& state, ViewportPanel& panel, float dt_seconds)
{
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0.0f, 0.0f});
    const bool open = ImGui::Begin("Viewport", nullptr, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
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
    ImGui::InvisibleButton("picture", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    if (panel.texture)
        ImGui::GetWindowDrawList()->AddImage(panel.texture, origin, {origin.x + size.x, origin.y + size.y});
    draw_overlay(state, origin);

    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
        CameraInput wheel;
        wheel.wheel = io.MouseWheel;
        state.step_camera(wheel, 0.0f);
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Right))
        panel.looking = true;
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
        const float x = io.MousePos.x - origin.x, y = io.MousePos.y - origin.y;
        if (x >= 0.0f && y >= 0.0f)
            state.pick(uint32_t(x), uint32_t(y));
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Right))
        panel.looking = false;
    ImGui::End();
}

} // namespace pvs::gui
