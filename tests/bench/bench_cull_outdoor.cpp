// Culling cost per frame on the default outdoor zone (`pvscope gen --outdoor`: 33 626 regions,
// terrain PVS, about 27 000 regions a row), over the 300 seeded cameras `pvscope walk` uses.
// Baseline in the same run: the same camera's region (tree walk) and row, then every region of
// the row tested on its own with the same packed box test (FrustumBoxes::intersects): the
// culler's per-region stage, which the block stage replaces on frames of kBlocksFrom candidates.
//
// "warm": the frames follow each other with nothing in between (the zone's data stays in
// cache). "cold": before each frame 64 MiB are written, as a render between two frames does in
// `pvscope walk`; only the cull is timed (manual time). An iteration is the 300 frames; the
// counters mean_us and median_us are per frame.
//
// A third case reads, cold or warm, only the boxes any exact box-hierarchy cull must look at one by
// one (BoundaryBoxReads): the memory floor under the culler's figure; with reads:2, also the
// camera's row decoded and the answer written (the regions to draw), which every culler does too.
//
//   build/tests/bench/bench_cull_outdoor --benchmark_repetitions=3
#include "visibility/bit_row.h"
#include "visibility/culler.h"
#include "visibility/eval/camera_set.h"
#include "visibility/math/frustum_boxes.h"
#include "visibility/region_locator.h"
#include "gen/generate_outdoor_zone.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
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

// Every region's box, by id.
std::vector<Aabb> region_boxes(const Zone& zone)
{
    std::vector<Aabb> out;
    for (const Region& r : zone.regions)
        out.push_back(r.bounds);
    return out;
}

// Calls visit(r, planes) for each region r of the camera's PVS row (none when the camera is in no
// region), with the frustum's six planes prepared; `row` is scratch of a row's words.
template <class Visit>
void for_each_row_region(const Zone& zone, const RegionLocator& locator, const Camera& camera,
                         std::vector<uint64_t>& row, Visit&& visit)
{
    const int32_t region = locator.locate(camera.position).region;
    if (region < 0)
        return;
    zone.baked_pvs->decode_row(uint32_t(region), row);
    const auto planes =
        FrustumBoxes::prepare(Frustum::from_view_projection(camera.view_projection()), FrustumBoxes::Planes::All);
    bits::for_each_set(std::span<const uint64_t>(row), [&](size_t r) { visit(uint32_t(r), planes); });
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
        visible.clear();
        for_each_row_region(zone_, locator_, camera, row_, [&](uint32_t r, const FrustumBoxes::PlaneGroups& planes) {
            if (boxes_.intersects(r, planes))
                visible.push_back(r);
        });
    }

private:
    const Zone& zone_;
    RegionLocator locator_;
    FrustumBoxes boxes_;
    std::vector<uint64_t> row_;
};

// Runs `cull` over all the cameras per iteration; argument 0: 1 = cold (caches evicted before
// each frame). The time reported is that of the 300 frames; the counters are per frame: mean_us,
// and median_us (the walk's statistic), each averaged over the iterations.
template <class Cull>
void run_frames(benchmark::State& state, Cull&& cull)
{
    const bool cold = state.range(0) != 0;
    std::vector<double> frame_us(cameras().size());
    double median_sum = 0.0, total_sum = 0.0;
    for (auto _ : state) {
        double total = 0.0;
        for (size_t i = 0; i < cameras().size(); ++i) {
            if (cold)
                evict_caches();
            const auto start = std::chrono::steady_clock::now();
            cull(i);
            frame_us[i] = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
            total += frame_us[i];
        }
        state.SetIterationTime(total * 1e-6);
        total_sum += total;
        std::nth_element(frame_us.begin(), frame_us.begin() + frame_us.size() / 2, frame_us.end());
        median_sum += frame_us[frame_us.size() / 2];
    }
    state.counters["mean_us"] = total_sum / double(state.iterations() * cameras().size());
    state.counters["median_us"] = median_sum / double(state.iterations());
}

void BM_CullOutdoor_Culler(benchmark::State& state)
{
    Culler culler(outdoor(), &*outdoor().baked_pvs);
    std::vector<uint32_t> visible;
    uint64_t drawn = 0;
    run_frames(state, [&](size_t i) {
        drawn += culler.cull(cameras()[i], {CullMode::PvsFrustum, false, false}, visible).regions_after_frustum;
        benchmark::DoNotOptimize(visible.data());
    });
    state.counters["regions_drawn"] = double(drawn) / double(state.iterations() * cameras().size());
}
BENCHMARK(BM_CullOutdoor_Culler)->ArgName("cold")->Arg(0)->Arg(1)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

void BM_CullOutdoor_Baseline_PerRegion(benchmark::State& state)
{
    PerRegionCuller culler(outdoor());
    std::vector<uint32_t> visible;
    uint64_t drawn = 0;
    run_frames(state, [&](size_t i) {
        culler.cull(cameras()[i], visible);
        drawn += visible.size();
        benchmark::DoNotOptimize(visible.data());
    });
    state.counters["regions_drawn"] = double(drawn) / double(state.iterations() * cameras().size());
}
BENCHMARK(BM_CullOutdoor_Baseline_PerRegion)->ArgName("cold")->Arg(0)->Arg(1)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

