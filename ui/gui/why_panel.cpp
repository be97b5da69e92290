// The Region panel's "Why does A see B?" section and the lists' "why?" menu (panels.h): the
// request, the verdict, the chain, and the camera along the sight line. The work is
// InspectorState's (pair_view.cpp); this only shows it.
#include "ui/gui/panels.h"

#include <algorithm>
#include <string>

namespace pvs::gui {
namespace {

void draw_chain(const PairExplanation& e)
{
    if (!e.chain) {
        ImGui::TextDisabled("portal-full has no chain from %u to %u", e.a, e.b);
        return;
    }
    ImGui::Text("portal-full chain, %zu portals (numbered in the viewport):", e.chain->steps.size());
    for (size_t k = 0; k < e.chain->steps.size(); ++k) {
        const ChainStep& s = e.chain->steps[k];
        const double kept = s.portal_size > 0 ? 100.0 * s.window_size / s.portal_size : 0.0;
        ImGui::BulletText("%zu: region %u through portal %u, %.0f%% seen, %u separators", k + 1, s.region, s.portal,
                          kept, s.separators);
    }
}

} // namespace

void why_context_menu(InspectorState& state, uint32_t a, uint32_t b)
{
    if (!ImGui::BeginPopupContextItem())
        return;
    const std::string label = "Why does " + std::to_string(a) + " see " + std::to_string(b) + "?";
    if (ImGui::MenuItem(label.c_str()))
        state.request_explanation(a, b);
    ImGui::EndPopup();
}

void draw_why_section(InspectorState& state, int& target, int32_t region)
{
    if (!ImGui::CollapsingHeader("Why does this region see...?", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    const int regions = int(state.zone().region_count());
    ImGui::SetNextItemWidth(120.0f);
    ImGui::InputInt("region B", &target);
    target = std::clamp(target, 0, std::max(regions - 1, 0));
    ImGui::SameLine();
    if (ImGui::Button("Explain"))
        state.request_explanation(uint32_t(region), uint32_t(target));
    if (state.explanation_running()) {
        ImGui::TextDisabled("explaining (portal-full flow and a sight-line search)...");
        return;
    }
    const std::optional<PairExplanation>& e = state.explanation();
    if (!e)
        return;
    ImGui::Text("%u -> %u: %s", e->a, e->b, pair_verdict_name(e->verdict));
    ImGui::TextWrapped("%s", e->summary.c_str());
    if (e->witness) {
        ImGui::Text("sight line after %llu lines", static_cast<unsigned long long>(e->witness->tries));
        if (ImGui::Button("Look along the sight line"))
            state.look_along_witness();
        ImGui::SameLine();
    }
    if (ImGui::Button("Clear##why"))
        state.clear_explanation();
    if (state.explanation())
        draw_chain(*state.explanation());
}

} // namespace pvs::gui
