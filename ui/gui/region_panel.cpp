// The region panel: the picked region (or the camera's), its bounds, flags, faces, and three
// clickable lists: its PVS row (the regions it sees), its column ("visible from": the regions
// that see it), both from the culler's current PVS source, and its neighbours through portals.
// Clicking an entry selects that region and moves the camera into it. Below them, PVS editing:
// the pair (camera's region, this region) shown or hidden, this region's row cleared or filled
// from portal-fast or the reference, undo/redo (also Ctrl-Z / Ctrl-Y anywhere), the edit count
// and its popping risk against a reference the Compare panel baked, and the edit list saved
// (re-applied after a re-bake with `pvscope bake --apply-edits`). Edited entries are marked *.
#include "ui/gui/panels.h"

#include "ui/gui/pvs_rows.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
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
    panel.column.restart(region >= 0 ? uint32_t(region) : UINT32_MAX); // UINT32_MAX: no column
    panel.neighbours.clear();
    panel.row_missing = false;
    if (const Pvs* pvs = state.active_pvs(); pvs && region >= 0 && uint32_t(region) < pvs->region_count()) {
        panel.row_missing = pvs->row_missing(uint32_t(region));
        panel.row = pvs_row_regions(*pvs, uint32_t(region));
    }
    if (neighbours_ready)
        panel.neighbours = portal_neighbours(*state.ready_portals(), uint32_t(region));
}


// A clipped list of region ids; a click selects the region and goes there. `edited(r)` marks
// the entries whose bit an edit set.
// `pair(r)` is the (A, B) pair a right click on entry r offers to explain.
template <class Edited, class Pair>
void draw_region_list(InspectorState& state, const char* id, const std::vector<uint32_t>& regions, float height,
                      Edited&& edited, Pair&& pair)
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
            const std::string label = "region " + std::to_string(r) + (edited(r) ? " *" : "") + "##" + id;
            if (ImGui::Selectable(label.c_str(), int32_t(r) == state.selection().region)) {
                state.select_region(int32_t(r));
                state.go_to_region(r);
            }
            const std::pair<uint32_t, uint32_t> ab = pair(r);
            why_context_menu(state, ab.first, ab.second);
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
        const EditablePvs* editor = state.pvs_source() == PvsSource::Edited ? state.pvs_editor() : nullptr;
        const uint32_t region = uint32_t(panel.lists_region);
        draw_region_list(
            state, "row", panel.row, list_height, [&](uint32_t r) { return editor && editor->edited(region, r); },
            [&](uint32_t r) { return std::pair(region, r); });
        // The column, read for at most a millisecond a frame (an open zone's takes tens).
        const Pvs& pvs = *state.active_pvs();
        const auto start = std::chrono::steady_clock::now();
        bool read = panel.column.region >= pvs.region_count();
        while (!read && std::chrono::steady_clock::now() - start < std::chrono::milliseconds(1))
            read = panel.column.step(pvs, 512);
        if (read)
            ImGui::Text("visible from %zu (PVS column)", panel.column.regions.size());
        else
            ImGui::Text("visible from %zu so far (PVS column, %u of %u rows read)", panel.column.regions.size(),
                        panel.column.next_row, pvs.row_count());
        draw_region_list(
            state, "column", panel.column.regions, list_height,
            [&](uint32_t r) { return editor && editor->edited(r, region); },
            [&](uint32_t r) { return std::pair(r, region); });
    }
    if (!panel.lists_neighbours) {
        ImGui::TextDisabled("neighbours through portals:");
        ImGui::SameLine();
        if (state.portals_building())
            ImGui::TextDisabled("building the portals...");
        else if (ImGui::SmallButton("build portals"))
            state.request_portals();
        return;
    }
    ImGui::Text("%zu neighbours through portals", panel.neighbours.size());
    const uint32_t region = uint32_t(panel.lists_region);
    draw_region_list(
        state, "neighbours", panel.neighbours, list_height, [](uint32_t) { return false; },
        [&](uint32_t r) { return std::pair(region, r); });
}

// The popping risk of the edits against the Compare panel's reference, when it has one.
void draw_edit_risk(const InspectorState& state)
{
    const std::optional<ui::CompareResult>& result = state.compare_job().result();
    if (!result)
        return;
    for (const ui::CompareRow& row : result->rows)
        if (row.method == "reference" && row.pvs) {
            ImGui::SameLine();
            ImGui::Text("| popping risk %zu pairs (vs the reference)", state.pvs_edit_popping_risk(*row.pvs));
            return;
        }
}

