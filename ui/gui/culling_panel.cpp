// The culling panel: this frame's stage counts and times, plots of the recent frames, the cull
// and render mode switches and the lock.
#include "ui/gui/panels.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <utility>

namespace pvs::gui {

namespace {

constexpr std::array<CullMode, 4> kCullModes{CullMode::None, CullMode::Frustum, CullMode::Pvs, CullMode::PvsFrustum};
// The render modes by name, so a mode the renderer does not know (yet) is simply not offered.
constexpr std::array<const char*, 4> kRenderModeNames{"textured", "regions", "ids", "flags"};

void draw_counts(const InspectorState& state)
{
    const CullStats& s = state.last_cull();
    const char* place = s.camera == CameraPlace::InRegion ? "" : s.camera == CameraPlace::InSolid ? " (in solid)"
                                                                                                 : " (outside)";
    if (state.zone().view_grid)
        ImGui::Text("camera view cell %d%s%s", s.cell, place, s.pvs_used ? "" : ", no PVS stage");
    else
        ImGui::Text("camera region %d%s%s", s.region, place, s.pvs_used ? "" : ", no PVS stage");
    ImGui::TextDisabled("left after each stage, and its time:");
    if (!ImGui::BeginTable("stages", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV))
        return;
    ImGui::TableSetupColumn("stage");
    ImGui::TableSetupColumn("regions");
    ImGui::TableSetupColumn("triangles");
    ImGui::TableSetupColumn("us");
    ImGui::TableHeadersRow();
    constexpr uint64_t kNotCounted = UINT64_MAX;
    const auto stage = [](const char* name, uint32_t regions, uint64_t triangles, double us) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(name);
        ImGui::TableNextColumn();
        ImGui::Text("%u", regions);
        ImGui::TableNextColumn();
        if (triangles == kNotCounted)
            ImGui::TextUnformatted("-");
        else
            ImGui::Text("%llu", static_cast<unsigned long long>(triangles));
        ImGui::TableNextColumn();
        ImGui::Text("%.1f", us);
    };
    stage("lookup", s.regions_total, s.triangles_total, s.lookup_us);
    stage("PVS", s.regions_after_pvs, s.triangles_after_pvs, s.pvs_us);
    if (state.far_clip > 0.0f)
        stage("distance", s.regions_after_distance, kNotCounted, s.distance_us);
    stage("frustum", s.regions_after_frustum, s.triangles_after_frustum, s.frustum_us);
    ImGui::EndTable();
    const ui::RenderStats& r = state.last_render();
    ImGui::Text("render %.1f ms (%u faces), %ux%u", r.draw_ms, r.faces_drawn, state.image().width, state.image().height);
}

void draw_plots(const InspectorState& state, CullingPanel& panel)
{
    const FrameHistory& history = state.history();
    const int count = int(history.size());
    if (count == 0)
        return;
    panel.plot_values.resize(history.size());
    const float width = ImGui::GetContentRegionAvail().x;
    for (size_t i = 0; i < history.size(); ++i)
        panel.plot_values[i] = history.at(i).cull_us();
    const float max_cull = *std::max_element(panel.plot_values.begin(), panel.plot_values.end());
    char label[64];
    std::snprintf(label, sizeof label, "cull %.1f us", double(history.newest().cull_us()));
    ImGui::PlotLines("##cull", panel.plot_values.data(), count, 0, label, 0.0f, max_cull * 1.1f + 1.0f, {width, 60.0f});
    for (size_t i = 0; i < history.size(); ++i)
        panel.plot_values[i] = history.at(i).render_ms;
    const float max_render = *std::max_element(panel.plot_values.begin(), panel.plot_values.end());
    std::snprintf(label, sizeof label, "render %.1f ms", double(history.newest().render_ms));
    ImGui::PlotLines("##render", panel.plot_values.data(), count, 0, label, 0.0f, max_render * 1.1f + 1.0f,
                     {width, 60.0f});
}

// Quake 2 maps: a door per areaportal. Shutting one drops the areas it cuts off, as the engine does.
void draw_area_portal_doors(InspectorState& state)
{
    if (!state.has_zone() || state.zone().area_portals.empty())
        return;
    const std::vector<AreaPortal>& portals = state.zone().area_portals;
    state.closed_area_portals.resize(portals.size(), 0);
    ImGui::TextDisabled("areaportals (Quake 2 doors): %zu regions dropped by shut ones", state.last_area_dropped());
    for (size_t p = 0; p < portals.size(); ++p) {
        bool shut = state.closed_area_portals[p] != 0;
        const std::string label = "shut " + std::to_string(portals[p].number) + " (areas " +
                                  std::to_string(portals[p].areas[0]) + "-" + std::to_string(portals[p].areas[1]) + ")";
        if (p % 3 != 0)
            ImGui::SameLine();
        if (ImGui::Checkbox(label.c_str(), &shut))
            state.closed_area_portals[p] = shut ? 1 : 0;
    }
}

void draw_switches(InspectorState& state)
{
    ImGui::TextDisabled("cull with");
    bool first = true;
    for (CullMode mode : kCullModes) {
        if (!std::exchange(first, false))
            ImGui::SameLine();
        if (ImGui::RadioButton(cull_mode_name(mode), state.cull_mode == mode))
            state.cull_mode = mode;
    }
    ImGui::SetNextItemWidth(160.0f);
    ImGui::DragFloat("far clip (0: off)", &state.far_clip, 16.0f, 0.0f, 65536.0f, "%.0f");
    draw_area_portal_doors(state);
    ImGui::TextDisabled("draw");
    first = true;
    for (const char* name : kRenderModeNames)
        if (const auto mode = ui::parse_render_mode(name)) {
            if (!std::exchange(first, false))
                ImGui::SameLine();
            if (ImGui::RadioButton(name, state.render_mode == *mode))
                state.render_mode = *mode;
        }
    ImGui::TextDisabled("PVS source");
    first = true;
    for (PvsSource source : {PvsSource::File, PvsSource::None, PvsSource::Baked, PvsSource::Edited}) {
        if (!std::exchange(first, false))
            ImGui::SameLine();
        const bool available = state.has_pvs_source(source);
        if (!available)
            ImGui::BeginDisabled();
        if (ImGui::RadioButton(pvs_source_name(source), state.pvs_source() == source))
            state.set_pvs_source(source);
        if (!available)
            ImGui::EndDisabled();
    }
    bool locked = state.locked();
    if (ImGui::Checkbox("Lock culling camera", &locked))
        state.set_lock(locked);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Culling stays with the camera where it is now: fly out and look at what it kept");
}

} // namespace

