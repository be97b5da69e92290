// The Zone panel's Health section: `pvscope check` on the open zone, on a background thread, its
// checks listed with their verdicts (error red, warning yellow, note grey, passed green); a
// failed check opens to its first failures, and a click on one takes the camera there (its point,
// or into its region, which is selected).
#include "ui/gui/panels.h"

#include <string>

namespace pvs::gui {

namespace {

ImVec4 verdict_colour(const CheckItem& item)
{
    if (!item.applicable)
        return {0.55f, 0.55f, 0.55f, 1.0f};
    if (item.passed())
        return {0.45f, 0.9f, 0.45f, 1.0f};
    switch (item.severity) {
    case CheckSeverity::Error: return {1.0f, 0.4f, 0.3f, 1.0f};
    case CheckSeverity::Warning: return {1.0f, 0.85f, 0.3f, 1.0f};
    case CheckSeverity::Note: break;
    }
    return {0.75f, 0.75f, 0.75f, 1.0f};
}

const char* verdict(const CheckItem& item)
{
    return !item.applicable ? "n/a" : item.passed() ? "ok" : check_severity_name(item.severity);
}

void draw_item(InspectorState& state, const CheckItem& item)
{
    ImGui::PushStyleColor(ImGuiCol_Text, verdict_colour(item));
    const std::string label = item.name + "  " + verdict(item);
    bool open = false;
    if (item.applicable && !item.passed())
        open = ImGui::TreeNode(item.name.c_str(), "%s", label.c_str()); // opens to its failures
    else
        ImGui::BulletText("%s", label.c_str());
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", item.summary.c_str());
    if (!open)
        return;
    ImGui::TextWrapped("%s", item.summary.c_str());
    for (size_t i = 0; i < item.examples.size(); ++i) {
        const CheckPlace place = i < item.places.size() ? item.places[i] : CheckPlace{};
        const bool has_place = place.region >= 0 || place.has_point;
        const std::string text = item.examples[i] + "##" + item.name + std::to_string(i);
        if (ImGui::Selectable(text.c_str(), false, has_place ? 0 : ImGuiSelectableFlags_Disabled))
            state.go_to_check_place(place);
    }
    if (item.failed > item.examples.size())
        ImGui::TextDisabled("... and %zu more (pvscope check --examples N)", item.failed - item.examples.size());
    ImGui::TreePop();
}

} // namespace

void draw_health_section(InspectorState& state)
{
    if (!ImGui::CollapsingHeader("Health"))
        return;
    InspectorState::CheckJob& job = state.check_job();
    if (job.status() == JobStatus::Running) {
        ImGui::TextDisabled("checking ...");
        return;
    }
    if (ImGui::Button("Check"))
        state.start_check();
    if (job.status() == JobStatus::Failed)
        ImGui::TextColored({1.0f, 0.4f, 0.3f, 1.0f}, "check failed: %s", job.error().c_str());
    if (job.status() != JobStatus::Done || !job.output())
        return;
    const ZoneHealth& health = *job.output();
    ImGui::SameLine();
    ImGui::Text("%s: %zu errors, %zu warnings", health.errors() ? "unhealthy" : "healthy", health.errors(),
                health.warnings());
    for (const CheckItem& item : health.items)
        draw_item(state, item);
}

} // namespace pvs::gui