void draw_editing(InspectorState& state, RegionPanel& panel, int32_t region)
{
    if (!ImGui::CollapsingHeader("Edit PVS"))
        return;
    const int32_t camera = state.last_cull().region;
    const Pvs* pvs = state.active_pvs();
    if (!pvs && !state.pvs_editor()) {
        ImGui::TextDisabled("choose a PVS source to edit (file or baked)");
        return;
    }
    if (camera >= 0 && pvs && uint32_t(camera) < pvs->row_count()) {
        const bool sees = pvs->visible(uint32_t(camera), uint32_t(region));
        ImGui::Text("camera's region %d %s region %d", camera, sees ? "sees" : "does not see", region);
        if (ImGui::SmallButton(sees ? "Hide" : "Show"))
            state.edit_pvs(pair_edit(uint32_t(camera), uint32_t(region), !sees, panel.edit_both_ways));
        ImGui::SameLine();
        ImGui::Checkbox("both ways", &panel.edit_both_ways);
    }
    ImGui::Text("row of region %d:", region);
    for (const char* method : {"cleared", "portal-fast", "reference"}) {
        ImGui::SameLine();
        const std::string label = std::string(method == std::string("cleared") ? "clear" : method) + "##fill";
        if (ImGui::SmallButton(label.c_str()))
            state.fill_pvs_row(uint32_t(region), method);
    }
    const EditablePvs* editor = state.pvs_editor();
    const bool can_undo = editor && editor->can_undo(), can_redo = editor && editor->can_redo();
    if (!can_undo)
        ImGui::BeginDisabled();
    if (ImGui::SmallButton("Undo"))
        state.undo_pvs_edit();
    if (!can_undo)
        ImGui::EndDisabled();
    ImGui::SameLine();
    if (!can_redo)
        ImGui::BeginDisabled();
    if (ImGui::SmallButton("Redo"))
        state.redo_pvs_edit();
    if (!can_redo)
        ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Text("%zu edits", editor ? editor->edit_count() : size_t(0));
    draw_edit_risk(state);
    ImGui::InputText("##editlist", panel.edit_list_path, sizeof panel.edit_list_path);
    ImGui::SameLine();
    if (ImGui::SmallButton("Save list") && editor) {
        std::ofstream out(panel.edit_list_path);
        out << state.pvs_edit_list_json();
        panel.edit_message = out ? std::string("saved ") + panel.edit_list_path : "could not write the file";
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("Load"))
        panel.edit_message = state.load_pvs_edit_list(panel.edit_list_path) ? "applied " + std::string(panel.edit_list_path)
                                                                             : state.error();
    if (panel.save_path[0] == 0 && !state.zone().source.path.empty()) {
        const std::filesystem::path source(state.zone().source.path);
        const std::string name = source.stem().string() + "-edited" +
                                 (state.zone().view_grid ? std::string(".hepvs") : source.extension().string());
        std::snprintf(panel.save_path, sizeof panel.save_path, "%s", name.c_str());
    }
    ImGui::InputText("##savepvs", panel.save_path, sizeof panel.save_path);
    ImGui::SameLine();
    if (ImGui::SmallButton("Save PVS")) {
        std::string message;
        panel.edit_message = state.save_pvs(panel.save_path, message) ? message : state.error();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("A copy of the zone file with this PVS, in its own format (as pvscope bake -o writes it)");
    if (!panel.edit_message.empty())
        ImGui::TextWrapped("%s", panel.edit_message.c_str());
}

} // namespace

std::string flag_names(uint32_t flags)
{
    std::string names;
    for (uint32_t bit = 0; bit < kRegionFlagCount; ++bit)
        if (flags & (1u << bit))
            names += (names.empty() ? "" : ", ") + std::string(region_flag_name(1u << bit));
    return names.empty() ? "none" : names;
}

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
    if (size_t(region) < zone.region_names.size()) // an OBJ's object, a Quake 2 leaf's cluster and area
        ImGui::Text("%s", zone.region_names[size_t(region)].c_str());
    if (info.zone_line >= 0 && size_t(info.zone_line) < zone.zone_lines.size())
        ImGui::Text("zone line to %s", zone.zone_lines[size_t(info.zone_line)].target.c_str());
    ImGui::Text("%zu faces, %llu triangles", zone.faces_of_region(uint32_t(region)).size(),
                static_cast<unsigned long long>(state.region_triangles(uint32_t(region))));
    update_lists(state, region, panel);
    draw_why_section(state, panel.why_target, region);
    draw_editing(state, panel, region);
    draw_lists(state, panel);
    ImGui::End();
}

} // namespace pvs::gui
