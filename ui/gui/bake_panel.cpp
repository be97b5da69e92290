// The bake panel: any baking method of the registry with the settings it reads (level, passages,
// portals from the file or the tree, heights, reference lines, raster density, threads), run on
// a background thread (BakeJob) with a progress bar and a cancel; the result becomes the
// "baked" PVS source of the Culling panel, and is compared with the zone file's own PVS: for
// the shown region, the regions only one of them lets it see (file only in red, baked only in
// green), and the totals over the whole zone.
#include "ui/gui/panels.h"

#include "ui/gui/pvs_rows.h"

#include <algorithm>
#include <string>
#include <thread>
#include <utility>

namespace pvs::gui {

namespace {

const ImVec4 kOnlyFileColor{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kOnlyBakedColor{0.45f, 1.0f, 0.45f, 1.0f};

// The registry's baking methods in a combo, its description as the tooltip.
void draw_method_choice(BakeRequest& r)
{
    ImGui::SetNextItemWidth(-80.0f);
    if (ImGui::BeginCombo("method", r.method.c_str())) {
        for (const VisMethod& m : vis_methods()) {
            if (!m.bakes)
                continue;
            if (ImGui::Selectable(std::string(m.name).c_str(), r.method == m.name))
                r.method = std::string(m.name);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("%.*s", int(m.description.size()), m.description.data());
        }
        ImGui::EndCombo();
    }
}

// An unsigned setting through an int field, kept within [low, high].
template <typename Unsigned>
void input_unsigned(const char* label, Unsigned& value, int low, int high)
{
    int v = int(std::min<Unsigned>(value, Unsigned(high)));
    ImGui::SetNextItemWidth(120.0f);
    if (ImGui::InputInt(label, &v))
        value = Unsigned(std::clamp(v, low, high));
}

// The settings the chosen method reads (vis_method.h), nothing else.
void draw_method_settings(const Zone& zone, BakeRequest& r)
{
    MethodSettings& s = r.settings;
    const bool portal = r.method == "portal-fast" || r.method == "portal-full";
    if (r.method == "portal-full" || r.method == "clustered") {
        ImGui::SetNextItemWidth(120.0f);
        ImGui::SliderInt("level", &s.level, 0, 4);
        ImGui::Checkbox("passages", &s.passages);
        ImGui::SameLine();
        ImGui::Checkbox("target checks", &s.target_checks);
    }
    if (portal && zone.portals && !zone.tree.has_height_nodes()) {
        int from_file = r.zone_portals ? 1 : 0;
        ImGui::TextUnformatted("portals");
        ImGui::SameLine();
        ImGui::RadioButton("file", &from_file, 1);
        ImGui::SameLine();
        ImGui::RadioButton("tree", &from_file, 0);
        r.zone_portals = from_file == 1;
    }
    if (portal && zone.tree.has_height_nodes())
        ImGui::Checkbox("heights block sight (static maps only)", &s.heights);
    if (r.method == "reference") {
        input_unsigned("lines/region (0: converge)", s.samples, 0, 1 << 24);
        input_unsigned("seed", s.seed, 1, 1 << 30);
    }
    if (r.method == "raster") {
        input_unsigned("pixels per face side", s.raster_resolution, 8, 1024);
        input_unsigned("points per region", s.raster_points, 1, 4096);
        // Where the views are drawn (raster_vis.h): the summary after the bake says which ran.
        int device = int(s.raster_device);
        ImGui::TextUnformatted("device");
        for (const auto& [label, value] : {std::pair{"CPU", RasterDevice::Cpu}, std::pair{"GPU", RasterDevice::Gpu},
                                           std::pair{"auto", RasterDevice::Auto}}) {
            ImGui::SameLine();
            ImGui::RadioButton(label, &device, int(value));
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("auto: the GPU when one answers through EGL, else the CPU");
        s.raster_device = RasterDevice(device);
    }
    int threads = int(s.threads);
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    ImGui::SetNextItemWidth(120.0f);
    if (ImGui::SliderInt("threads", &threads, 1, cores))
        s.threads = unsigned(std::clamp(threads, 1, cores));
}

void draw_request(InspectorState& state, BakePanel& panel)
{
    BakeRequest& r = panel.request;
    draw_method_choice(r);
    draw_method_settings(state.zone(), r);
    BakeJob& job = state.bake_job();
    if (job.status() == JobStatus::Running) {
        if (ImGui::Button("Cancel"))
            job.cancel();
        ImGui::SameLine();
        ImGui::ProgressBar(float(job.progress()), {-1.0f, 0.0f});
    } else if (ImGui::Button("Bake")) {
        state.start_bake(panel.request);
    }
}

void draw_outcome(const InspectorState& state)
{
    const BakeJob& job = state.bake_job();
    if (job.status() == JobStatus::Failed)
        ImGui::TextColored({1.0f, 0.4f, 0.3f, 1.0f}, "bake failed: %s", job.error().c_str());
    else if (job.status() == JobStatus::Cancelled)
        ImGui::TextDisabled("cancelled: nothing kept");
    if (!state.baked_pvs())
        return;
    ImGui::TextWrapped("baked: %s", state.baked_summary().c_str());
}

void update_diff(const InspectorState& state, BakePanel& panel, int32_t region)
{
    if (panel.diff_pvs == state.pvs_generation() && panel.diff_region == region)
        return;
    const bool new_pvs = panel.diff_pvs != state.pvs_generation();
    panel.diff_pvs = state.pvs_generation();
    panel.diff_region = region;
    panel.only_file.clear();
    panel.only_baked.clear();
    const Zone& zone = state.zone();
    if (!zone.baked_pvs || !state.baked_pvs())
        return;
    if (new_pvs) {
        const PvsDiffCounts counts = diff_pvs(*zone.baked_pvs, *state.baked_pvs());
        panel.total_only_file = counts.only_a;
        panel.total_only_baked = counts.only_b;
    }
    if (region < 0)
        return;
    RegionDiff diff = diff_regions(pvs_row_regions(*zone.baked_pvs, uint32_t(region)),
                                   pvs_row_regions(*state.baked_pvs(), uint32_t(region)));
    panel.only_file = std::move(diff.only_a);
    panel.only_baked = std::move(diff.only_b);
}

void draw_diff_list(InspectorState& state, const char* id, const std::vector<uint32_t>& regions, ImVec4 colour)
{
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    if (ImGui::BeginChild(id, {ImGui::GetContentRegionAvail().x * (id[0] == 'f' ? 0.5f : 1.0f), 0.0f}, true)) {
        ImGuiListClipper clipper;
        clipper.Begin(int(regions.size()));
        while (clipper.Step())
            for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                const uint32_t r = regions[size_t(i)];
                if (ImGui::Selectable(("region " + std::to_string(r) + "##" + id).c_str())) {
                    state.select_region(int32_t(r));
                    state.go_to_region(r);
                }
            }
    }
    ImGui::EndChild();
    ImGui::PopStyleColor();
}

void draw_diff(InspectorState& state, BakePanel& panel)
{
    if (!state.baked_pvs())
        return;
    if (!state.zone().baked_pvs) {
        ImGui::TextDisabled("the zone file has no PVS to compare with");
        return;
    }
    const int32_t region = state.shown_region();
    update_diff(state, panel, region);
    ImGui::TextColored(kOnlyFileColor, "file only: %llu pairs", static_cast<unsigned long long>(panel.total_only_file));
    ImGui::SameLine();
    ImGui::TextColored(kOnlyBakedColor, "baked only: %llu pairs",
                       static_cast<unsigned long long>(panel.total_only_baked));
    if (region < 0)
        return;
    ImGui::Text("region %d: %zu file only, %zu baked only", region, panel.only_file.size(), panel.only_baked.size());
    draw_diff_list(state, "file_only", panel.only_file, kOnlyFileColor);
    ImGui::SameLine();
    draw_diff_list(state, "baked_only", panel.only_baked, kOnlyBakedColor);
}

} // namespace

void draw_bake_panel(InspectorState& state, BakePanel& panel)
{
    if (!ImGui::Begin("Bake")) {
        ImGui::End();
        return;
    }
    if (state.has_zone()) {
        draw_request(state, panel);
        draw_outcome(state);
        if (state.baked_pvs() && state.pvs_source() != PvsSource::Baked) {
            if (ImGui::SmallButton("Cull with the baked PVS"))
                state.set_pvs_source(PvsSource::Baked);
        }
        ImGui::Separator();
        draw_diff(state, panel);
    }
    ImGui::End();
}

} // namespace pvs::gui
