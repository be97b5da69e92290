#include "gen/generate_outdoor_zone.h"

#include "gen/generate_zone.h"
#include "gen/grid_zone.h"
#include "gen/terrain_level.h"
#include "visibility/methods/vis_method.h"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace pvs::gen {

namespace {

// The terrain method: on open ground the portal flow does not finish in useful time (even 5 200
// regions take over 560 CPU-seconds: docs/outdoor.md); the horizon over the ground is
// conservative, quicker than base vis and tighter. The notes say how the PVS was made.
void bake_terrain_pvs(Zone& zone, unsigned threads, const std::function<bool(double)>& progress)
{
    MethodSettings settings;
    settings.threads = threads;
    settings.progress = progress;
    MethodRun run = find_vis_method("terrain")->run(zone, settings);
    if (run.cancelled || !run.pvs) {
        zone.source.notes.push_back("no PVS: the terrain bake was cancelled");
        return;
    }
    zone.baked_pvs = std::move(run.pvs);
    zone.source.notes.push_back("PVS baked with " + run.summary);
}

} // namespace

Zone generate_outdoor_zone(const OutdoorParams& params)
{
    if (!(params.cell_size > 0.0f) || !(params.size > 0.0f))
        throw std::invalid_argument("outdoor zone: size and cell size must be positive");
    const double columns = std::floor(double(params.size) / double(params.cell_size));
    if (columns < kMinTerrainColumns || columns > kMaxTerrainColumns)
        throw std::invalid_argument("outdoor zone: size / cell = " + std::to_string(int(columns)) +
                                    " columns, outside " + std::to_string(kMinTerrainColumns) + ".." +
                                    std::to_string(kMaxTerrainColumns));
    TerrainFeatures features;
    const VoxelLevel level = make_terrain_level({int(columns), params.height, params.seed}, &features);
    // One label per cell: no two cells share a region, as EverQuest's trees split down to cells.
    std::vector<uint32_t> labels(level.cells.size());
    std::iota(labels.begin(), labels.end(), 0u);
    const glm::vec3 origin = -glm::vec3(level.dims) * params.cell_size * 0.5f * glm::vec3(1, 1, 0);
    Zone zone = build_grid_zone(level, uniform_grid_axes(level.dims, params.cell_size, origin), labels);
    ZoneSource source{"gen:outdoor,size=" + std::to_string(int(params.size)) + ",cell=" +
                          std::to_string(int(params.cell_size)) + ",seed=" + std::to_string(params.seed),
                      "pvscope procedural outdoor zone", "1", {}, {}};
    zone.source = std::move(source);
    size_t open = 0;
    for (Cell c : level.cells)
        open += c != Cell::Solid ? 1 : 0;
    zone.source.counts = {{"columns", uint64_t(columns)},
                          {"cells", level.cells.size()},
                          {"open cells", open},
                          {"buildings", uint64_t(features.buildings)}};
    if (params.bake)
        bake_terrain_pvs(zone, params.bake_threads, params.bake_progress);
    else
        zone.source.notes.push_back("no PVS: not baked (the culler falls back to the frustum)");
    zone.shrink_to_fit();
    return zone;
}

} // namespace pvs::gen
