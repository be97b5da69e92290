// Point -> region lookup, current-row fetch and load time on e1m1 (../shared/data/quake).
// Each figure has a baseline measured in the same run (the naive approach a client might
// take), so docs/performance.md reports ratios, not bare times that depend on the machine.
//
//   build/tests/bench/bench_lookup --benchmark_min_time=0.5
#include "tests/support/test_data.h"
#include "visibility/bit_row.h"
#include "visibility/codec/quake_rle.h"
#include "visibility/region_locator.h"
#include "visibility/region_lookup.h"
#include "wld/common/read_file.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/zone_file.h"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>
#include <random>

namespace pvs {
namespace {

const std::string& e1m1_path()
{
    static const std::string path = test::find_shared_data("quake/e1m1.bsp").value_or("");
    return path;
}

const Zone* e1m1()
{
    static const Zone* zone = e1m1_path().empty() ? nullptr : new Zone(load_zone(e1m1_path()));
    return zone;
}

bool skip_without_data(benchmark::State& state)
{
    if (e1m1())
        return false;
    state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
    return true;
}

// 4096 points that lie in regions, so both methods find an answer.
const std::vector<glm::vec3>& points_in_regions()
{
    static const std::vector<glm::vec3> points = [] {
        std::vector<glm::vec3> out;
        const Aabb box = e1m1()->bounds();
        std::mt19937 rng(42);
        std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y),
            uz(box.min.z, box.max.z);
        while (out.size() < 4096) {
            const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
            if (locate_point(e1m1()->tree, p).in_region())
                out.push_back(p);
        }
        return out;
    }();
    return points;
}

void BM_LocatePoint_BspWalk(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    const auto& points = points_in_regions();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(locate_point(e1m1()->tree, points[i++ & 4095]));
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_LocatePoint_BspWalk);

// A camera flying through the level: successive points 4 units apart along straight legs
// between random in-region points, as a frame-by-frame walk would ask.
const std::vector<glm::vec3>& camera_path()
{
    static const std::vector<glm::vec3> path = [] {
        std::vector<glm::vec3> out;
        const auto& targets = points_in_regions();
        for (size_t leg = 0; out.size() < 65536; ++leg) {
            const glm::vec3 a = targets[leg % targets.size()], b = targets[(leg + 1) % targets.size()];
            const int steps = std::max(1, int(glm::length(b - a) / 4.0f));
            for (int k = 0; k < steps && out.size() < 65536; ++k)
                out.push_back(a + (b - a) * (float(k) / float(steps)));
        }
        return out;
    }();
    return path;
}

void BM_LocatePoint_BspWalk_CameraPath(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    const auto& path = camera_path();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(locate_point(e1m1()->tree, path[i++ & 65535]));
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_LocatePoint_BspWalk_CameraPath);

const RegionLocator& e1m1_locator()
{
    static const RegionLocator locator(e1m1()->tree, e1m1()->bounds());
    return locator;
}

void BM_LocatePoint_GridLocator(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    const auto& points = points_in_regions();
    const RegionLocator& locator = e1m1_locator();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(locator.locate(points[i++ & 4095]));
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
    state.counters["grid_kib"] = double(locator.memory_bytes()) / 1024.0;
    state.counters["levels_skipped"] = locator.mean_skipped_depth();
}
BENCHMARK(BM_LocatePoint_GridLocator);

void BM_LocatePoint_GridLocator_CameraPath(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    const auto& path = camera_path();
    const RegionLocator& locator = e1m1_locator();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(locator.locate(path[i++ & 65535]));
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_LocatePoint_GridLocator_CameraPath);

// Baseline: the first region whose bounding box holds the point, by a linear scan.
void BM_LocatePoint_Baseline_LinearBoxScan(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    const auto& points = points_in_regions();
    const auto& regions = e1m1()->regions;
    size_t i = 0;
    for (auto _ : state) {
        const glm::vec3& p = points[i++ & 4095];
        int32_t found = -1;
        for (size_t r = 0; r < regions.size(); ++r)
            if (regions[r].bounds.contains(p)) {
                found = int32_t(r);
                break;
            }
        benchmark::DoNotOptimize(found);
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_LocatePoint_Baseline_LinearBoxScan);

// The row of a region the camera just entered: every iteration is a region change.
void row_fetch(benchmark::State& state, Pvs::StoragePolicy policy)
{
    if (skip_without_data(state))
        return;
    const Pvs& baked = *e1m1()->baked_pvs;
    const Pvs pvs = Pvs::build(baked.region_count(), [&](uint32_t r, std::span<uint64_t> row) {
        baked.decode_row(r, row);
        return true;
    }, policy);
    PvsRowCursor cursor(pvs);
    uint32_t r = 0;
    for (auto _ : state) {
        r = (r + 617) % pvs.region_count(); // a stride that never repeats the previous region
        const auto row = cursor.row(r);
        benchmark::DoNotOptimize(row.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
}
void BM_RowFetch_Dense(benchmark::State& state) { row_fetch(state, Pvs::StoragePolicy::Dense); }
void BM_RowFetch_Compressed(benchmark::State& state) { row_fetch(state, Pvs::StoragePolicy::Compressed); }
BENCHMARK(BM_RowFetch_Dense);
BENCHMARK(BM_RowFetch_Compressed);

// Baseline: decode the file's RLE row into a std::vector<bool> of the whole zone, as a client
// that keeps no decoded rows does on every region change.
void BM_RowFetch_Baseline_VectorBool(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    const Pvs& baked = *e1m1()->baked_pvs;
    const uint32_t n = baked.region_count();
    std::vector<std::vector<uint8_t>> rle(n);
    std::vector<uint64_t> row(baked.words_per_row());
    for (uint32_t r = 0; r < n; ++r) {
        baked.decode_row(r, row);
        encode_quake_rle(row, n, rle[r]);
    }
    uint32_t r = 0;
    for (auto _ : state) {
        r = (r + 617) % n;
        std::vector<bool> visible(n, false);
        size_t bit = 0;
        for (size_t k = 0; k < rle[r].size() && bit < n; ++k) {
            const uint8_t b = rle[r][k];
            if (b == 0) {
                bit += 8 * size_t(rle[r][++k]);
                continue;
            }
            for (int j = 0; j < 8 && bit < n; ++j, ++bit)
                visible[bit] = (b >> j) & 1;
        }
        benchmark::DoNotOptimize(visible);
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_RowFetch_Baseline_VectorBool);

void BM_Load_E1m1(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    const std::vector<uint8_t> bytes = read_whole_file(e1m1_path());
    for (auto _ : state) {
        const Zone zone = quake::load_bsp29(bytes, e1m1_path());
        benchmark::DoNotOptimize(zone.regions.data());
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes.size()));
}
BENCHMARK(BM_Load_E1m1)->Unit(benchmark::kMillisecond);

// Baseline: reading the file into memory, the floor any loader starts from.
void BM_Load_Baseline_ReadFile(benchmark::State& state)
{
    if (skip_without_data(state))
        return;
    for (auto _ : state) {
        const std::vector<uint8_t> bytes = read_whole_file(e1m1_path());
        benchmark::DoNotOptimize(bytes.data());
    }
}
BENCHMARK(BM_Load_Baseline_ReadFile)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
