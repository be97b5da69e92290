// Thread scheduling of the portal-vis baker (portal_vis.h, "Threads, progress, cancellation").
//
// Contract. run_parallel runs worker(t) for t in [0, threads) on worker threads while the
// calling thread calls progress(fraction()) about every 50 ms (never when progress is empty);
// progress returning false sets `user_cancel` and `cancel`. With one thread and no progress
// callback the worker runs on the calling thread. An exception from a worker sets `cancel` (so
// the other workers stop and no one waits for a portal that will never finish); exceptions from
// workers or from progress are rethrown once every thread has joined. The workers take their
// items from counters of their own: which thread does what never changes a result.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace pvs::portal_vis {

// Shares of the progress bar (Method::Full): base vis, then the passages when built; the flow
// gets the rest.
constexpr double kBaseWeight = 0.1;
constexpr double kPassageWeight = 0.1;

// The worker count for `requested` threads (0 = hardware concurrency) and `items` items: at
// least 1, at most 256 and at most `items`.
unsigned thread_count(unsigned requested, size_t items);

void run_parallel(unsigned threads, const std::function<void(unsigned)>& worker, std::atomic<bool>& cancel,
                  std::atomic<bool>& user_cancel, const std::function<bool(double)>& progress,
                  const std::function<double()>& fraction);

} // namespace pvs::portal_vis
