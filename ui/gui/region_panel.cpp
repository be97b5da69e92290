// The region panel: the picked region (or the camera's), its bounds, flags, faces, and its PVS
// row as a clipped list; a row entry selects that region.
#include "ui/gui/panels.h"

#include <bit>
#include <string>

namespace pvs::gui {

namespace {

// Decodes `region`'s PVS row into panel.row, once per region.
void update_row(const InspectorState& state, int32_t region, RegionPanel& panel)
{
    if (panel.row_zone == state.zone_generation() && panel.row_region == region)
        return;
    const Zone& zone = state.zone();
    panel.row_zone = state.zone_generation();
    panel.row_region = region;
    panel.row.clear();
    panel.row_missing = false;
    if (!zone.baked_pvs || region < 0 || uint32_t(region) >= zone.baked_pvs->region_count())
        return;
    const Pvs& pvs = *zone.baked_pvs;
    panel.row_missing = pvs.row_missing(uint32_t(region));
    panel.words.assign(pvs.words_per_row(), 0);
    pvs.decode_row(uint32_t(region), panel.words);
    for (size_t w = 0; w < panel.words.size(); ++w)
        for (uint64_t bits = panel.words[w]; bits; bits &= bits - 1)
            panel.row.push_back(uint32_t(w * 64 + size_t(std::countr_zero(bits))));
}

std::string flag_names(uint32_t flags)
{
    std::string names;
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        if (flags & (1u << bit))
            names += (names.empty() ? "" : ", ") + std::string(region_flag_name(1u << bit));
    return names.empty() ? "none" : names;
}

void draw_row_list(InspectorState& state, RegionPanel& panel)
{
    if (!state.zone().baked_pvs) {
        ImGui::TextDisabled("no PVS in this zone");
        return;
    }
    ImGui::Text("PVS row: %zu visible%s", panel.row.size(), panel.row_missing ? " (row missing: all visible)" : "");
    if (!ImGui::BeginChild("pvs_row", {0.0f, 0.0f}, true)) {
        ImGui::EndChild();
        return;
    }
    ImGuiListClipper clipper;
    clipper.Begin(int(panel.row.size()));
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const uint32_t r = panel.row[size_t(i)];
            const std::string label = "region " + std::to_string(r);
            if (ImGui::Selectable(label.c_str(), int32_t(r) == state.selection().region))
                state.select_region(int32_t(r));
        }
    ImGui::EndChild();
}

} // namespace

void draw_region_panel(InspectorState& state, RegionPanel& panel)
{
    if (!ImGui::Begin("Region")) {
        ImGui::End();
        return;
    }
    const int32_t region = state.has_zone() ? state.shown_region() : -1;
    if (region < 0 || size_t(region) >= state.zone().region_count()) {
        ImGui::TextUnformatted(state.has_zone() ? "The camera is not in a region; click a face to pick one." : "");
        ImGui::End();
        return;
    }
    const Zone& zone = state.zone();
    const Region& info = zone.regions[size_t(region)];
    const bool picked = state.selection().region == region;
    ImGui::Text("region %d (%s)", region, picked ? "selected" : "the camera's");
    if (picked) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Go to"))
            state.go_to_region(uint32_t(region));
        ImGui::SameLine();
        if (ImGui::SmallButton("Clear"))
            state.select_region(-1);
    }
    if (state.selection().face != ui::kNoFace)
        ImGui::TextDisabled("picked face %u, listed by %zu region(s)", state.selection().face,
                            state.selection().face_regions.size());
    ImGui::Text("bounds %.0f %.0f %.0f .. %.0f %.0f %.0f", double(info.bounds.min.x), double(info.bounds.min.y),
                double(info.bounds.min.z), double(info.bounds.max.x), double(info.bounds.max.y),
                double(info.bounds.max.z));
    ImGui::Text("flags: %s", flag_names(info.flags).c_str());
    if (info.zone_line >= 0 && size_t(info.zone_line) < zone.zone_lines.size())
        ImGui::Text("zone line to %s", zone.zone_lines[size_t(info.zone_line)].target.c_str());
    ImGui::Text("%zu faces, %llu triangles", zone.faces_of_region(uint32_t(region)).size(),
                static_cast<unsigned long long>(state.region_triangles(uint32_t(region))));
    update_row(state, region, panel);
    draw_row_list(state, panel);
    ImGui::End();
}

} // namespace pvs::gui
