// The portal-vis baker's progress bar (portal_vis.h, "Threads, progress, cancellation"): the
// shares of its phases. Its threads are the worker pool's (visibility/worker_pool.h).
#pragma once

namespace pvs::portal_vis {

// Shares of the progress bar (Method::Full): base vis, then the passages when built; the flow
// gets the rest.
constexpr double kBaseWeight = 0.1;
constexpr double kPassageWeight = 0.1;

} // namespace pvs::portal_vis
