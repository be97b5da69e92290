// `compare` on a background thread, for the inspector's Compare panel: ui::run_compare over the
// open zone with a progress fraction, the stage it is in, and a cancel the UI thread reads and
// sets each frame. The same states and lifetime rules as BakeJob (bake_job.h): Idle -> start() ->
// Running -> Done (result() holds the rows) | Cancelled | Failed (error() says why); the owner
// keeps the zone alive and unchanged until stop() (cancel and join), which the destructor calls.
#pragma once

#include "ui/gui/bake_job.h"
#include "ui/method_compare.h"

#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace pvs::gui {

class CompareJob {
public:
    CompareJob() = default;
    ~CompareJob();
    CompareJob(const CompareJob&) = delete;
    CompareJob& operator=(const CompareJob&) = delete;

    // Starts comparing on `zone`; false (and nothing happens) while a compare is running.
    bool start(const Zone& zone, const ui::CompareOptions& options);
    void cancel() { cancel_ = true; }
    void stop();
    BakeStatus poll();

    BakeStatus status() const { return status_; }
    double progress() const { return progress_.load(); }
    std::string stage() const;
    const std::optional<ui::CompareResult>& result() const { return result_; }
    const std::string& error() const { return error_; }

private:
    void run(const Zone& zone, ui::CompareOptions options);

    std::jthread thread_;
    std::atomic<double> progress_{0.0};
    std::atomic<bool> cancel_{false};
    std::atomic<bool> finished_{false};
    BakeStatus status_ = BakeStatus::Idle;

    mutable std::mutex mutex_; // guards the worker's outputs and the stage name
    std::string stage_;
    std::optional<ui::CompareResult> worker_result_;
    std::string worker_error_;

    std::optional<ui::CompareResult> result_;
    std::string error_;
};

} // namespace pvs::gui
