// A PVS bake on a background thread, for the inspector's Bake panel: the zone's portals (its
// own, else build_zone_portals, visibility/portal/portalize.h) through bake_portal_vis
// (visibility/portal/portal_vis.h), with a progress fraction and a cancel the UI thread reads
// and sets each frame, so the UI never blocks on a bake.
//
// States: Idle -> start() -> Running -> Done (result() holds the PVS) | Cancelled | Failed
// (error() says why); start() again from any state but Running. The worker only publishes; the
// UI thread sees the end through poll(), which is where the state changes, so the state a frame
// reads does not change under it.
//
// Lifetime: the worker reads the Zone given to start() until it ends; the owner must keep that
// zone alive and unchanged until then: stop() (cancel and join) before replacing it. The
// destructor stops too.
//
// on_progress, when set before start(), is called on the worker thread with each progress
// fraction after it is published (tests use it to cancel at a known point).
#pragma once

#include "visibility/portal/portal_vis.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

namespace pvs::gui {

enum class BakeStatus : uint8_t { Idle, Running, Done, Cancelled, Failed };
const char* bake_status_name(BakeStatus status);

struct BakeRequest {
    VisParams::Method method = VisParams::Method::Fast;
    int level = 4;        // Full: separator test level 0 .. 4
    unsigned threads = 1; // worker threads of the baker (0 = all cores)
};

class BakeJob {
public:
    BakeJob() = default;
    ~BakeJob();
    BakeJob(const BakeJob&) = delete;
    BakeJob& operator=(const BakeJob&) = delete;

    // Starts baking `zone`; false (and nothing happens) while a bake is running.
    bool start(const Zone& zone, const BakeRequest& request);
    // Asks the running bake to stop; poll() reports Cancelled once it has.
    void cancel();
    // cancel() and wait for the worker; the status becomes Cancelled if it was running.
    void stop();
    // Takes the worker's outcome when it has finished. Returns the status.
    BakeStatus poll();

    BakeStatus status() const { return status_; }
    double progress() const { return progress_.load(); } // 0 .. 1, while running
    // The baked PVS (Done only); take_result moves it out.
    const std::optional<Pvs>& result() const { return result_; }
    std::optional<Pvs> take_result() { return std::exchange(result_, std::nullopt); }
    const VisReport& report() const { return report_; }
    const BakeRequest& request() const { return request_; }
    size_t portal_count() const { return portal_count_; }
    const std::string& error() const { return error_; }

    std::function<void(double fraction)> on_progress;

private:
    void run(const Zone& zone, BakeRequest request);

    std::jthread thread_;
    std::atomic<double> progress_{0.0};
    std::atomic<bool> cancel_{false};
    std::atomic<bool> finished_{false};
    BakeStatus status_ = BakeStatus::Idle;
    BakeRequest request_;

    // Written by the worker before finished_ is set, read by poll() after it.
    std::mutex mutex_;
    std::optional<Pvs> worker_result_;
    VisReport worker_report_;
    size_t worker_portals_ = 0;
    std::string worker_error_;

    std::optional<Pvs> result_;
    VisReport report_;
    size_t portal_count_ = 0;
    std::string error_;
};

} // namespace pvs::gui
