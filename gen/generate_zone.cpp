#include "gen/generate_zone.h"

#include "gen/grid_zone.h"
#include "gen/voxel_level.h"
#include "visibility/methods/portal_input.h"
#include "visibility/methods/vis_method.h"
#include "visibility/zone_stats.h"

#include <cstdio>
#include <glm/common.hpp>
#include <stdexcept>
#include <string>

namespace pvs::gen {

// The zone's own portals, baked by the registry's portal-full (level 4) or portal-fast; the notes
// say how it was made.
void bake_generated_pvs(Zone& zone, unsigned threads, const std::function<bool(double)>& progress,
                        VisParams::Method method, bool enclosed)
{
    const bool full = method == VisParams::Method::Full;
    const char* name = full ? "portal-full (level 4)" : "portal-fast (base vis)";
    MethodSettings settings;
    settings.level = 4;
    settings.threads = threads;
    settings.progress = progress;
    const PortalInput input = zone_portal_input(zone, settings);
    zone.portals = input.portals;
    settings.portals = &input;
    MethodRun run = find_vis_method(full ? "portal-full" : "portal-fast")->run(zone, settings);
    if (run.cancelled) {
        zone.baked_pvs.reset();
        zone.source.notes.push_back(std::string("no PVS: the ") + name + " bake was cancelled");
        return;
    }
    zone.baked_pvs = std::move(run.pvs);
    const ReportField* used = find_field(run.fields, "portals"); // the portals the bake could use
    char note[200];
    std::snprintf(note, sizeof note,
                  "PVS baked with %s from %llu portals built from the tree: mean %.1f of %zu regions visible", name,
                  used ? static_cast<unsigned long long>(std::get<uint64_t>(used->value)) : 0ull,
                  compute_pvs_density(*zone.baked_pvs).mean_visible, zone.regions.size());
    zone.source.notes.push_back(note);
    // Solid cells are kLeafOutside leaves here, so only the world box counts as a leak.
    if (enclosed && input.stats && !input.stats->leaves_touching_world.empty())
        zone.source.notes.push_back("warning: " + std::to_string(input.stats->leaves_touching_world.size()) +
                                    " open leaves touch the world box (a leak in the generator)");
}

Zone generate_zone(const GenParams& params)
{
    if (!(params.cell_size > 0.0f))
        throw std::invalid_argument("cell size must be positive");
    const VoxelLevel level = make_voxel_level(params.rooms, params.seed);
    const glm::vec3 origin = -glm::vec3(level.dims) * params.cell_size * 0.5f * glm::vec3(1, 1, 0);
    Zone zone = build_grid_zone(level, uniform_grid_axes(level.dims, params.cell_size, origin));
    // Filled apart and moved in: assigning literals into the returned zone's strings draws a
    // GCC 12 -Wrestrict false positive.
    ZoneSource source{"gen:rooms=" + std::to_string(params.rooms) + ",seed=" + std::to_string(params.seed),
                      "pvscope procedural zone", "1", {}, {}};
    zone.source = std::move(source);
    zone.source.counts = {{"rooms", level.rooms.size()},
                          {"floors", uint64_t(level.floors)},
                          {"corridors", uint64_t(level.corridors)},
                          {"shafts", uint64_t(level.shafts)},
                          {"stairs", uint64_t(level.stairs)},
                          {"cells", level.cells.size()}};
    if (params.bake)
        bake_generated_pvs(zone, params.bake_threads, params.bake_progress, VisParams::Method::Full, true);
    else
        zone.source.notes.push_back("no PVS: not baked (GenParams::bake off; the culler falls back to the frustum)");
    zone.shrink_to_fit(); // loaders grow their vectors; keep only what the zone needs
    return zone;
}

} // namespace pvs::gen
