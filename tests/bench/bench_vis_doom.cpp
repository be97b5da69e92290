// The 2-D portal vis on Freedoom maps (docs/performance.md "Doom: 2-D portal vis"), against the
// 3-D baker on the very same portals in the same run (exact on vertical portals of one height:
// the baseline a user would otherwise have). GL nodes by glbsp (made once, in a temp dir).
//   build/tests/bench/bench_vis_doom --benchmark_counters_tabular=true
// Maps: freedoom2 MAP10, MAP28, freedoom1 E3M7 (glVIS 1.6 -O3 took 13.1, 18.3 and 31.3 s on this
// machine kind) and MAP12 (glVIS: more than 19 minutes; the 3-D baseline is not run).
#include "tests/support/freedoom.h"
#include "visibility/bsp_tree_edit.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portal_vis_2d.h"
#include "visibility/portal/portalize.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/doom_zone.h"

#include <benchmark/benchmark.h>

#include <map>
#include <memory>

namespace {

using namespace pvs;

struct DoomCase {
    Zone zone;
    PortalSet portals;
};

const DoomCase* load(const std::string& wad_name, const std::string& map)
{
    static std::map<std::string, std::unique_ptr<DoomCase>> cache;
    auto& slot = cache[wad_name + map];
    if (slot)
        return slot.get();
    const auto wad_path = test::find_freedoom(wad_name);
    if (!wad_path)
        return nullptr;
    const auto gwa_path = test::gl_nodes_file(*wad_path, test::GlBuilder::glbsp_v2);
    if (!gwa_path)
        return nullptr;
    const doom::WadFile wad = doom::read_wad(*wad_path), gwa = doom::read_wad(*gwa_path);
    slot = std::make_unique<DoomCase>();
    slot->zone = doom::build_doom_zone(doom::read_doom_map(wad, &gwa, map), nullptr);
    slot->portals = build_portals(without_height_nodes(slot->zone.tree), slot->zone.regions,
                                  zone_portal_world(slot->zone), {});
    return slot.get();
}

void BM_DoomVis(benchmark::State& state, const char* wad, const char* map, bool two_d)
{
    const DoomCase* c = load(wad, map);
    if (!c) {
        state.SkipWithError("needs Freedoom and glbsp (apt-get install freedoom glbsp)");
        return;
    }
    VisParams params;
    params.threads = unsigned(state.range(0));
    params.level = 3;
    VisReport report;
    for (auto _ : state) {
        Pvs pvs = two_d ? bake_portal_vis_2d(c->portals, uint32_t(c->zone.region_count()), params, &report)
                        : bake_portal_vis(c->portals, uint32_t(c->zone.region_count()), params, &report);
        benchmark::DoNotOptimize(pvs);
    }
    state.counters["portals"] = double(report.portals);
    state.counters["mean_visible"] = report.mean_visible;
    state.counters["seconds"] = report.seconds;
}

BENCHMARK_CAPTURE(BM_DoomVis, MAP10_2d, "freedoom2.wad", "MAP10", true)->Arg(1)->Arg(2)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DoomVis, MAP10_3d, "freedoom2.wad", "MAP10", false)->Arg(2)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DoomVis, MAP28_2d, "freedoom2.wad", "MAP28", true)->Arg(1)->Arg(2)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DoomVis, MAP28_3d, "freedoom2.wad", "MAP28", false)->Arg(2)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DoomVis, E3M7_2d, "freedoom1.wad", "E3M7", true)->Arg(1)->Arg(2)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DoomVis, E3M7_3d, "freedoom1.wad", "E3M7", false)->Arg(2)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_DoomVis, MAP12_2d, "freedoom2.wad", "MAP12", true)->Arg(2)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
