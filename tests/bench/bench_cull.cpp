// Culling cost per frame on e1m1 with its baked PVS (lookup + row + frustum), over seeded
// cameras inside regions. Baseline in the same run: a client that finds the camera's region by
// a linear scan of all region boxes and keeps a std::vector<bool> PVS row per region, scanned
// whole every frame, with the same frustum test.
//
//   build/tests/bench/bench_cull --benchmark_min_time=0.5
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/culler.h"
#include "visibility/math/frustum.h"
#include "visibility/region_lookup.h"
#include "wld/zone_file.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>

namespace pvs {
namespace {

const Zone* e1m1()
{
    static const Zone* zone = [] {
        const auto path = test::find_shared_data("quake/e1m1.bsp");
        return path ? new Zone(load_zone(*path)) : nullptr;
    }();
    return zone;
}

// A walk: 4096 frames along straight legs between random in-region points, 8 units a frame,
// turning a little each frame.
const std::vector<Camera>& walk()
{
    static const std::vector<Camera> cameras = [] {
        std::vector<Camera> out;
        const Aabb box = e1m1()->bounds();
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y),
            uz(box.min.z, box.max.z);
        auto random_in_region = [&] {
            for (;;) {
                const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
                if (locate_point(e1m1()->tree, p).in_region())
                    return p;
            }
        };
        glm::vec3 a = random_in_region();
        float yaw = 0.0f;
        while (out.size() < 4096) {
            const glm::vec3 b = random_in_region();
            const int steps = std::max(1, int(glm::length(b - a) / 8.0f));
            for (int k = 0; k < steps && out.size() < 4096; ++k) {
                Camera c;
                c.position = a + (b - a) * (float(k) / float(steps));
                c.yaw_degrees = (yaw += 1.5f);
                out.push_back(c);
            }
            a = b;
        }
        return out;
    }();
    return cameras;
}

// Argument 0: CullOptions::time_stages (1 = the per-stage clock reads tools use, 0 = an
// engine's frame loop without them).
void BM_Cull_PvsFrustum(benchmark::State& state)
{
    if (!e1m1()) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    Culler culler(*e1m1(), &*e1m1()->baked_pvs);
    std::vector<uint32_t> visible;
    const auto& cameras = walk();
    size_t i = 0;
    uint64_t drawn = 0;
    for (auto _ : state) {
        drawn += culler.cull(cameras[i++ & 4095], {CullMode::PvsFrustum, false, state.range(0) != 0}, visible)
                     .regions_after_frustum;
        benchmark::DoNotOptimize(visible.data());
    }
    state.counters["regions_drawn"] = double(drawn) / double(state.iterations());
}
BENCHMARK(BM_Cull_PvsFrustum)->ArgName("time_stages")->Arg(1)->Arg(0);

// The distribution over the walk: each frame timed on its own (steady_clock, ~20 ns of overhead
// included), 10 passes over the 4096 frames; the counters are the median and the 99th percentile.
void BM_Cull_PvsFrustum_PerFrameDistribution(benchmark::State& state)
{
    if (!e1m1()) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    Culler culler(*e1m1(), &*e1m1()->baked_pvs);
    std::vector<uint32_t> visible;
    const auto& cameras = walk();
    std::vector<double> ns;
    for (auto _ : state) {
        ns.clear();
        for (int pass = 0; pass < 10; ++pass)
            for (const Camera& camera : cameras) {
                const auto start = std::chrono::steady_clock::now();
                culler.cull(camera, {CullMode::PvsFrustum, false, state.range(0) != 0}, visible);
                ns.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count());
            }
    }
    std::sort(ns.begin(), ns.end());
    state.counters["median_us"] = ns[ns.size() / 2] / 1000.0;
    state.counters["p99_us"] = ns[ns.size() * 99 / 100] / 1000.0;
    state.counters["max_us"] = ns.back() / 1000.0;
}
BENCHMARK(BM_Cull_PvsFrustum_PerFrameDistribution)
    ->ArgName("time_stages")
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_Cull_Baseline_LinearScanVectorBool(benchmark::State& state)
{
    if (!e1m1()) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    const Zone& zone = *e1m1();
    const uint32_t n = uint32_t(zone.region_count());
    std::vector<std::vector<bool>> rows(n, std::vector<bool>(n));
    std::vector<uint64_t> row(zone.baked_pvs->words_per_row());
    for (uint32_t r = 0; r < n; ++r) {
        zone.baked_pvs->decode_row(r, row);
        for (uint32_t c = 0; c < n; ++c)
            rows[r][c] = bits::test(row, c);
    }
    std::vector<uint32_t> visible;
    const auto& cameras = walk();
    size_t i = 0;
    for (auto _ : state) {
        const Camera& camera = cameras[i++ & 4095];
        int32_t region = -1;
        for (uint32_t r = 0; r < n && region < 0; ++r)
            if (zone.regions[r].bounds.contains(camera.position))
                region = int32_t(r);
        const Frustum frustum = Frustum::from_view_projection(camera.view_projection());
        visible.clear();
        for (uint32_t r = 0; r < n; ++r)
            if ((region < 0 || rows[uint32_t(region)][r]) && frustum.intersects(zone.regions[r].bounds))
                visible.push_back(r);
        benchmark::DoNotOptimize(visible.data());
    }
}
BENCHMARK(BM_Cull_Baseline_LinearScanVectorBool);

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
