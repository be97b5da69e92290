// The worker pool (worker_pool.h).
#include "visibility/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace pvs {

unsigned thread_count(unsigned requested, size_t items)
{
    const size_t cores = std::max(1u, std::thread::hardware_concurrency());
    const size_t wanted = requested == 0 ? cores : requested;
    return unsigned(std::max<size_t>(1, std::min({wanted, cores * kMaxThreadsPerCore, items})));
}

namespace {

// What the workers and the calling thread share: the first error and the count of workers done.
struct Run {
    std::mutex mutex;
    std::condition_variable ended;
    unsigned finished = 0;
    std::exception_ptr error;

    void fail(std::atomic<bool>& stop)
    {
        const std::lock_guard lock(mutex);
        if (!error)
            error = std::current_exception();
        stop.store(true);
    }
};

// Calls progress until every started worker has finished; false when progress asked to stop.
bool watch(Run& run, unsigned started, std::atomic<bool>& stop, const std::function<bool(double)>& progress,
           const std::function<double()>& fraction)
{
    bool keep_going = true;
    std::unique_lock lock(run.mutex);
    while (run.finished < started) {
        if (progress && !stop.load()) {
            lock.unlock();
            try {
                if (!progress(fraction())) {
                    keep_going = false;
                    stop.store(true);
                }
            } catch (...) {
                run.fail(stop);
            }
            lock.lock();
        }
        run.ended.wait_for(lock, std::chrono::milliseconds(50), [&] { return run.finished == started; });
    }
    return keep_going;
}

} // namespace

bool run_workers(unsigned threads, const std::function<void(unsigned)>& worker, std::atomic<bool>& stop,
                 const std::function<bool(double)>& progress, const std::function<double()>& fraction)
{
    Run run;
    auto body = [&](unsigned t) {
        try {
            worker(t);
        } catch (...) {
            run.fail(stop);
        }
        {
            const std::lock_guard lock(run.mutex);
            ++run.finished;
        }
        run.ended.notify_all();
    };
    bool keep_going = true;
    if (threads <= 1 && !progress) {
        body(0);
    } else {
        std::vector<std::thread> pool;
        pool.reserve(std::max(threads, 1u));
        for (unsigned t = 0; t < std::max(threads, 1u); ++t) {
            try {
                pool.emplace_back(body, t);
            } catch (const std::system_error&) {
                break; // the system gives no more threads: the ones running take every item
            }
        }
        if (pool.empty())
            body(0); // not even one: the calling thread does the work
        else
            keep_going = watch(run, unsigned(pool.size()), stop, progress, fraction);
        for (std::thread& th : pool)
            th.join();
    }
    if (run.error)
        std::rethrow_exception(run.error);
    return keep_going;
}

} // namespace pvs
