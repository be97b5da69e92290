#include "ui/gui/bake_job.h"

#include "visibility/methods/vis_method.h"

#include <stdexcept>
#include <utility>

namespace pvs::gui {

const char* job_status_name(JobStatus status)
{
    switch (status) {
    case JobStatus::Idle: return "idle";
    case JobStatus::Running: return "running";
    case JobStatus::Done: return "done";
    case JobStatus::Cancelled: return "cancelled";
    case JobStatus::Failed: return "failed";
    }
    return "?";
}

bool BakeJob::start(const Zone& zone, const BakeRequest& request)
{
    if (job_.status() == JobStatus::Running)
        return false;
    request_ = request;
    return job_.start(
        [this, &zone, request](JobControl& control) {
            const VisMethod* method = find_vis_method(request.method);
            if (!method || !method->bakes)
                throw std::invalid_argument("no method that bakes is called '" + request.method +
                                            "' (they are: " + baking_method_names() + ")");
            MethodSettings settings = request.settings;
            settings.portals = nullptr;
            settings.progress = [this, &control](double fraction) {
                control.set_progress(fraction);
                if (on_progress)
                    on_progress(fraction);
                return !control.cancel_requested();
            };
            // A map extruded from 2-D bakes on its column portals, never on a file's.
            std::optional<PortalInput> own;
            const bool portal_method = request.method == "portal-fast" || request.method == "portal-full";
            if (portal_method && request.zone_portals && zone.portals && !zone.tree.has_height_nodes()) {
                own.emplace();
                own->portals = *zone.portals;
                own->source = "the zone's portal file";
                settings.portals = &*own;
            }
            Output out;
            if (!control.cancel_requested())
                out.run = method->run(zone, settings);
            else
                out.run.cancelled = true;
            return out;
        },
        [](const Output& out) { return out.run.pvs && !out.run.cancelled; });
}

size_t BakeJob::portal_count() const
{
    const ReportField* portals = find_field(output().run.fields, "portals");
    return portals ? size_t(std::get<uint64_t>(portals->value)) : 0;
}

const std::optional<Pvs>& BakeJob::result() const
{
    static const std::optional<Pvs> kNone;
    return job_.status() == JobStatus::Done ? output().run.pvs : kNone;
}

std::optional<Pvs> BakeJob::take_result()
{
    if (job_.status() != JobStatus::Done || !job_.output())
        return std::nullopt;
    return std::exchange(job_.output()->run.pvs, std::nullopt);
}

const BakeJob::Output& BakeJob::output() const
{
    static const Output kNothing;
    return job_.output() ? *job_.output() : kNothing;
}

} // namespace pvs::gui
