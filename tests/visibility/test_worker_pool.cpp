// The one worker pool (visibility/worker_pool.h): every item done exactly once whatever the
// thread count asked, including counts no machine gives (a million: `bake --method raster
// --threads 1000000` once aborted when thread creation threw outside any handler); the count
// capped at the items and a few workers a core; exceptions from a worker or from progress carried
// back to the caller after every thread joined; progress returning false cancels.
#include "visibility/worker_pool.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>
#include <vector>

namespace pvs {
namespace {

size_t run_all(size_t count, unsigned threads, bool with_progress)
{
    std::vector<std::atomic<int>> done(count);
    std::atomic<bool> stop{false};
    const std::function<bool(double)> progress = with_progress ? std::function<bool(double)>([](double) { return true; })
                                                               : std::function<bool(double)>();
    const bool finished = parallel_items(
        count, threads, progress, [] { return 0.0; }, stop, [] { return 0; },
        [&](size_t item, int&) { done[item].fetch_add(1); });
    EXPECT_TRUE(finished);
    size_t once = 0;
    for (const auto& d : done)
        once += d.load() == 1;
    return once;
}

TEST(WorkerPool, EveryItemOnceWhateverTheThreadsAsked)
{
    for (unsigned threads : {0u, 1u, 2u, 3u, 64u, 1000000u})
        for (bool progress : {false, true}) {
            EXPECT_EQ(run_all(1000, threads, progress), 1000u) << threads << " threads";
            EXPECT_EQ(run_all(3, threads, progress), 3u) << threads << " threads, 3 items";
        }
}

TEST(WorkerPool, TheCountIsCappedAtTheItemsAndTheCores)
{
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    EXPECT_EQ(thread_count(1000000, 1u << 20), cores * kMaxThreadsPerCore);
    EXPECT_EQ(thread_count(1000000, 5), std::min(5u, cores * kMaxThreadsPerCore));
    EXPECT_EQ(thread_count(0, 100), std::min(100u, cores)) << "0 asks for every hardware thread";
    EXPECT_EQ(thread_count(0, 1), 1u);
    EXPECT_EQ(thread_count(2, 100), std::min(2u, cores * kMaxThreadsPerCore));
    EXPECT_EQ(thread_count(3, 0), 1u);
}

TEST(WorkerPool, WorkerExceptionReachesTheCallerAndStopsTheOthers)
{
    for (unsigned threads : {1u, 3u}) {
        std::atomic<bool> stop{false};
        std::atomic<size_t> after_stop{0};
        EXPECT_THROW(parallel_items(
                         100000, threads, [](double) { return true; }, [] { return 0.0; }, stop, [] { return 0; },
                         [&](size_t item, int&) {
                             if (item == 10)
                                 throw std::runtime_error("item 10 is bad");
                             if (stop.load())
                                 after_stop.fetch_add(1);
                         }),
                     std::runtime_error)
            << threads << " threads";
        EXPECT_TRUE(stop.load()) << "the failure stopped the other workers";
        EXPECT_LE(after_stop.load(), threads) << "at most the item each worker was on";
    }
}

TEST(WorkerPool, ProgressExceptionReachesTheCaller)
{
    std::atomic<bool> stop{false};
    EXPECT_THROW(run_workers(
                     2,
                     [&](unsigned) {
                         while (!stop.load())
                             std::this_thread::yield();
                     },
                     stop, [](double) -> bool { throw std::logic_error("progress failed"); }, [] { return 0.5; }),
                 std::logic_error);
}

TEST(WorkerPool, ProgressFalseCancels)
{
    std::atomic<bool> stop{false};
    double seen = -1;
    const bool kept_going = run_workers(
        2,
        [&](unsigned) {
            while (!stop.load())
                std::this_thread::yield();
        },
        stop,
        [&](double f) {
            seen = f;
            return false;
        },
        [] { return 0.25; });
    EXPECT_FALSE(kept_going);
    EXPECT_TRUE(stop.load());
    EXPECT_EQ(seen, 0.25);
}

TEST(WorkerPool, AStopSetBeforeTheCallCancelsTheItems)
{
    std::atomic<bool> stop{true};
    std::atomic<size_t> ran{0};
    EXPECT_FALSE(parallel_items(
        10, 1, {}, [] { return 0.0; }, stop, [] { return 0; }, [&](size_t, int&) { ran.fetch_add(1); }));
    EXPECT_EQ(ran.load(), 0u);
}

} // namespace
} // namespace pvs
