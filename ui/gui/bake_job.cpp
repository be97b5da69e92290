#include "ui/gui/bake_job.h"

#include "visibility/methods/vis_method.h"

#include <exception>
#include <utility>

namespace pvs::gui {

const char* bake_status_name(BakeStatus status)
{
    switch (status) {
    case BakeStatus::Idle: return "idle";
    case BakeStatus::Running: return "running";
    case BakeStatus::Done: return "done";
    case BakeStatus::Cancelled: return "cancelled";
    case BakeStatus::Failed: return "failed";
    }
    return "?";
}

BakeJob::~BakeJob() { stop(); }

bool BakeJob::start(const Zone& zone, const BakeRequest& request)
{
    if (status_ == BakeStatus::Running)
        return false;
    if (thread_.joinable())
        thread_.join(); // finished already (status is not Running)
    progress_ = 0.0;
    cancel_ = false;
    finished_ = false;
    result_.reset();
    report_ = {};
    portal_count_ = 0;
    error_.clear();
    request_ = request;
    status_ = BakeStatus::Running;
    thread_ = std::jthread([this, &zone, request] { run(zone, request); });
    return true;
}

void BakeJob::run(const Zone& zone, BakeRequest request)
{
    std::optional<Pvs> pvs;
    VisReport report;
    size_t portals = 0;
    std::string error;
    try {
        VisParams params;
        params.method = request.method;
        params.level = request.level;
        params.threads = request.threads;
        params.progress = [this](double fraction) {
            progress_ = fraction;
            if (on_progress)
                on_progress(fraction);
            return !cancel_.load();
        };
        if (!cancel_)
            pvs = bake_zone_portal_vis(zone, params, false, &report, &portals);
    } catch (const std::exception& e) {
        error = e.what();
    }
    const std::lock_guard lock(mutex_);
    worker_result_ = std::move(pvs);
    worker_report_ = report;
    worker_portals_ = portals;
    worker_error_ = std::move(error);
    finished_ = true;
}

void BakeJob::cancel() { cancel_ = true; }

void BakeJob::stop()
{
    cancel();
    if (thread_.joinable())
        thread_.join();
    poll();
}

BakeStatus BakeJob::poll()
{
    if (status_ != BakeStatus::Running || !finished_.load())
        return status_;
    if (thread_.joinable())
        thread_.join();
    const std::lock_guard lock(mutex_);
    report_ = worker_report_;
    portal_count_ = worker_portals_;
    error_ = std::move(worker_error_);
    const bool cancelled = report_.cancelled || !worker_result_; // a finished bake stays Done
    if (!error_.empty())
        status_ = BakeStatus::Failed;
    else if (cancelled)
        status_ = BakeStatus::Cancelled; // a cancelled bake's PVS is only conservative: not offered
    else {
        status_ = BakeStatus::Done;
        result_ = std::move(worker_result_);
    }
    worker_result_.reset();
    return status_;
}

} // namespace pvs::gui
