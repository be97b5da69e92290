#include "ui/gui/compare_job.h"

#include <exception>
#include <utility>

namespace pvs::gui {

CompareJob::~CompareJob() { stop(); }

bool CompareJob::start(const Zone& zone, const ui::CompareOptions& options)
{
    if (status_ == BakeStatus::Running)
        return false;
    if (thread_.joinable())
        thread_.join();
    progress_ = 0.0;
    cancel_ = false;
    finished_ = false;
    result_.reset();
    error_.clear();
    status_ = BakeStatus::Running;
    thread_ = std::jthread([this, &zone, options] { run(zone, options); });
    return true;
}

void CompareJob::run(const Zone& zone, ui::CompareOptions options)
{
    options.progress = [this](const std::string& stage, double fraction) {
        {
            const std::lock_guard lock(mutex_);
            if (stage_ != stage)
                stage_ = stage;
        }
        progress_ = fraction;
        return !cancel_.load();
    };
    std::optional<ui::CompareResult> result;
    std::string error;
    try {
        result = ui::run_compare(zone, options);
    } catch (const std::exception& e) {
        error = e.what();
    }
    const std::lock_guard lock(mutex_);
    worker_result_ = std::move(result);
    worker_error_ = std::move(error);
    finished_ = true;
}

std::string CompareJob::stage() const
{
    const std::lock_guard lock(mutex_);
    return stage_;
}

void CompareJob::stop()
{
    cancel();
    if (thread_.joinable())
        thread_.join();
    poll();
}

BakeStatus CompareJob::poll()
{
    if (status_ != BakeStatus::Running || !finished_.load())
        return status_;
    if (thread_.joinable())
        thread_.join();
    const std::lock_guard lock(mutex_);
    error_ = std::move(worker_error_);
    if (!error_.empty())
        status_ = BakeStatus::Failed;
    else if (!worker_result_ || worker_result_->cancelled)
        status_ = BakeStatus::Cancelled;
    else {
        status_ = BakeStatus::Done;
        result_ = std::move(worker_result_);
    }
    worker_result_.reset();
    return status_;
}

} // namespace pvs::gui
