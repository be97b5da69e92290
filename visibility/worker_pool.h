// The one worker pool of every parallel bake (portal vis 3-D and 2-D, passages, the reference,
// the mesh reference, the raster baker) and its one thread-count rule.
//
// thread_count(requested, items): 0 asks for every hardware thread; the count is capped at
// kMaxThreadsPerCore per hardware thread (a request of a million threads asks for what no machine
// gives) and at the work items, and is at least 1. Results never depend on it: workers take their
// items from shared counters and write to per-item slots.
//
// run_workers(threads, worker, stop, progress, fraction) runs worker(t) for t in [0, threads) on
// threads of its own while the calling thread calls progress(fraction()) at once and then about
// every 50 ms until they end (never when progress is empty or `stop` is set). Workers must watch `stop` and take their items from
// shared counters, because:
// - a thread the system refuses to start (std::system_error) leaves its share to the workers
//   already running, or to the calling thread (worker(0)) when none started;
// - an exception from a worker or from progress sets `stop`, and the first one is rethrown once
//   every thread has joined (never std::terminate);
// - progress returning false sets `stop`; run_workers then returns false (cancelled).
// With one thread and no progress callback the worker runs on the calling thread.
//
// parallel_items(count, threads, ...) is the common shape on top: items [0, count) taken one at a
// time, each worker with its own scratch made once by make_scratch().
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace pvs {

inline constexpr unsigned kMaxThreadsPerCore = 4;

unsigned thread_count(unsigned requested, size_t items);

bool run_workers(unsigned threads, const std::function<void(unsigned)>& worker, std::atomic<bool>& stop,
                 const std::function<bool(double)>& progress, const std::function<double()>& fraction);

// Items [0, count) on thread_count(threads, count) workers; work(item, scratch). False when cancelled.
template <class MakeScratch, class Work>
bool parallel_items(size_t count, unsigned threads, const std::function<bool(double)>& progress,
                    const std::function<double()>& fraction, std::atomic<bool>& stop, MakeScratch&& make_scratch,
                    Work&& work)
{
    std::atomic<size_t> next{0};
    const bool kept_going = run_workers(
        thread_count(threads, count),
        [&](unsigned) {
            auto scratch = make_scratch();
            while (!stop.load(std::memory_order_relaxed)) {
                const size_t item = next.fetch_add(1, std::memory_order_relaxed);
                if (item >= count)
                    return;
                work(item, scratch);
            }
        },
        stop, progress, fraction);
    return kept_going && !stop.load(); // a stop set before the call cancels too
}

} // namespace pvs