void draw_culling_panel(InspectorState& state, CullingPanel& panel)
{
    if (!ImGui::Begin("Culling")) {
        ImGui::End();
        return;
    }
    if (state.has_zone()) {
        draw_switches(state);
        ImGui::Separator();
        draw_counts(state);
        ImGui::Separator();
        draw_plots(state, panel);
        const CullTotals& t = state.totals();
        if (t.frames) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            ImGui::TextWrapped("%llu frames since opened: mean cull %.1f us, render %.1f ms, %.1f regions drawn",
                               static_cast<unsigned long long>(t.frames),
                               (t.lookup_us + t.pvs_us + t.distance_us + t.frustum_us) / double(t.frames),
                               t.render_ms / double(t.frames), double(t.regions_drawn) / double(t.frames));
            ImGui::PopStyleColor();
        }
        ImGui::Separator();
        const Camera& c = state.view_camera();
        ImGui::Text("camera %.0f %.0f %.0f  yaw %.0f  pitch %.0f", double(c.position.x), double(c.position.y),
                    double(c.position.z), double(c.yaw_degrees), double(c.pitch_degrees));
        ImGui::Text("speed %.0f u/s (wheel; shift x%.0f)", double(state.move_speed()), double(kFastFactor));
        float fov = c.fov_y_degrees;
        if (ImGui::SliderFloat("field of view", &fov, kMinFovDegrees, kMaxFovDegrees, "%.0f deg"))
            state.set_fov(fov);
        if (ImGui::Button("Reset camera"))
            state.reset_camera();
        ImGui::SameLine();
        ImGui::SetNextItemWidth(80.0f);
        ImGui::InputInt("##goto", &panel.go_to_region, 0);
        ImGui::SameLine();
        if (ImGui::Button("Go to region") && panel.go_to_region >= 0)
            state.go_to_region(uint32_t(panel.go_to_region));
        if (const auto& target = state.orbit_target())
            ImGui::TextDisabled("orbit about %.0f %.0f %.0f (middle drag)", double(target->x), double(target->y),
                                double(target->z));
        else
            ImGui::TextDisabled("pick a face, then middle-drag to orbit about it");
    }
    ImGui::End();
}

} // namespace pvs::gui
