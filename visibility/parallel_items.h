// Items [0, count) on `threads` workers that take them from a shared counter, while the calling
// thread reports progress about every 50 ms: the scheduling of the sampled bakers (the reference,
// the raster baker). Each worker makes its own scratch once (make_scratch()) and calls
// work(item, scratch); results go to per-item slots, so the outcome never depends on which worker
// took which item. progress(fraction()) returning false sets `stop`: the workers stop after their
// current item and parallel_items returns false. With one thread and no progress callback the
// items run on the calling thread. An exception from progress stops and joins the workers first.
// The worker count is capped at the item count and at kMaxThreadsPerCore per hardware thread (a
// request of a million threads asks for what no machine gives; the result does not depend on the
// count), and a thread the system refuses to start (std::system_error) leaves the items to the
// workers already running, or to the calling thread when none is.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace pvs {

inline constexpr unsigned kMaxThreadsPerCore = 4;

// The workers parallel_items starts for `requested` threads (0: 1) and `count` items.
inline unsigned parallel_items_threads(unsigned requested, size_t count)
{
    const size_t cores = std::max(1u, std::thread::hardware_concurrency());
    const size_t cap = std::min(std::max<size_t>(count, 1), cores * kMaxThreadsPerCore);
    return unsigned(std::min<size_t>(requested == 0 ? 1 : requested, cap));
}

template <class MakeScratch, class Work>
bool parallel_items(size_t count, unsigned threads, const std::function<bool(double)>& progress,
                    const std::function<double()>& fraction, std::atomic<bool>& stop, MakeScratch&& make_scratch,
                    Work&& work)
{
    std::atomic<size_t> next{0};
    auto worker = [&] {
        auto scratch = make_scratch();
        for (;;) {
            if (stop.load(std::memory_order_relaxed))
                return;
            const size_t item = next.fetch_add(1, std::memory_order_relaxed);
            if (item >= count)
                return;
            work(item, scratch);
        }
    };
    if (threads <= 1 && !progress) {
        worker();
        return !stop.load();
    }
    threads = parallel_items_threads(threads, count);
    std::mutex mutex;
    std::condition_variable ended;
    unsigned finished = 0;
    std::vector<std::thread> workers;
    workers.reserve(threads);
    for (unsigned t = 0; t < threads; ++t) {
        try {
            workers.emplace_back([&] {
                worker();
                const std::lock_guard lock(mutex);
                ++finished;
                ended.notify_all();
            });
        } catch (const std::system_error&) {
            break; // the system gives no more threads: the ones running take every item
        }
    }
    if (workers.empty()) { // not even one: the calling thread does the work
        worker();
        return !stop.load();
    }
    {
        const std::lock_guard lock(mutex);
        threads = unsigned(workers.size());
    }
    bool cancelled = false;
    try {
        std::unique_lock lock(mutex);
        while (finished < threads) {
            lock.unlock();
            if (progress && !cancelled && !progress(fraction())) {
                stop.store(true);
                cancelled = true;
            }
            lock.lock();
            ended.wait_for(lock, std::chrono::milliseconds(50), [&] { return finished == threads; });
        }
    } catch (...) {
        stop.store(true);
        for (std::thread& w : workers)
            w.join();
        throw;
    }
    for (std::thread& w : workers)
        w.join();
    return !cancelled;
}

} // namespace pvs
