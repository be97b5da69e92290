// The inspector's "why does A see B?" (inspector_state.h): the explanation job and the overlay
// it feeds.
#include "ui/gui/inspector_state.h"

#include <chrono>

namespace pvs::gui {
namespace {

// The explanation as the overlay draws it: the witness, and per chain step its portal's polygon
// (from the portal set the flow used) and, for the 3-D flow, the window it saw where that is
// smaller than the portal.
ui::PairOverlay pair_overlay(const PairExplanation& e)
{
    ui::PairOverlay overlay;
    if (e.witness)
        overlay.sight_line = std::array<glm::vec3, 2>{glm::vec3(e.witness->from), glm::vec3(e.witness->to)};
    if (!e.chain)
        return overlay;
    for (const ChainStep& step : e.chain->steps) {
        std::vector<glm::vec3>& polygon = overlay.chain_portals.emplace_back();
        if (step.portal < e.portals.portals.size()) {
            const Portal& p = e.portals.portals[step.portal];
            if (size_t(p.first_point) + p.point_count <= e.portals.points.size())
                polygon.assign(e.portals.points.begin() + p.first_point,
                               e.portals.points.begin() + p.first_point + p.point_count);
        }
        // The window only where the flow narrowed it: a whole one would hide its portal's outline.
        std::vector<glm::vec3>& window = overlay.chain_windows.emplace_back();
        if (!e.chain_2d && step.window_size < 0.999 * step.portal_size)
            for (const glm::dvec3& point : step.window)
                window.emplace_back(point);
    }
    return overlay;
}

} // namespace

bool InspectorState::request_explanation(uint32_t a, uint32_t b)
{
    if (!zone_ || !zone_->tree.exists() || zone_->view_grid) {
        error_ = "why: the zone has no BSP tree of regions to explain a pair on";
        return false;
    }
    if (a >= zone_->region_count() || b >= zone_->region_count()) {
        error_ = "why: region " + std::to_string(std::max(a, b)) + " is out of range (" +
                 std::to_string(zone_->region_count()) + " regions)";
        return false;
    }
    clear_explanation();
    const Pvs* active = active_pvs();
    explain_pvs_ = active ? std::optional<Pvs>(*active) : std::nullopt;
    explain_job_ = std::async(std::launch::async, [zone = zone_.get(), pvs = explain_pvs_ ? &*explain_pvs_ : nullptr, a, b] {
        return explain_pair(*zone, pvs, a, b, ExplainOptions{});
    });
    return true;
}

void InspectorState::take_finished_explanation()
{
    if (!explain_job_.valid() || explain_job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return;
    try {
        explanation_ = explain_job_.get();
        pair_overlay_ = pair_overlay(*explanation_);
    } catch (const std::exception& e) { // bad_alloc, or a zone the flow refuses
        error_ = std::string("why: ") + e.what();
    }
    explain_pvs_.reset();
}

const PairExplanation* InspectorState::wait_for_explanation()
{
    if (explain_job_.valid()) {
        explain_job_.wait();
        take_finished_explanation();
    }
    return explanation_ ? &*explanation_ : nullptr;
}

void InspectorState::clear_explanation()
{
    if (explain_job_.valid())
        explain_job_.wait(); // it reads the zone and explain_pvs_
    explain_job_ = {};
    explain_pvs_.reset();
    explanation_.reset();
    pair_overlay_ = {};
}

bool InspectorState::look_along_witness()
{
    if (!explanation_ || !explanation_->camera)
        return false;
    const WitnessCamera& c = *explanation_->camera;
    view_.position = glm::vec3(c.eye);
    view_.yaw_degrees = float(c.yaw_degrees);
    view_.pitch_degrees = float(c.pitch_degrees);
    set_orbit_target(std::nullopt);
    if (!locked_)
        cull_ = view_;
    return true;
}

} // namespace pvs::gui
