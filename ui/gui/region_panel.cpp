// The region panel: the picked region (or the camera's), its bounds, flags, faces, and three
// clickable lists: its PVS row (the regions it sees), its column ("visible from": the regions
// that see it), both from the culler's current PVS source, and its neighbours through portals.
// Clicking an entry selects that region and moves the camera into it.
#include "ui/gui/panels.h"

#include "ui/gui/pvs_rows.h"

#include <string>

namespace pvs::gui {

namespace {

void update_lists(InspectorState& state, int32_t region, RegionPanel& panel)
{
    const bool neighbours_ready = state.portals_ready();
    if (panel.lists_zone == state.zone_generation() && panel.lists_pvs == state.pvs_generation() &&
        panel.lists_region == region && panel.lists_neighbours == neighbours_ready)
        return;
    panel.lists_zone = state.zone_generation();
    panel.lists_pvs = state.pvs_generation();
    panel.lists_region = region;
    panel.lists_neighbours = neighbours_ready;
    panel.row.clear();
    panel.column.clear();
    panel.neighbours.clear();
    panel.row_missing = false;
    if (const Pvs* pvs = state.active_pvs(); pvs && region >= 0 && uint32_t(region) < pvs->region_count()) {
        panel.row_missing = pvs->row_missing(uint32_t(region));
        panel.row = pvs_row_regions(*pvs, uint32_t(region));
        panel.column = pvs_column_regions(*pvs, uint32_t(region));
    }
    if (neighbours_ready)
        panel.neighbours = portal_neighbours(state.portals(), uint32_t(region));
}

std::string flag_names(uint32_t flags)
{
    std::string names;
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        if (flags & (1u << bit))
            names += (names.empty() ? "" : ", ") + std::string(region_flag_name(1u << bit));
    return names.empty() ? "none" : names;
}

// A clipped list of region ids; a click selects the region and goes there.
void draw_region_list(InspectorState& state, const char* id, const std::vector<uint32_t>& regions, float height)
{
    if (!ImGui::BeginChild(id, {0.0f, height}, true)) {
        ImGui::EndChild();
        return;
    }
    ImGuiListClipper clipper;
    clipper.Begin(int(regions.size()));
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const uint32_t r = regions[size_t(i)];
            const std::string label = "region " + std::to_string(r) + "##" + id;
            if (ImGui::Selectable(label.c_str(), int32_t(r) == state.selection().region)) {
                state.select_region(int32_t(r));
                state.go_to_region(r);
            }
        }
    ImGui::EndChild();
}

void draw_lists(InspectorState& state, RegionPanel& panel)
{
    const float list_height = std::max(60.0f, (ImGui::GetContentRegionAvail().y - 90.0f) / 3.0f);
    if (!state.active_pvs()) {
        ImGui::TextDisabled("no PVS source (Culling panel): no row or column");
    } else {
        ImGui::Text("sees %zu (PVS row, %s)%s", panel.row.size(), pvs_source_name(state.pvs_source()),
                    panel.row_missing ? ": row missing, all visible" : "");
        draw_region_list(state, "row", panel.row, list_height);
        ImGui::Text("visible from %zu (PVS column)", panel.column.size());
        draw_region_list(state, "column", panel.column, list_height);
    }
    if (!panel.lists_neighbours) {
        ImGui::TextDisabled("neighbours through portals:");
        ImGui::SameLine();
        if (ImGui::SmallButton("build portals"))
            state.portals();
        return;
    }
    ImGui::Text("%zu neighbours through portals", panel.neighbours.size());
    draw_region_list(state, "neighbours", panel.neighbours, list_height);
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
    update_lists(state, region, panel);
    draw_lists(state, panel);
    ImGui::End();
}

} // namespace pvs::gui
