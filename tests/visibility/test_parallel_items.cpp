// The sampled bakers' scheduler (visibility/parallel_items.h): every item done exactly once
// whatever the thread count asked, including counts no machine gives (a million: `bake --method
// raster --threads 1000000` aborted when thread creation threw outside any handler), and the
// count capped at the items and a few workers a core.
#include "visibility/parallel_items.h"

#include <gtest/gtest.h>

#include <numeric>

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

TEST(ParallelItems, EveryItemOnceWhateverTheThreadsAsked)
{
    for (unsigned threads : {0u, 1u, 2u, 3u, 64u, 1000000u})
        for (bool progress : {false, true}) {
            EXPECT_EQ(run_all(1000, threads, progress), 1000u) << threads << " threads";
            EXPECT_EQ(run_all(3, threads, progress), 3u) << threads << " threads, 3 items";
        }
}

TEST(ParallelItems, TheCountIsCappedAtTheItemsAndTheCores)
{
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    EXPECT_EQ(parallel_items_threads(1000000, 1u << 20), cores * kMaxThreadsPerCore);
    EXPECT_EQ(parallel_items_threads(1000000, 5), std::min(5u, cores * kMaxThreadsPerCore));
    EXPECT_EQ(parallel_items_threads(0, 100), 1u);
    EXPECT_EQ(parallel_items_threads(2, 100), std::min(2u, cores * kMaxThreadsPerCore));
    EXPECT_EQ(parallel_items_threads(3, 0), 1u);
}

} // namespace
} // namespace pvs
