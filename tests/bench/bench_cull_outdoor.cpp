// Culling cost per frame on the default outdoor zone (`pvscope gen --outdoor`: 33 626 regions,
// terrain PVS, about 27 000 regions a row), over the 300 seeded cameras `pvscope walk` uses.
// Baseline in the same run: the same camera's region (tree walk) and row, then every region of
// the row tested on its own with the same packed box test (FrustumBoxes::intersects): the
// culler's per-region stage, which the block stage replaces on frames of kBlocksFrom candidates.
//
// "warm": the frames follow each other with nothing in between (the zone's data stays in
// cache). "cold": before each frame 64 MiB are written, as a render between two frames does in
// `pvscope walk`; only the cull is timed (manual time).
//
//   build/tests/bench/bench_cull_outdoor --benchmark_min_time=0.5
#include "visibility/bit_row.h"
#include "visibility/culler.h"
#include "visibility/eval/camera_set.h"
#include "visibility/math/frustum_boxes.h"
#include "visibility/region_locator.h"
#include "wld/gen/generate_outdoor_zone.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <vector>

namespace pvs {
namespace {

const Zone& outdoor()
{
    static const Zone zone = [] {
        gen::OutdoorParams params;
        params.bake = true;
        return gen::generate_outdoor_zone(params);
    }();
    return zone;
}

// As `pvscope walk --cameras 300` (seed 1, 70 degrees, 320x240).
const std::vector<Camera>& cameras()
{
    static const std::vector<Camera> out = [] {
        Camera lens;
        lens.fov_y_degrees = 70.0f;
        lens.aspect = 320.0f / 240.0f;
        return random_cameras_in_regions(outdoor(), 300, 1, lens);
    }();
    return out;
}

// Writes a buffer bigger than the last-level cache.
void evict_caches()
{
    static std::vector<char> buffer(64u << 20);
    for (size_t i = 0; i < buffer.size(); i += 64)
        buffer[i] = char(buffer[i] + 1);
    benchmark::DoNotOptimize(buffer.data());
}

// The per-region stage: the row's regions tested one by one.
class PerRegionCuller {
public:
    explicit PerRegionCuller(const Zone& zone)
        : zone_(zone), locator_(zone.tree, zone.bounds()), boxes_(region_boxes(zone)), row_(zone.baked_pvs->words_per_row())
    {
    }
    void cull(const Camera& camera, std::vector<uint32_t>& visible)
    {
        const int32_t region = locator_.locate(camera.position).region;
        visible.clear();
        if (region < 0)
            return;
        zone_.baked_pvs->decode_row(uint32_t(region), row_);
        const auto planes = FrustumBoxes::prepare(Frustum::from_view_projection(camera.view_projection()),
                                                  FrustumBoxes::Planes::All);
        bits::for_each_set(std::span<const uint64_t>(row_), [&](size_t r) {
            if (boxes_.intersects(uint32_t(r), planes))
                visible.push_back(uint32_t(r));
        });
    }

private:
    static std::vector<Aabb> region_boxes(const Zone& zone)
    {
        std::vector<Aabb> out;
        for (const Region& r : zone.regions)
            out.push_back(r.bounds);
        return out;
    }
    const Zone& zone_;
    RegionLocator locator_;
    FrustumBoxes boxes_;
    std::vector<uint64_t> row_;
};

// Runs `cull` over the cameras; argument 0: 1 = cold (caches evicted before each frame).
template <class Cull>
void run_frames(benchmark::State& state, Cull&& cull)
{
    const bool cold = state.range(0) != 0;
    size_t i = 0;
    for (auto _ : state) {
        const Camera& camera = cameras()[i++ % cameras().size()];
        if (cold)
            evict_caches();
        const auto start = std::chrono::steady_clock::now();
        cull(camera);
        state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
}

void BM_CullOutdoor_Culler(benchmark::State& state)
{
    Culler culler(outdoor(), &*outdoor().baked_pvs);
    std::vector<uint32_t> visible;
    uint64_t drawn = 0;
    run_frames(state, [&](const Camera& camera) {
        drawn += culler.cull(camera, {CullMode::PvsFrustum, false, false}, visible).regions_after_frustum;
        benchmark::DoNotOptimize(visible.data());
    });
    state.counters["regions_drawn"] = double(drawn) / double(state.iterations());
}
BENCHMARK(BM_CullOutdoor_Culler)->ArgName("cold")->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMicrosecond);

void BM_CullOutdoor_Baseline_PerRegion(benchmark::State& state)
{
    PerRegionCuller culler(outdoor());
    std::vector<uint32_t> visible;
    uint64_t drawn = 0;
    run_frames(state, [&](const Camera& camera) {
        culler.cull(camera, visible);
        drawn += visible.size();
        benchmark::DoNotOptimize(visible.data());
    });
    state.counters["regions_drawn"] = double(drawn) / double(state.iterations());
}
BENCHMARK(BM_CullOutdoor_Baseline_PerRegion)->ArgName("cold")->Arg(0)->Arg(1)->UseManualTime()->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
