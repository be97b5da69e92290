// Render time per frame of e1m1 at 800x600, textured, with Irrlicht's software renderer (Burning's
// Video): frustum culling only (the baseline) against pvs+frustum, over the same 64 seeded cameras
// in playable space. Triangle counts per frame are reported as counters.
//
//   build/tests/bench/bench_render --benchmark_min_time=2
#include "tests/support/test_data.h"
#include "render/software_renderer.h"
#include "visibility/culler.h"
#include "visibility/eval/camera_set.h"

#include <benchmark/benchmark.h>

namespace pvs {
namespace {

void render_walk(benchmark::State& state, CullMode mode)
{
    const Zone* zone = test::shared_zone("quake/e1m1.bsp");
    if (!zone) {
        state.SkipWithError("SKIPPED: needs ../shared/data/quake/e1m1.bsp");
        return;
    }
    Camera lens;
    lens.aspect = 800.0f / 600.0f;
    const std::vector<Camera> cameras = random_cameras_in_regions(*zone, 64, 4, lens);
    ui::SoftwareRenderer renderer(800, 600);
    Culler culler(*zone, &*zone->baked_pvs);
    std::vector<uint32_t> visible;
    renderer.render(*zone, cameras[0], visible, ui::RenderMode::Textured); // build the scene outside the timing
    size_t i = 0;
    uint64_t triangles = 0;
    for (auto _ : state) {
        const Camera& camera = cameras[i++ % cameras.size()];
        culler.cull(camera, {mode, false}, visible);
        const ui::Image image = renderer.render(*zone, camera, visible, ui::RenderMode::Textured);
        triangles += renderer.last_stats().triangles_drawn;
        benchmark::DoNotOptimize(image.rgba.data());
    }
    state.counters["triangles_per_frame"] = double(triangles) / double(state.iterations());
}

void BM_Render800x600_Baseline_FrustumOnly(benchmark::State& state) { render_walk(state, CullMode::Frustum); }
void BM_Render800x600_PvsFrustum(benchmark::State& state) { render_walk(state, CullMode::PvsFrustum); }
BENCHMARK(BM_Render800x600_Baseline_FrustumOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Render800x600_PvsFrustum)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace pvs

BENCHMARK_MAIN();
