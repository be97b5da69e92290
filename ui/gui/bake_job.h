// A PVS bake on a background thread, for the inspector's Bake panel: any method of the registry
// that bakes (visibility/methods/vis_method.h) with the request's settings; portal-fast and
// portal-full on the zone's own portals when it carries them (a Quake map's .prt beside it) and
// the request asks for them, else on the portals the method builds from the tree; as a
// BackgroundJob (background_job.h: its states, progress, cancel and lifetime rules). Done when
// the bake ran to the end: result() holds the PVS; a cancelled bake's PVS is only conservative
// and is not offered, but its report() (the method's run: summary, fields, cancelled) is kept.
//
// on_progress, when set before start(), is called on the worker thread with each progress
// fraction after it is published (tests use it to cancel at a known point).
#pragma once

#include "ui/gui/background_job.h"
#include "visibility/methods/vis_method.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <functional>
#include <optional>
#include <string>

namespace pvs::gui {

struct BakeRequest {
    std::string method = "portal-fast"; // a registry method that bakes; another fails the job
    // What the method reads of them (level, passages, samples, raster settings, heights, ...);
    // threads 1 by default, progress and portals are the job's.
    MethodSettings settings = one_thread();
    bool zone_portals = true; // portal-fast / portal-full: the zone's own portals when it has them

    static MethodSettings one_thread()
    {
        MethodSettings s;
        s.threads = 1;
        return s;
    }
};

class BakeJob {
public:
    ~BakeJob() { job_.stop(); } // before on_progress goes

    // Starts baking `zone`; false (and nothing happens) while a bake is running.
    bool start(const Zone& zone, const BakeRequest& request);
    void cancel() { job_.cancel(); }
    void stop() { job_.stop(); }
    JobStatus poll() { return job_.poll(); }

    JobStatus status() const { return job_.status(); }
    double progress() const { return job_.progress(); }
    // The baked PVS (Done only); take_result moves it out.
    const std::optional<Pvs>& result() const;
    std::optional<Pvs> take_result();
    const MethodRun& report() const { return output().run; }
    const BakeRequest& request() const { return request_; }
    size_t portal_count() const;
    const std::string& error() const { return job_.error(); }

    std::function<void(double fraction)> on_progress;

private:
    struct Output {
        MethodRun run; // run.pvs: the baked PVS
    };
    const Output& output() const;

    BakeRequest request_;
    BackgroundJob<Output> job_; // last: destroyed (joined) first
};

} // namespace pvs::gui
