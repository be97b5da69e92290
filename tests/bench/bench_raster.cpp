// One point's six 90-degree views of the HateEngine E1M1 level (15 006 triangles), the unit of
// work of the raster baker (visibility/raster/): pvscope's CPU rasteriser (CubeRaster::render)
// against the baseline measured in the same run, Embree primary rays through the same pixel
// centres (MeshTracer::first_hit, one ray at a time; and MeshTracer::first_hits, packets of 8
// rays), at 32, 64 and 128 pixels a side. Points:
// the centres of E1M1.hepvs's cells that are in open space, every seventh cell (50 of them).
// The time is wall time for all the points (divide by the counter `points` for one point); the
// CPU paths run on one thread, the GPU's driver on its own (llvmpipe: one per core); counter
// faces_seen: faces with a pixel, summed over the points (within a few percent of each other:
// the same rays, the rasteriser deciding pixel centres by edge functions); samples_per_s: pixel
// samples (points x 6 x resolution^2) a second, the figure that scales to HateEngine's default
// density (513 points a cell at 512^2: 2.7e12 samples on E1M1).
//
// BM_GpuCube is the same work on the GPU path (gpu_cube.h: all 50 points in one render call, the
// IDs reduced on the GPU), on whatever device EGL finds (llvmpipe on a machine without a GPU;
// skipped with a message when none answers), up to 512 pixels a side.
//
//   build/tests/bench/bench_raster --benchmark_counters_tabular=true
#include "tests/support/test_data.h"
#include "visibility/raster/cube_raster.h"
#include "visibility/raster/gl_headless.h"
#include "visibility/raster/gpu_cube.h"
#include "visibility/raster/raster_vis.h"
#include "visibility/raster/ray_cube.h"
#include "visibility/reference/mesh_tracer.h"
#include "wld/zone_file.h"

#include <benchmark/benchmark.h>

#include <limits>
#include <memory>
#include <span>

namespace pvs {
namespace {

struct Level {
    Zone zone;
    std::unique_ptr<MeshTracer> tracer;
    std::vector<glm::vec3> points;
};

const Level* level()
{
    static const std::unique_ptr<Level> loaded = []() -> std::unique_ptr<Level> {
        const auto path = test::find_shared_data("hateengine/E1M1.obj");
        if (!path)
            return nullptr;
        auto l = std::make_unique<Level>();
        l->zone = load_zone(*path);
        l->tracer = std::make_unique<MeshTracer>(l->zone);
        const ViewGrid& grid = *l->zone.view_grid;
        for (uint32_t c = 0; c < grid.cell_count() && l->points.size() < 50; c += 7) {
            const glm::vec3 g = grid_cell_points(grid, c, 0.0f)[0] * grid.grid_size;
            const glm::vec3 p(g.x, -g.z, g.y);
            if (l->tracer->in_open_space(p))
                l->points.push_back(p);
        }
        return l;
    }();
    return loaded.get();
}

void count_samples(benchmark::State& state, size_t points, uint64_t faces)
{
    const double r = double(state.range(0));
    state.counters["points"] = double(points);
    state.counters["faces_seen"] = double(faces);
    state.counters["samples_per_s"] =
        benchmark::Counter(double(points) * 6.0 * r * r * double(state.iterations()), benchmark::Counter::kIsRate);
}

// Times `renderer.render(point, seen)` over the level's points; counts the faces seen.
template <class Renderer>
void time_views(benchmark::State& state, const Level& l, Renderer& renderer)
{
    std::vector<uint8_t> seen(l.zone.mesh.faces.size());
    uint64_t faces = 0;
    for (auto _ : state) {
        faces = 0;
        for (const glm::vec3& p : l.points) {
            std::fill(seen.begin(), seen.end(), 0);
            renderer.render(p, seen);
            for (uint8_t s : seen)
                faces += s;
        }
    }
    count_samples(state, l.points.size(), faces);
}

void BM_CubeRaster(benchmark::State& state)
{
    const Level* l = level();
    if (!l) {
        state.SkipWithError("needs ../shared/data/hateengine/E1M1.obj");
        return;
    }
    CubeRaster raster(l->zone, {uint32_t(state.range(0)), true, 0.05f});
    time_views(state, *l, raster);
}

void BM_EmbreePrimaryRays(benchmark::State& state)
{
    const Level* l = level();
    if (!l) {
        state.SkipWithError("needs ../shared/data/hateengine/E1M1.obj");
        return;
    }
    const auto r = uint32_t(state.range(0));
    std::vector<uint8_t> seen(l->zone.mesh.faces.size());
    uint64_t faces = 0;
    for (auto _ : state) {
        faces = 0;
        for (const glm::vec3& p : l->points) {
            std::fill(seen.begin(), seen.end(), 0);
            for (int view = 0; view < 6; ++view)
                for (uint32_t y = 0; y < r; ++y)
                    for (uint32_t x = 0; x < r; ++x) {
                        const int axis = view / 2;
                        glm::vec3 d(0.0f);
                        d[axis] = view % 2 ? -1.0f : 1.0f;
                        d[(axis + 1) % 3] = 2.0f * (float(x) + 0.5f) / float(r) - 1.0f;
                        d[(axis + 2) % 3] = 2.0f * (float(y) + 0.5f) / float(r) - 1.0f;
                        const MeshTracer::Hit h = l->tracer->first_hit(p, d, std::numeric_limits<float>::infinity());
                        if (h.hit && h.front)
                            seen[h.face] = 1;
                    }
            for (uint8_t s : seen)
                faces += s;
        }
    }
    count_samples(state, l->points.size(), faces);
}

// The same rays in packets of 8 (RayCube: MeshTracer::first_hits, rtcIntersect8), what the raster
// baker uses.
void BM_EmbreePacketRays(benchmark::State& state)
{
    const Level* l = level();
    if (!l) {
        state.SkipWithError("needs ../shared/data/hateengine/E1M1.obj");
        return;
    }
    RayCube rays(*l->tracer, {uint32_t(state.range(0)), true, 0.05f});
    time_views(state, *l, rays);
}

void BM_GpuCube(benchmark::State& state)
{
    const Level* l = level();
    if (!l) {
        state.SkipWithError("needs ../shared/data/hateengine/E1M1.obj");
        return;
    }
    std::unique_ptr<GlHeadless> gpu;
    try {
        gpu = GlHeadless::open();
    } catch (const GlUnavailable& e) {
        state.SkipWithError(e.what());
        return;
    }
    // Point by point, as the CPU renderers are timed (the faces seen counted per point).
    struct OnePoint {
        GpuCube cube;
        void render(const glm::vec3& p, std::vector<uint8_t>& seen) { cube.render(std::span(&p, 1), seen); }
    } renderer{GpuCube(*gpu, l->zone, {uint32_t(state.range(0)), true, 0.05f})};
    time_views(state, *l, renderer);
    state.SetLabel(gpu->description());
}

// Wall time (UseRealTime): the GPU's work runs on the driver's threads (llvmpipe: one per core).
BENCHMARK(BM_CubeRaster)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EmbreePrimaryRays)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EmbreePacketRays)->Arg(32)->Arg(64)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GpuCube)->Arg(32)->Arg(64)->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
