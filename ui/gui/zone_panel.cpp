// The zone panel: compute_zone_stats' figures, the open field and the statistics export.
#include "ui/gui/panels.h"

#include <imgui_stdlib.h>

#include <fstream>

namespace pvs::gui {

namespace {

bool save_text(const std::string& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    return bool(out.flush());
}

void row(const char* name, const char* format, auto... values)
{
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    ImGui::TableNextColumn();
    ImGui::Text(format, values...);
}

void draw_figures(const InspectorState& state)
{
    const Zone& zone = state.zone();
    const ZoneStats& s = state.zone_stats();
    ImGui::TextWrapped("%s", zone.source.path.c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s, version %s, loaded in %.1f ms", zone.source.format.c_str(), zone.source.version.c_str(),
                       state.load_ms());
    ImGui::PopStyleColor();
    if (!ImGui::BeginTable("zone_figures", 2, ImGuiTableFlags_RowBg))
        return;
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("zone lines ").x);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    row("regions", "%u", s.regions);
    row("nodes", "%u (depth max %u, mean %.1f)", s.tree.nodes, s.tree.max_depth, s.tree.mean_depth);
    row("faces", "%u (%llu triangles)", s.faces, static_cast<unsigned long long>(s.triangles));
    row("vertices", "%u", s.vertices);
    row("materials", "%u (%u with pixels)", s.materials, s.materials_with_pixels);
    row("portals", "%u", s.portals);
    row("zone lines", "%u", s.zone_lines);
    if (s.pvs.present)
        row("PVS", "%s, mean %.1f visible (%.1f %%), %u-%u", s.pvs.dense ? "dense" : "compressed", s.pvs.mean_visible,
            s.pvs.mean_percent, s.pvs.min_visible, s.pvs.max_visible);
    else
        row("PVS", "%s", "none (frustum only)");
    row("memory", "%.2f MiB (PVS %.1f KiB)", double(s.memory_bytes) / (1024.0 * 1024.0),
        double(s.pvs.memory_bytes) / 1024.0);
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        if (s.flag_counts[bit])
            row(region_flag_name(1u << bit), "%u regions", s.flag_counts[bit]);
    if (!s.bounds.empty())
        row("bounds", "%.0f %.0f %.0f .. %.0f %.0f %.0f", double(s.bounds.min.x), double(s.bounds.min.y),
            double(s.bounds.min.z), double(s.bounds.max.x), double(s.bounds.max.y), double(s.bounds.max.z));
    ImGui::EndTable();
    for (const std::string& note : zone.source.notes)
        ImGui::TextWrapped("note: %s", note.c_str());
}

} // namespace

void draw_zone_panel(InspectorState& state, ZonePanel& panel)
{
    if (!ImGui::Begin("Zone")) {
        ImGui::End();
        return;
    }
    ImGui::SetNextItemWidth(-110.0f);
    const bool entered = ImGui::InputTextWithHint("##path", "zone file (.bsp, .s3d, ...)", &panel.open_path,
                                                  ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || entered) && !panel.open_path.empty())
        state.open_zone(panel.open_path);
    ImGui::SameLine();
    if (ImGui::Button("Demo"))
        state.open_demo();
    if (!state.error().empty())
        ImGui::TextColored({1.0f, 0.4f, 0.3f, 1.0f}, "%s", state.error().c_str());
    if (!state.has_zone()) {
        ImGui::End();
        return;
    }
    ImGui::Separator();
    draw_figures(state);

    ImGui::Separator();
    ImGui::SetNextItemWidth(-150.0f);
    ImGui::InputText("##export", &panel.export_base);
    ImGui::SameLine();
    if (ImGui::Button("JSON"))
        panel.message = save_text(panel.export_base + ".json", state.export_stats_json())
                            ? "wrote " + panel.export_base + ".json"
                            : "cannot write " + panel.export_base + ".json";
    ImGui::SameLine();
    if (ImGui::Button("CSV"))
        panel.message = save_text(panel.export_base + ".csv", state.export_stats_csv())
                            ? "wrote " + panel.export_base + ".csv"
                            : "cannot write " + panel.export_base + ".csv";
    if (!panel.message.empty())
        ImGui::TextDisabled("%s", panel.message.c_str());
    draw_health_section(state);
    ImGui::End();
}

} // namespace pvs::gui
