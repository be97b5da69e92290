// The Compare panel: `pvscope compare` over the open zone on a background thread (CompareJob),
// its speed-vs-accuracy chart drawn by the same module as the CLI's PNG (ui/chart/), and a click
// on a point (or a row of the table) culls with that method's PVS (InspectorState::use_compared_pvs).
#include "ui/chart/compare_points.h"
#include "ui/gui/chart_imgui_canvas.h"
#include "ui/chart/speed_accuracy_chart.h"
#include "ui/gui/panels.h"

#include <algorithm>
#include <cstdio>

namespace pvs::gui {

namespace {

constexpr float kChartHeight = 300.0f;

void draw_request(InspectorState& state, ComparePanel& panel)
{
    ImGui::SetNextItemWidth(110.0f);
    ImGui::InputInt("reference lines/region", &panel.reference_samples, 64, 1024);
    panel.reference_samples = std::clamp(panel.reference_samples, 16, 1 << 16);
    ImGui::SetNextItemWidth(110.0f);
    ImGui::InputInt("cameras", &panel.cameras, 10, 100);
    panel.cameras = std::clamp(panel.cameras, 0, 5000);
    CompareJob& job = state.compare_job();
    if (job.status() == JobStatus::Running) {
        char label[96];
        std::snprintf(label, sizeof label, "%s %.0f%%", job.stage().c_str(), 100.0 * job.progress());
        ImGui::ProgressBar(float(job.progress()), ImVec2(-1.0f, 0.0f), label);
        if (ImGui::Button("Cancel"))
            job.cancel();
        return;
    }
    if (ImGui::Button("Compare every method")) {
        ui::CompareOptions options;
        options.reference_samples = uint64_t(panel.reference_samples);
        options.cameras = size_t(panel.cameras);
        state.start_compare(options);
    }
    if (job.status() == JobStatus::Failed)
        ImGui::TextWrapped("compare failed: %s", job.error().c_str());
    else if (job.status() == JobStatus::Cancelled)
        ImGui::TextUnformatted("compare cancelled");
}

void draw_chart(InspectorState& state, const ui::CompareResult& result)
{
    const std::vector<ui::chart::ChartPoint> points = ui::chart::compare_chart_points(result);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, 200.0f), kChartHeight);
    ui::chart::ImguiCanvas canvas(ImGui::GetWindowDrawList(), ImGui::GetFont(), ImGui::GetFontSize());
    const ui::chart::PointPositions at = ui::chart::draw_speed_accuracy_chart(
        points, "speed against accuracy (click a point to cull with it)", canvas, {origin.x, origin.y}, {size.x, size.y});
    ImGui::InvisibleButton("chart", size);
    if (ImGui::IsItemClicked()) {
        const ImVec2 mouse = ImGui::GetMousePos();
        if (const int hit = ui::chart::point_near(at, {mouse.x, mouse.y}, 8.0f); hit >= 0)
            state.use_compared_pvs(size_t(hit));
    }
}

void draw_table(InspectorState& state, const ui::CompareResult& result)
{
    if (!ImGui::BeginTable("compare rows", 6, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_Borders))
        return;
    ImGui::TableSetupColumn("method");
    ImGui::TableSetupColumn("s");
    ImGui::TableSetupColumn("missing");
    ImGui::TableSetupColumn("excess");
    ImGui::TableSetupColumn("popping px");
    ImGui::TableSetupColumn("overdraw");
    ImGui::TableHeadersRow();
    for (size_t i = 0; i < result.rows.size(); ++i) {
        const ui::CompareRow& r = result.rows[i];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        const std::string label = r.method + " " + r.params + "##" + std::to_string(i);
        if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_SpanAllColumns))
            state.use_compared_pvs(i);
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", r.wall_s);
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(r.missing_bits));
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(r.excess_bits));
        ImGui::TableNextColumn();
        ImGui::Text("%llu", static_cast<unsigned long long>(r.popping_pixels));
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", r.triangle_overdraw);
    }
    ImGui::EndTable();
}

// Per method, the pairs it misses (the first few, pvs_gap.h) and its worst overdraw: a click
// explains the pair (the Region panel then shows why, the viewport the sight line or chain).
void draw_missing_pairs(InspectorState& state, const ui::CompareResult& result)
{
    for (size_t i = 0; i < result.rows.size(); ++i) {
        const ui::CompareRow& r = result.rows[i];
        if (r.missing_pairs.empty())
            continue;
        const std::string title = r.method + " " + r.params + ": missing pairs##missing" + std::to_string(i);
        if (!ImGui::TreeNode(title.c_str()))
            continue;
        for (const auto& [a, b] : r.missing_pairs) {
            const std::string label = std::to_string(a) + " -> " + std::to_string(b) + "##" + std::to_string(i);
            if (ImGui::Selectable(label.c_str()))
                state.request_explanation(a, b);
        }
        ImGui::TreePop();
    }
    // Per method, the excess pairs that draw the most triangles for nothing.
    for (size_t i = 0; i < result.rows.size(); ++i) {
        const ui::CompareRow& r = result.rows[i];
        if (r.worst_overdraw_pairs.empty())
            continue;
        const std::string title = r.method + " " + r.params + ": worst overdraw##worst" + std::to_string(i);
        if (!ImGui::TreeNode(title.c_str()))
            continue;
        for (const CostlyPair& p : r.worst_overdraw_pairs) {
            const std::string label = std::to_string(p.row) + " -> " + std::to_string(p.region) + ": " +
                                      std::to_string(p.cost) + " triangles##w" + std::to_string(i);
            if (ImGui::Selectable(label.c_str()))
                state.request_explanation(p.row, p.region);
        }
        ImGui::TreePop();
    }
}

} // namespace

void draw_compare_panel(InspectorState& state, ComparePanel& panel)
{
    const bool drawn = ImGui::Begin("Compare");
    panel.expanded = !ImGui::IsWindowCollapsed(); // the tiling gives it room next frame
    if (!drawn) {
        ImGui::End();
        return;
    }
    if (state.has_zone()) {
        draw_request(state, panel);
        if (const auto& result = state.compare_job().result()) {
            ImGui::Text("culling with: %s", state.pvs_source() == PvsSource::Baked ? state.baked_label().c_str()
                                                                                     : pvs_source_name(state.pvs_source()));
            draw_chart(state, *result);
            draw_table(state, *result);
            draw_missing_pairs(state, *result);
        }
    }
    ImGui::End();
}

} // namespace pvs::gui
