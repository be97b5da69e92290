#include "visibility/methods/vis_method.h"

#include "visibility/bsp_tree_edit.h"
#include "visibility/methods/vis_report_fields.h"
#include "visibility/portal/box_clusters.h"
#include "visibility/portal/cluster_vis.h"
#include "visibility/portal/portal_vis.h"
#include "visibility/portal/portal_vis_2d.h"
#include "visibility/portal/portalize.h"
#include "visibility/portal/region_clusters.h"
#include "visibility/raster/raster_vis.h"
#include "visibility/reference/mesh_reference.h"
#include "visibility/reference/portal_sampler.h"
#include "visibility/reference/region_sampler.h"
#include "visibility/terrain/terrain_vis.h"

#include <chrono>
#include <stdexcept>
#include <cstdio>

namespace pvs {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(const char* fmt, auto... args)
{
    char text[256];
    std::snprintf(text, sizeof text, fmt, args...);
    return text;
}

const char* on_off(bool b) { return b ? "on" : "off"; }

// What a user of a reference PVS must know.
constexpr const char* kReferenceCanPop =
    "warning: the reference is a lower bound (only sight lines it traced): culling with it can pop where a line it "
    "did not find would have shown a region; use it to judge other PVSs";

std::string no_label(const MethodSettings&) { return {}; }
std::string full_label(const MethodSettings& s)
{
    return format("level=%d passages=%s target-checks=%s%s", s.level, on_off(s.passages), on_off(s.target_checks),
                  s.heights ? " heights" : "");
}
std::string reference_label(const MethodSettings& s)
{
    return (s.samples ? "samples=" + std::to_string(s.samples) : std::string("converged")) +
           " seed=" + std::to_string(s.seed);
}

VisParams vis_params(const MethodSettings& s, VisParams::Method method)
{
    VisParams params;
    params.method = method;
    params.level = s.level;
    params.threads = s.threads;
    if (!s.passages)
        params.passage_budget_bytes = 0;
    params.target_checks = s.target_checks;
    params.progress = s.progress;
    return params;
}

MethodRun run_from_report(Pvs pvs, const VisReport& report, double seconds, const std::string& what)
{
    MethodRun run;
    run.seconds = seconds;
    run.peak_bytes_estimate = report.peak_bytes_estimate;
    run.cancelled = report.cancelled;
    run.summary = format("%s: %zu portals, mean %.1f visible of %u regions, %.2f s on %u threads", what.c_str(),
                         report.portals, report.mean_visible, pvs.region_count(), seconds, report.threads);
    run.pvs = std::move(pvs);
    return run;
}

MethodRun run_file(const Zone& zone, const MethodSettings&)
{
    MethodRun run;
    run.pvs = zone.baked_pvs;
    run.summary = zone.baked_pvs ? "file: the PVS the file carries" : "file: the file has no PVS";
    return run;
}

MethodRun run_none(const Zone&, const MethodSettings&)
{
    MethodRun run;
    run.summary = "none: no PVS, the frustum only";
    return run;
}

// Where the portals came from and what the build met, for the report.
void add_portal_input_fields(const PortalInput& in, std::vector<ReportField>& fields)
{
    fields.push_back({"portal_source", in.source});
    fields.push_back({"portalize_seconds", in.seconds});
    if (in.stats) {
        fields.push_back({"leaks.leaves_touching_world", uint64_t(in.stats->leaves_touching_world.size())});
        fields.push_back({"leaks.leaves_touching_outside", uint64_t(in.stats->leaves_touching_outside.size())});
    }
}

void add_cluster_fields(const ClusterReport& r, std::vector<ReportField>& fields)
{
    fields.push_back({"clusters.clusters", uint64_t(r.clusters)});
    fields.push_back({"clusters.cluster_portals", uint64_t(r.cluster_portals)});
    fields.push_back({"clusters.portals_inside_clusters", uint64_t(r.portals_inside_clusters)});
    fields.push_back({"clusters.cluster_mean_visible", r.cluster_mean_visible});
    fields.push_back({"clusters.expand_seconds", r.expand_seconds});
}

// The portals given (a file's) or built here; over clusters when they name clusters, on the 2-D
// baker for a map extruded from 2-D.
MethodRun run_portal(const Zone& zone, const MethodSettings& s, VisParams::Method method, const char* name)
{
    const auto start = std::chrono::steady_clock::now();
    const PortalInput built = s.portals ? PortalInput{} : zone_portal_input(zone, s);
    const PortalInput& in = s.portals ? *s.portals : built;
    const uint32_t regions = uint32_t(zone.region_count());
    const bool flow_2d = !in.clusters && zone_uses_2d_vis(zone, s);
    VisParams params = vis_params(s, method);
    if (method == VisParams::Method::Full && !in.clusters)
        params.probe = s.chain_probe;
    VisReport report;
    ClusterReport cluster_report;
    Pvs pvs = in.clusters ? bake_cluster_portal_vis(in.portals, in.clusters->cluster_of_region,
                                                    in.clusters->cluster_count, params, &report, &cluster_report)
              : flow_2d   ? bake_portal_vis_2d(in.portals, regions, params, &report)
                          : bake_portal_vis(in.portals, regions, params, &report);
    MethodRun run = run_from_report(std::move(pvs), report, seconds_since(start),
                                    flow_2d ? std::string(name) + " (2-D)" : std::string(name));
    run.notes = in.notes;
    if (in.portals.portals.empty())
        run.notes.push_back("warning: " + zone.source.path + " has no portals: every region will see only itself");
    run.fields = vis_report_fields(report, method == VisParams::Method::Full, flow_2d);
    if (method == VisParams::Method::Full)
        run.fields.push_back({"level", uint64_t(s.level)});
    add_portal_input_fields(in, run.fields);
    if (in.clusters) {
        cluster_report.portals_inside_clusters = in.portals_inside_clusters;
        add_cluster_fields(cluster_report, run.fields);
    }
    return run;
}

MethodRun run_portal_fast(const Zone& zone, const MethodSettings& s)
{
    return run_portal(zone, s, VisParams::Method::Fast, "portal-fast");
}

MethodRun run_portal_full(const Zone& zone, const MethodSettings& s)
{
    return run_portal(zone, s, VisParams::Method::Full, "portal-full");
}

// Box clusters where the zone's regions are boxes (generated zones), else the tree's subtrees.
MethodRun run_clustered(const Zone& zone, const MethodSettings& s)
{
    const auto start = std::chrono::steady_clock::now();
    const PortalSet portals = method_portals(zone, s);
    const bool boxes = regions_are_boxes(zone.regions, portals);
    const RegionClusters clusters =
        boxes ? box_merge_clusters(zone.regions, portals) : bsp_subtree_clusters(zone.tree, zone.regions);
    VisReport report;
    ClusterReport cluster_report;
    Pvs pvs = bake_clustered_portal_vis(portals, clusters.cluster_of_region, clusters.cluster_count,
                                        vis_params(s, VisParams::Method::Full), &report, &cluster_report);
    MethodRun run = run_from_report(std::move(pvs), report, seconds_since(start), "clustered");
    run.fields = vis_report_fields(report, true, false);
    run.fields.push_back({"level", uint64_t(s.level)});
    add_cluster_fields(cluster_report, run.fields);
    run.summary += format(" (%u %s clusters)", clusters.cluster_count, boxes ? "box" : "subtree");
    return run;
}

// A grid zone's reference: sight lines against the mesh (mesh_reference.h), `samples` a cell
// (4096 by default) from max(16, samples / 256) points, reported as one round.
MethodRun run_mesh_reference(const Zone& zone, const MethodSettings& s)
{
    MeshReferenceParams params;
    params.seed = s.seed;
    params.threads = s.threads;
    params.progress = s.progress;
    const uint64_t samples = s.samples ? s.samples : 4096;
    params.points_per_cell = uint32_t(std::max<uint64_t>(16, samples / 256));
    params.rays_per_point = uint32_t(std::max<uint64_t>(1, samples / params.points_per_cell));
    MeshReferenceReport report;
    Pvs pvs = bake_mesh_reference_grid(zone, *zone.view_grid, params, &report);
    MethodRun run;
    run.seconds = report.seconds;
    run.cancelled = report.cancelled;
    run.summary = format("reference (mesh rays, Embree): %s rays from %s of %s points in open space, %s of %s cells "
                         "open, mean %.1f visible, %.2f s on %u threads",
                         std::to_string(report.rays).c_str(), std::to_string(report.open_points).c_str(),
                         std::to_string(report.points).c_str(), std::to_string(report.open_cells).c_str(),
                         std::to_string(report.cells).c_str(), report.mean_visible, report.seconds, report.threads);
    run.notes.push_back(kReferenceCanPop);
    if (s.on_reference_round && !report.cancelled) {
        ReferenceRound round;
        round.samples_per_region = samples;
        round.rays = report.rays;
        round.bits = uint64_t(report.mean_visible * double(report.cells) + 0.5);
        round.new_bits = round.bits;
        round.seconds = report.seconds;
        s.on_reference_round(round, pvs);
    }
    run.pvs = std::move(pvs);
    return run;
}

MethodRun run_reference(const Zone& zone, const MethodSettings& s)
{
    if (!zone.tree.exists() && zone.view_grid)
        return run_mesh_reference(zone, s);
    ReferenceParams params;
    params.seed = s.seed;
    params.sky = s.sky;
    params.threads = s.threads;
    params.progress = s.progress;
    params.on_round = s.on_reference_round;
    if (s.samples) { // exactly what was asked for: no early stop
        params.max_samples = s.samples;
        params.initial_samples = uint32_t(std::min<uint64_t>(params.initial_samples, s.samples));
        params.converge_share = 0.0;
    }
    params.per_source = s.reference_per_source;
    params.sources = s.sources;
    ReferenceReport report;
    Pvs pvs = bake_reference_vis(zone, params, &report);
    MethodRun run;
    run.seconds = report.seconds;
    run.peak_bytes_estimate = report.peak_bytes_estimate;
    run.cancelled = report.cancelled;
    const ReferenceRound last = report.rounds.empty() ? ReferenceRound{} : report.rounds.back();
    run.summary = format("reference: %s lines, %s per region, %s walks from %s eyes per region, mean %.1f visible "
                         "of %u regions, last doubling added %.3f%%%s, %.2f s on %u threads",
                         std::to_string(report.rays).c_str(), std::to_string(last.samples_per_region).c_str(),
                         std::to_string(report.walks).c_str(), std::to_string(last.eyes_per_region).c_str(),
                         report.mean_visible, pvs.region_count(), 100.0 * last.new_share(),
                         report.converged ? " (converged)" : "", report.seconds, report.threads);
    if (report.truncated_walks) // a walk that hit its depth limit or budget: degenerate portals
        run.summary += format("; %s walks cut short", std::to_string(report.truncated_walks).c_str());
    run.notes.push_back(kReferenceCanPop);
    run.pvs = std::move(pvs);
    return run;
}

// A region's cost: its volume lines, and its walks at about 300 lines each (the progress bar's
// weights; reference_vis.cpp), where it has a volume and portals.
std::vector<double> reference_source_costs(const Zone& zone, const MethodSettings& s)
{
    if (!zone.tree.exists()) // an OBJ level's reference traces against the mesh, over its grid's cells
        throw std::invalid_argument("the reference of a zone without a BSP tree (sight lines against the mesh) "
                                    "cannot be split into shards yet");
    const RegionSampler volumes(zone);
    PortalOptions portal_options;
    portal_options.sky = s.sky;
    const PortalSet portal_set = build_zone_portals(zone, portal_options);
    const PortalSampler portals(portal_set, uint32_t(zone.region_count()));
    const ReferenceParams defaults;
    const double samples = double(s.samples ? s.samples : defaults.max_samples);
    const double walks = double(defaults.initial_walks) * samples / double(defaults.initial_samples);
    std::vector<double> costs(zone.region_count(), 0.0);
    for (uint32_t r = 0; r < costs.size(); ++r)
        costs[r] = (volumes.has_volume(r) ? samples : 0.0) + (portals.links(r).empty() ? 0.0 : 300.0 * walks);
    return costs;
}

std::string raster_label(const MethodSettings& s)
{
    // The sample knobs: points per region or open cell, and the lattice step (grid lattices).
    const char* lattice = s.raster_lattice == Lattice::OpenRandom ? "open"
                          : s.raster_lattice == Lattice::Centred  ? "centred"
                                                                  : "hateengine";
    return format("res=%u points=%u step=%g lattice=%s", s.raster_resolution, s.raster_points,
                  double(s.raster_step), lattice);
}

MethodRun run_raster(const Zone& zone, const MethodSettings& s)
{
    RasterParams params;
    params.raster.resolution = s.raster_resolution;
    params.raster.cull_back_faces = s.cull_back_faces;
    params.engine = s.raster_engine;
    params.device = s.raster_device;
    params.gpu_batch_views = s.raster_gpu_batch;
    params.step = s.raster_step;
    params.lattice = s.raster_lattice;
    params.points_per_region = s.raster_points;
    params.seed = s.seed;
    params.threads = s.threads;
    params.cells = s.sources;
    params.progress = s.progress;
    RasterReport report;
    Pvs pvs = zone.view_grid ? bake_raster_grid(zone, *zone.view_grid, params, &report)
                             : bake_raster_regions(zone, params, &report);
    MethodRun run;
    run.seconds = report.seconds;
    run.cancelled = report.cancelled;
    run.peak_bytes_estimate = size_t(report.threads) * 7 * size_t(s.raster_resolution) * s.raster_resolution * 8 +
                              pvs.memory_bytes();
    const std::string drawn = report.device != "cpu"                  ? report.device
                              : s.raster_engine == RasterEngine::Rays ? std::string("pixel rays")
                                                                      : std::string("rasteriser");
    const std::string where =
        report.device != "cpu" ? std::string("on the GPU") : "on " + std::to_string(report.threads) + " threads";
    run.summary = format("raster: %s points in %s %s, %ux%u per cube face (%s), mean %.1f visible, %.2f s %s",
                         std::to_string(report.points).c_str(), std::to_string(report.cells).c_str(),
                         zone.view_grid ? "grid cells" : "regions", s.raster_resolution, s.raster_resolution,
                         drawn.c_str(), report.mean_visible, report.seconds, where.c_str());
    if (!report.device_note.empty())
        run.notes.push_back("note: " + report.device_note);
    run.notes.push_back("note: the raster PVS is a sample (what the rendered points saw): a camera between the "
                        "points can see more; denser sampling (--step, --points, --resolution) only adds");
    run.pvs = std::move(pvs);
    return run;
}

// A cell's cost: the points it renders (a point's six views cost about the same anywhere).
std::vector<double> raster_source_costs(const Zone& zone, const MethodSettings& s)
{
    RasterParams params;
    params.step = s.raster_step;
    params.lattice = s.raster_lattice;
    params.points_per_region = s.raster_points;
    params.seed = s.seed;
    const std::vector<uint32_t> points = raster_cell_point_counts(zone, params);
    return std::vector<double>(points.begin(), points.end());
}

MethodRun run_terrain(const Zone& zone, const MethodSettings& s)
{
    TerrainVisParams params;
    params.threads = s.threads;
    params.progress = s.progress;
    TerrainVisReport report;
    Pvs pvs = bake_terrain_vis(zone, params, &report);
    MethodRun run;
    run.seconds = report.seconds;
    run.cancelled = report.cancelled;
    run.peak_bytes_estimate = report.peak_bytes_estimate;
    run.summary = format("terrain: heightfield of %u x %u columns (%g x %g), %s sweeps, mean %.1f visible, %.2f s on "
                         "%u threads",
                         report.columns_x, report.columns_y, report.cell_x, report.cell_y,
                         std::to_string(report.sources).c_str(), report.mean_visible, report.seconds, report.threads);
    if (!report.cancelled)
        run.pvs = std::move(pvs);
    return run;
}

constexpr VisMethod kMethods[] = {
    {"file", "the PVS stored in the zone file", Bound::Unknown, false, false, run_file, no_label},
    {"none", "no PVS: the frustum only", Bound::Everything, false, false, run_none, no_label},
    {"portal-fast", "base portal vis: loose, conservative", Bound::Upper, true, false, run_portal_fast, no_label,
     nullptr, "its rows are unions of the directed portals' base vis, computed in batches over every portal"},
    {"portal-full", "clipped portal flow (as Quake's vis): conservative", Bound::Upper, true, false, run_portal_full,
     full_label, nullptr,
     "its flow prunes each portal's walk with the finished rows of the portals ranked before it, so a shard on its own "
     "would bake other rows"},
    {"clustered", "portal-full over clusters of regions: faster on big zones, looser", Bound::Upper, true, true,
     run_clustered, full_label, nullptr,
     "its flow prunes each portal's walk with the finished rows of the portals ranked before it, so a shard on its own "
     "would bake other rows"},
    {"terrain", "horizon over the zone's heightfield (open ground): conservative, hides only what hills hide",
     Bound::Upper, true, true, run_terrain, no_label, nullptr,
     "each row is a source's horizon intersected with the transposed rows, which need every source"},
    {"reference", "sampled sight lines through the tree: ground truth from below (can pop)", Bound::Lower, true, true,
     run_reference, reference_label, reference_source_costs,
     "each round's walks aim by the rows every region found in the rounds before (--per-source and --samples N make "
     "each region's lines its own)",
     true},
    {"raster", "cube maps rendered from points in each cell (as HateEngine's baker): a sample, can pop", Bound::Lower,
     true, true, run_raster, raster_label, raster_source_costs},
};

} // namespace

const char* bound_name(Bound bound)
{
    switch (bound) {
    case Bound::Upper: return "upper";
    case Bound::Lower: return "lower";
    case Bound::Everything: return "everything";
    case Bound::Unknown: break;
    }
    return "unknown";
}

std::span<const VisMethod> vis_methods() { return kMethods; }

PortalSet method_portals(const Zone& zone, const MethodSettings& settings)
{
    MethodSettings plain = settings;
    plain.box_clusters = false;
    plain.portals = nullptr;
    return zone_portal_input(zone, plain).portals;
}

bool method_uses_2d_vis(const Zone& zone, const MethodSettings& settings) { return zone_uses_2d_vis(zone, settings); }

const VisMethod* find_vis_method(std::string_view name)
{
    for (const VisMethod& m : kMethods)
        if (m.name == name)
            return &m;
    return nullptr;
}

std::string vis_method_names()
{
    std::string names;
    for (const VisMethod& m : kMethods)
        names += (names.empty() ? "" : ", ") + std::string(m.name);
    return names;
}

std::string baking_method_names()
{
    std::string names;
    for (const VisMethod& m : kMethods)
        if (m.bakes)
            names += (names.empty() ? "" : ", ") + std::string(m.name);
    return names;
}

} // namespace pvs