// A floor, not a culler: only reading the boxes no box hierarchy can settle. A row region whose
// box is Partial for the frustum (crossing a plane's boundary, outside none) has every enclosing
// box Partial too, so an exact cull must look at that box itself. This reads, per camera, just
// those boxes (in region order) and tests nothing: what the memory alone costs a frame. Two
// layouts: the culler's (one float array per coordinate, as FrustumBoxes keeps them) and the
// densest a box can be (six bytes, each coordinate quantized over the zone: a quarter of the
// bytes of a float box).
class BoundaryBoxReads {
public:
    explicit BoundaryBoxReads(const Zone& zone) : coords_(6)
    {
        const Aabb world = zone.bounds();
        for (const Region& r : zone.regions) {
            std::array<uint8_t, 6>& q = bytes_.emplace_back();
            for (int k = 0; k < 3; ++k) {
                coords_[k].push_back(r.bounds.min[k]);
                coords_[3 + k].push_back(r.bounds.max[k]);
                const float extent = std::max(world.max[k] - world.min[k], 1.0f);
                q[k] = uint8_t(std::clamp(255.0f * (r.bounds.min[k] - world.min[k]) / extent, 0.0f, 255.0f));
                q[3 + k] = uint8_t(std::clamp(255.0f * (r.bounds.max[k] - world.min[k]) / extent, 0.0f, 255.0f));
            }
        }
        const FrustumBoxes packed(region_boxes(zone));
        RegionLocator locator(zone.tree, zone.bounds());
        std::vector<uint64_t> row(zone.baked_pvs->words_per_row());
        Culler culler(zone, &*zone.baked_pvs);
        for (const Camera& camera : cameras()) {
            answers_.emplace_back();
            culler.cull(camera, {CullMode::PvsFrustum, false, false}, answers_.back());
            region_.push_back(locator.locate(camera.position).region);
            std::vector<uint32_t>& ids = partial_.emplace_back();
            for_each_row_region(zone, locator, camera, row, [&](uint32_t r, const FrustumBoxes::PlaneGroups& planes) {
                if (packed.classify(r, planes) == FrustumBoxes::Side::Partial)
                    ids.push_back(r);
            });
        }
    }
    // The sum of the boxes' coordinates for camera i (only so that the reads happen).
    float read_floats(size_t camera) const
    {
        float sum = 0.0f;
        for (const uint32_t r : partial_[camera])
            for (const std::vector<float>& c : coords_)
                sum += c[r];
        return sum;
    }
    unsigned read_bytes(size_t camera) const
    {
        unsigned sum = 0;
        for (const uint32_t r : partial_[camera])
            for (const uint8_t b : bytes_[r])
                sum += b;
        return sum;
    }
    size_t count(size_t camera) const { return partial_[camera].size(); }
    // What any culler must do besides: decode the camera's row and write its answer (the regions
    // to draw, as the culler's `visible`), with the boundary boxes read as floats.
    float read_row_boxes_and_write(size_t camera, const Pvs& pvs, std::vector<uint64_t>& row,
                                   std::vector<uint32_t>& out) const
    {
        if (region_[camera] >= 0)
            pvs.decode_row(uint32_t(region_[camera]), row);
        out.assign(answers_[camera].begin(), answers_[camera].end());
        return read_floats(camera);
    }

private:
    std::vector<std::vector<uint32_t>> answers_; // per camera: the culler's answer
    std::vector<int32_t> region_;               // per camera: its region
    std::vector<std::vector<float>> coords_;
    std::vector<std::array<uint8_t, 6>> bytes_;
    std::vector<std::vector<uint32_t>> partial_; // per camera, in region order
};

void BM_CullOutdoor_Floor_ReadBoundaryBoxes(benchmark::State& state)
{
    static const BoundaryBoxReads reads(outdoor());
    uint64_t boxes = 0;
    const int what = int(state.range(1)); // 0: floats, 1: bytes, 2: floats + the row + the answer
    std::vector<uint64_t> row(outdoor().baked_pvs->words_per_row());
    std::vector<uint32_t> out;
    run_frames(state, [&](size_t i) {
        if (what == 1)
            benchmark::DoNotOptimize(reads.read_bytes(i));
        else if (what == 0)
            benchmark::DoNotOptimize(reads.read_floats(i));
        else
            benchmark::DoNotOptimize(reads.read_row_boxes_and_write(i, *outdoor().baked_pvs, row, out));
        boxes += reads.count(i);
    });
    state.counters["boundary_boxes"] = double(boxes) / double(state.iterations() * cameras().size());
}
BENCHMARK(BM_CullOutdoor_Floor_ReadBoundaryBoxes)
    ->ArgNames({"cold", "reads"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
