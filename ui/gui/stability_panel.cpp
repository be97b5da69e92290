// The Stability panel: every method on every crafted stability case (wld/gen/case_table.h), as a
// grid of cases x methods with missing / excess bits against each case's known truth; a click on
// a cell opens that case at its camera and culls with that method's PVS
// (InspectorState::open_stability_case), so a user sees the failure from where it happens.
// The cases are a few regions each: the whole table takes well under a second, so it runs on
// the click, not on a background job.
#include "ui/gui/panels.h"

#include <cstdio>

namespace pvs::gui {

namespace {

const ImVec4 kBroken{1.0f, 0.35f, 0.3f, 1.0f};  // a bound broken: an upper bound misses a bit
const ImVec4 kLoose{1.0f, 0.8f, 0.3f, 1.0f};    // within its bound, but off the truth
const ImVec4 kExact{0.5f, 0.9f, 0.5f, 1.0f};

void draw_cell(InspectorState& state, StabilityPanel& panel, const gen::CaseTableRow& row)
{
    char text[64];
    std::snprintf(text, sizeof text, "-%llu +%llu##%s%s", static_cast<unsigned long long>(row.missing_bits),
                  static_cast<unsigned long long>(row.excess_bits), row.case_name.c_str(), row.method.c_str());
    const bool exact = row.missing_bits == 0 && row.excess_bits == 0;
    ImGui::PushStyleColor(ImGuiCol_Text, row.broken() ? kBroken : exact ? kExact : kLoose);
    const bool open_now = state.stability_case_name() == row.case_name && state.baked_label() == row.method + " on case " + row.case_name;
    if (ImGui::Selectable(text, open_now) && !state.open_stability_case(row.case_name, row.method))
        panel.message = state.error();
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s on %s: %llu of %llu truth bits missing, %llu excess (%s bound)", row.method.c_str(),
                          row.case_name.c_str(), static_cast<unsigned long long>(row.missing_bits),
                          static_cast<unsigned long long>(row.truth_bits), static_cast<unsigned long long>(row.excess_bits),
                          bound_name(row.bound));
}

void draw_grid(InspectorState& state, StabilityPanel& panel, const gen::CaseTable& table)
{
    const size_t methods = panel.options.methods.size();
    if (methods == 0 || !ImGui::BeginTable("cases", int(methods) + 1, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg))
        return;
    ImGui::TableSetupColumn("case");
    for (const std::string& m : panel.options.methods)
        ImGui::TableSetupColumn(m.c_str());
    ImGui::TableHeadersRow();
    for (size_t i = 0; i + methods <= table.rows.size(); i += methods) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(table.rows[i].case_name.c_str());
        for (size_t m = 0; m < methods; ++m) {
            ImGui::TableNextColumn();
            draw_cell(state, panel, table.rows[i + m]);
        }
    }
    ImGui::EndTable();
}

} // namespace

void draw_stability_panel(InspectorState& state, StabilityPanel& panel)
{
    const bool drawn = ImGui::Begin("Stability");
    panel.expanded = !ImGui::IsWindowCollapsed(); // the tiling gives it room next frame
    if (!drawn) {
        ImGui::End();
        return;
    }
    ImGui::TextWrapped("Each method on crafted zones whose truth is known: -missing (would pop) +excess (overdraw). "
                       "Click a cell to open the case at its camera with that method's PVS.");
    if (ImGui::Button("Run every case")) {
        try {
            panel.table = gen::run_case_table(panel.options);
            panel.message.clear();
        } catch (const std::exception& e) {
            panel.message = e.what();
        }
    }
    if (!state.stability_case_name().empty()) {
        ImGui::Text("open: %s, culling with %s", state.stability_case_name().c_str(), state.baked_label().c_str());
        if (state.stability_case_missing().empty())
            ImGui::TextUnformatted("  the PVS holds every pair of the truth");
        // "A -> B": a click explains the pair (the Region panel shows why, the viewport the pop).
        for (const std::string& pair : state.stability_case_missing()) {
            ImGui::PushStyleColor(ImGuiCol_Text, kBroken);
            const bool clicked = ImGui::Selectable(("  missing " + pair + "##case").c_str());
            ImGui::PopStyleColor();
            unsigned a = 0, b = 0;
            if (clicked && std::sscanf(pair.c_str(), "%u -> %u", &a, &b) == 2)
                state.request_explanation(a, b);
        }
    }
    if (!panel.message.empty())
        ImGui::TextColored(kBroken, "%s", panel.message.c_str());
    if (panel.table)
        draw_grid(state, panel, *panel.table);
    ImGui::End();
}

} // namespace pvs::gui
