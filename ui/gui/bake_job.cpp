#include "ui/gui/bake_job.h"

#include "visibility/methods/vis_method.h"

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
            Output out;
            VisParams params;
            params.method = request.method;
            params.level = request.level;
            params.threads = request.threads;
            params.progress = [this, &control](double fraction) {
                control.set_progress(fraction);
                if (on_progress)
                    on_progress(fraction);
                return !control.cancel_requested();
            };
            if (!control.cancel_requested())
                out.pvs = bake_zone_portal_vis(zone, params, false, &out.report, &out.portals);
            return out;
        },
        [](const Output& out) { return out.pvs && !out.report.cancelled; });
}

const std::optional<Pvs>& BakeJob::result() const
{
    static const std::optional<Pvs> kNone;
    return job_.status() == JobStatus::Done ? output().pvs : kNone;
}

std::optional<Pvs> BakeJob::take_result()
{
    if (job_.status() != JobStatus::Done || !job_.output())
        return std::nullopt;
    return std::exchange(job_.output()->pvs, std::nullopt);
}

const BakeJob::Output& BakeJob::output() const
{
    static const Output kNothing;
    return job_.output() ? *job_.output() : kNothing;
}

} // namespace pvs::gui
