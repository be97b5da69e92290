// Culling cost per frame on e1m1 with its baked PVS (lookup + row + frustum), over seeded
// cameras inside regions. Baseline in the same run: a client that finds the camera's region by
// a linear scan of all region boxes and keeps a std::vector<bool> PVS row per region, scanned
// whole every frame, with the same frustum test.
//
//   build/tests/bench/bench_cull --benchmark_min_time=0.5
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/culler.h"
#include "visibility/eval/camera_set.h"
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

const std::vector<Camera>& camera_set(int64_t set);

// The mean over the playable cameras (camera_set(1)), frame after frame: for profiles.
void BM_Cull_PvsFrustum_Playable(benchmark::State& state)
{
    if (!e1m1()) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    Culler culler(*e1m1(), &*e1m1()->baked_pvs);
    std::vector<uint32_t> visible;
    const auto& cameras = camera_set(1);
    size_t i = 0;
    double words = 0, blocks = 0, boxes = 0, candidates = 0, drawn = 0, lookup = 0, pvs = 0, frustum = 0;
    for (auto _ : state) {
        const CullStats s = culler.cull(cameras[i++ & 4095], {CullMode::PvsFrustum, false, state.range(0) != 0}, visible);
        words += s.work.row_words, blocks += s.work.blocks, boxes += s.work.boxes;
        candidates += s.regions_after_pvs, drawn += s.regions_after_frustum;
        lookup += s.lookup_us, pvs += s.pvs_us, frustum += s.frustum_us;
        benchmark::DoNotOptimize(visible.data());
    }
    const double n = double(state.iterations());
    state.counters["row_words"] = words / n;
    state.counters["blocks_tested"] = blocks / n;
    state.counters["boxes_tested"] = boxes / n;
    state.counters["candidates"] = candidates / n;
    state.counters["drawn"] = drawn / n;
    state.counters["lookup_us"] = lookup / n;
    state.counters["pvs_us"] = pvs / n;
    state.counters["frustum_us"] = frustum / n;
}
BENCHMARK(BM_Cull_PvsFrustum_Playable)->ArgName("time_stages")->Arg(1)->Arg(0);

// The per-frame distribution over the walk: each frame timed on its own (steady_clock, its
// ~30-70 ns included), 10 passes over the 4096 frames. Counters:
//  - median_us, p99_us, max_us: over all 40 960 timed frames, preemption by other jobs included;
//  - cost_median_us, cost_p99_us: per camera the fastest of its 10 passes (what the frame costs
//    when nothing interrupts it), then the median and the 99th percentile over the cameras. On a
//    loaded machine these are the stable figures; on a quiet one both agree.
// Camera sets of the distributions (the benchmarks' last argument):
//  0 "legs": walk() above. Its straight legs cross walls, so about a third of its frames have
//    the camera inside solid, where the culler's policy tests every region against the frustum.
//  1 "playable": `pvscope walk`'s camera set (random_cameras_in_regions: points in regions with
//    clearance, not in sky, random view directions; seed 2026), the frames a player can see.
const std::vector<Camera>& camera_set(int64_t set)
{
    static const std::vector<Camera> playable = [] {
        Camera lens;
        lens.aspect = 4.0f / 3.0f;
        return random_cameras_in_regions(*e1m1(), 4096, 2026, lens);
    }();
    return set == 0 ? walk() : playable;
}

template <typename CullFrame>
void per_frame_distribution(benchmark::State& state, int64_t set, CullFrame&& cull_frame)
{
    const auto& cameras = camera_set(set);
    std::vector<double> all, best(cameras.size());
    for (auto _ : state) {
        all.clear();
        std::fill(best.begin(), best.end(), 1e300);
        for (int pass = 0; pass < 10; ++pass)
            for (size_t i = 0; i < cameras.size(); ++i) {
                const auto start = std::chrono::steady_clock::now();
                cull_frame(cameras[i]);
                const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
                all.push_back(ns);
                best[i] = std::min(best[i], ns);
            }
    }
    std::sort(all.begin(), all.end());
    std::sort(best.begin(), best.end());
    state.counters["median_us"] = all[all.size() / 2] / 1000.0;
    state.counters["p99_us"] = all[all.size() * 99 / 100] / 1000.0;
    state.counters["max_us"] = all.back() / 1000.0;
    state.counters["cost_median_us"] = best[best.size() / 2] / 1000.0;
    state.counters["cost_p99_us"] = best[best.size() * 99 / 100] / 1000.0;
}

void BM_Cull_PvsFrustum_PerFrameDistribution(benchmark::State& state)
{
    if (!e1m1()) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    Culler culler(*e1m1(), &*e1m1()->baked_pvs);
    std::vector<uint32_t> visible;
    const CullOptions options{CullMode::PvsFrustum, false, state.range(0) != 0};
    per_frame_distribution(state, state.range(1), [&](const Camera& camera) {
        culler.cull(camera, options, visible);
        benchmark::DoNotOptimize(visible.data());
    });
}
BENCHMARK(BM_Cull_PvsFrustum_PerFrameDistribution)
    ->ArgNames({"time_stages", "cameras"})
    ->ArgsProduct({{1, 0}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// The baseline client: region by a linear scan of all region boxes (first hit), a
// std::vector<bool> PVS row per region scanned whole every frame, the scalar frustum test.
class BaselineCuller {
public:
    explicit BaselineCuller(const Zone& zone) : zone_(zone), rows_(zone.region_count())
    {
        const uint32_t n = uint32_t(zone.region_count());
        std::vector<uint64_t> row(zone.baked_pvs->words_per_row());
        for (uint32_t r = 0; r < n; ++r) {
            zone.baked_pvs->decode_row(r, row);
            rows_[r].resize(n);
            for (uint32_t c = 0; c < n; ++c)
                rows_[r][c] = bits::test(row, c);
        }
    }
    void cull(const Camera& camera, std::vector<uint32_t>& visible) const
    {
        const uint32_t n = uint32_t(zone_.region_count());
        int32_t region = -1;
        for (uint32_t r = 0; r < n && region < 0; ++r)
            if (zone_.regions[r].bounds.contains(camera.position))
                region = int32_t(r);
        const Frustum frustum = Frustum::from_view_projection(camera.view_projection());
        visible.clear();
        for (uint32_t r = 0; r < n; ++r)
            if ((region < 0 || rows_[uint32_t(region)][r]) && frustum.intersects(zone_.regions[r].bounds))
                visible.push_back(r);
    }

private:
    const Zone& zone_;
    std::vector<std::vector<bool>> rows_;
};

void BM_Cull_Baseline_LinearScanVectorBool(benchmark::State& state)
{
    if (!e1m1()) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    const BaselineCuller baseline(*e1m1());
    std::vector<uint32_t> visible;
    const auto& cameras = walk();
    size_t i = 0;
    for (auto _ : state) {
        baseline.cull(cameras[i++ & 4095], visible);
        benchmark::DoNotOptimize(visible.data());
    }
}
BENCHMARK(BM_Cull_Baseline_LinearScanVectorBool);

void BM_Cull_Baseline_PerFrameDistribution(benchmark::State& state)
{
    if (!e1m1()) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    const BaselineCuller baseline(*e1m1());
    std::vector<uint32_t> visible;
    per_frame_distribution(state, state.range(0), [&](const Camera& camera) {
        baseline.cull(camera, visible);
        benchmark::DoNotOptimize(visible.data());
    });
}
BENCHMARK(BM_Cull_Baseline_PerFrameDistribution)->ArgName("cameras")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
