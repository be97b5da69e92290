// Loading EverQuest zones: e1m1 converted to .s3d, and generated zones of 50, 500 and 5000 rooms
// written as .s3d, each loaded from memory. Counters: the archive's size, the loaded model's
// memory (Zone::memory_bytes), their ratio, and the peak of heap bytes in use during one load
// above what was in use before it (counted by replacing the global operator new / delete in
// this program). Baseline in the same run: parsing e1m1 as the Quake BSP it was converted from.
//
//   build/tests/bench/bench_eq_load --benchmark_min_time=1
#include "tests/support/test_data.h"
#include "visibility/geometry/split_faces.h"
#include "wld/common/read_file.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/eq/eq_zone_writer.h"
#include "gen/generate_zone.h"
#include "wld/quake/bsp29_reader.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

// ---- Heap accounting: bytes in use now and the most since the last reset ----

namespace {
std::atomic<size_t> g_heap_in_use{0};
std::atomic<size_t> g_heap_peak{0};

void* counted_alloc(size_t size)
{
    void* p = std::malloc(size ? size : 1);
    if (!p)
        throw std::bad_alloc();
    const size_t now = g_heap_in_use += malloc_usable_size(p);
    size_t peak = g_heap_peak.load();
    while (now > peak && !g_heap_peak.compare_exchange_weak(peak, now)) {
    }
    return p;
}

void counted_free(void* p) noexcept
{
    if (!p)
        return;
    g_heap_in_use -= malloc_usable_size(p);
    std::free(p);
}
} // namespace

void* operator new(size_t size) { return counted_alloc(size); }
void* operator new[](size_t size) { return counted_alloc(size); }
void operator delete(void* p) noexcept { counted_free(p); }
void operator delete[](void* p) noexcept { counted_free(p); }
void operator delete(void* p, size_t) noexcept { counted_free(p); }
void operator delete[](void* p, size_t) noexcept { counted_free(p); }

namespace pvs {
namespace {

void load_archive(benchmark::State& state, const std::vector<uint8_t>& archive)
{
    size_t model_bytes = 0, peak_bytes = 0;
    for (auto _ : state) {
        const size_t before = g_heap_in_use.load();
        g_heap_peak = before;
        const Zone zone = eq::load_eq_zone(archive, "bench.s3d");
        model_bytes = zone.memory_bytes();
        peak_bytes = g_heap_peak.load() - before;
        benchmark::DoNotOptimize(zone.regions.data());
    }
    state.counters["archive_kib"] = double(archive.size()) / 1024.0;
    state.counters["model_kib"] = double(model_bytes) / 1024.0;
    state.counters["model_per_archive"] = double(model_bytes) / double(archive.size());
    state.counters["peak_load_kib"] = double(peak_bytes) / 1024.0;
}

void BM_LoadS3d_E1m1Converted(benchmark::State& state)
{
    const Zone* quake = test::shared_zone("quake/e1m1.bsp");
    if (!quake) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    static const std::vector<uint8_t> archive = eq::write_eq_zone(clip_faces_to_region_cells(*quake), "e1m1");
    load_archive(state, archive);
}
BENCHMARK(BM_LoadS3d_E1m1Converted)->Unit(benchmark::kMillisecond);

void BM_LoadBsp_Baseline_E1m1(benchmark::State& state)
{
    const auto path = test::find_shared_data("quake/e1m1.bsp");
    if (!path) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    const std::vector<uint8_t> bytes = read_whole_file(*path);
    for (auto _ : state) {
        const Zone zone = quake::load_bsp29(bytes, *path);
        benchmark::DoNotOptimize(zone.regions.data());
    }
}
BENCHMARK(BM_LoadBsp_Baseline_E1m1)->Unit(benchmark::kMillisecond);

void BM_LoadS3d_Generated(benchmark::State& state)
{
    const int rooms = int(state.range(0));
    const Zone generated = gen::generate_zone({.rooms = rooms, .seed = 1, .cell_size = 32.0f});
    const std::vector<uint8_t> archive = eq::write_eq_zone(generated, "gen");
    load_archive(state, archive);
    state.counters["rooms"] = rooms;
}
BENCHMARK(BM_LoadS3d_Generated)->Arg(50)->Arg(500)->Arg(5000)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
