// Thread scheduling of the portal-vis baker (vis_threads.h).
#include "visibility/portal/vis_threads.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace pvs::portal_vis {

unsigned thread_count(unsigned requested, size_t items)
{
    unsigned n = requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
    n = std::min(n, 256u);
    if (items < n)
        n = unsigned(std::max<size_t>(items, 1));
    return n;
}

void run_parallel(unsigned threads, const std::function<void(unsigned)>& worker, std::atomic<bool>& cancel,
                  std::atomic<bool>& user_cancel, const std::function<bool(double)>& progress,
                  const std::function<double()>& fraction)
{
    std::exception_ptr error;
    std::mutex mutex;
    std::condition_variable finished_cv;
    unsigned finished = 0;
    auto body = [&](unsigned t) {
        try {
            worker(t);
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!error)
                error = std::current_exception();
            cancel.store(true);
        }
        {
            std::lock_guard lock(mutex);
            ++finished;
        }
        finished_cv.notify_all();
    };
    if (threads == 1 && !progress) {
        body(0);
    } else {
        std::vector<std::thread> pool;
        pool.reserve(threads);
        try {
            for (unsigned t = 0; t < threads; ++t)
                pool.emplace_back(body, t);
        } catch (...) {
            cancel.store(true);
            for (std::thread& th : pool)
                th.join();
            throw;
        }
        std::unique_lock lock(mutex);
        while (finished < pool.size()) {
            finished_cv.wait_for(lock, std::chrono::milliseconds(50), [&] { return finished == pool.size(); });
            if (finished == pool.size() || !progress || cancel.load())
                continue;
            lock.unlock();
            bool keep_going = false;
            try {
                keep_going = progress(fraction());
            } catch (...) {
                std::lock_guard error_lock(mutex);
                if (!error)
                    error = std::current_exception();
            }
            if (!keep_going) {
                user_cancel.store(true);
                cancel.store(true);
            }
            lock.lock();
        }
        lock.unlock();
        for (std::thread& th : pool)
            th.join();
    }
    if (error)
        std::rethrow_exception(error);
}

} // namespace pvs::portal_vis
