// One piece of long work on a background thread, for the inspector's panels (the Bake panel's
// bake_job.h, the Compare panel's compare_job.h): progress, the stage it is in and a cancel the
// UI thread reads and sets each frame, so the UI never blocks.
//
// States: Idle -> start() -> Running -> Done | Cancelled | Failed (error() says why); start()
// again from any state but Running. The work returns an Output and `completed(output)` says
// whether it ran to the end (Done) or stopped on the cancel (Cancelled); an exception makes the
// job Failed. The worker only publishes; the UI thread sees the end through poll(), which is
// where the state changes, so the state a frame reads does not change under it. output() holds
// the work's Output once the job has ended Done or Cancelled.
//
// Lifetime: whatever the work reads (the zone) must outlive it: stop() (cancel and join) before
// replacing it. The destructor stops too.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <utility>

namespace pvs::gui {

enum class JobStatus : uint8_t { Idle, Running, Done, Cancelled, Failed };
const char* job_status_name(JobStatus status);

// What the work sees of its job: where to publish progress and stage, whether to stop.
class JobControl {
public:
    void set_progress(double fraction) { progress_ = fraction; }
    void set_stage(std::string_view stage)
    {
        const std::lock_guard lock(mutex_);
        if (stage_ != stage)
            stage_ = stage;
    }
    bool cancel_requested() const { return cancel_.load(); }

private:
    template <class>
    friend class BackgroundJob;
    std::atomic<double> progress_{0.0};
    std::atomic<bool> cancel_{false};
    mutable std::mutex mutex_;
    std::string stage_;
};

template <class Output>
class BackgroundJob {
public:
    using Work = std::function<Output(JobControl&)>;
    using Completed = std::function<bool(const Output&)>;

    BackgroundJob() = default;
    ~BackgroundJob() { stop(); }
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

    // Starts `work` on the worker thread; false (and nothing happens) while a job is running.
    bool start(Work work, Completed completed)
    {
        if (status_ == JobStatus::Running)
            return false;
        if (thread_.joinable())
            thread_.join(); // finished already (status is not Running)
        control_.progress_ = 0.0;
        control_.cancel_ = false;
        control_.set_stage("");
        finished_ = false;
        output_.reset();
        error_.clear();
        completed_ = std::move(completed);
        status_ = JobStatus::Running;
        thread_ = std::jthread([this, work = std::move(work)] { run(work); });
        return true;
    }

    // Asks the running work to stop; poll() reports the end once it has.
    void cancel() { control_.cancel_ = true; }
    // cancel() and wait for the worker; then poll().
    void stop()
    {
        cancel();
        if (thread_.joinable())
            thread_.join();
        poll();
    }

    // Takes the worker's outcome when it has finished. Returns the status.
    JobStatus poll()
    {
        if (status_ != JobStatus::Running || !finished_.load())
            return status_;
        if (thread_.joinable())
            thread_.join();
        const std::lock_guard lock(mutex_);
        error_ = std::move(worker_error_);
        output_ = std::move(worker_output_);
        worker_output_.reset();
        if (!error_.empty() || !output_)
            status_ = JobStatus::Failed;
        else
            status_ = completed_(*output_) ? JobStatus::Done : JobStatus::Cancelled;
        return status_;
    }

    JobStatus status() const { return status_; }
    double progress() const { return control_.progress_.load(); } // 0 .. 1, while running
    std::string stage() const
    {
        const std::lock_guard lock(control_.mutex_);
        return control_.stage_;
    }
    const std::optional<Output>& output() const { return output_; }
    std::optional<Output>& output() { return output_; }
    std::optional<Output> take_output() { return std::exchange(output_, std::nullopt); }
    const std::string& error() const { return error_; }

private:
    void run(const Work& work)
    {
        std::optional<Output> output;
        std::string error;
        try {
            output.emplace(work(control_));
        } catch (const std::exception& e) {
            error = e.what();
        } catch (...) {
            error = "unknown error";
        }
        const std::lock_guard lock(mutex_);
        worker_output_ = std::move(output);
        worker_error_ = std::move(error);
        finished_ = true;
    }

    std::jthread thread_;
    JobControl control_;
    std::atomic<bool> finished_{false};
    JobStatus status_ = JobStatus::Idle;
    Completed completed_;

    std::mutex mutex_; // the worker's outcome, written before finished_ is set
    std::optional<Output> worker_output_;
    std::string worker_error_;

    std::optional<Output> output_;
    std::string error_;
};

} // namespace pvs::gui
