// Why A's row holds B, or not (pair_explanation.h).
#include "visibility/eval/pair_explanation.h"

#include "visibility/methods/portal_input.h"
#include "visibility/methods/vis_method.h"
#include "visibility/portal/portalize.h"
#include "visibility/reference/grid_witness.h"
#include "visibility/reference/mesh_tracer.h"
#include "visibility/reference/region_sampler.h"
#include "visibility/reference/tree_trace.h"

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace pvs {
namespace {

// The polygons of the portals on region r's boundary.
std::vector<std::vector<glm::dvec3>> region_portal_polygons(const PortalSet& set, uint32_t r)
{
    std::vector<std::vector<glm::dvec3>> polygons;
    for (const Portal& p : set.portals) {
        if (p.regions[0] != int32_t(r) && p.regions[1] != int32_t(r))
            continue;
        if (p.first_point > set.points.size() || p.point_count > set.points.size() - p.first_point)
            continue;
        std::vector<glm::dvec3>& polygon = polygons.emplace_back();
        for (uint32_t i = 0; i < p.point_count; ++i)
            polygon.emplace_back(set.points[p.first_point + i]);
    }
    return polygons;
}

// The regions the segment passes through, in order (consecutive repeats once).
std::vector<uint32_t> regions_along(const TreeTracer& tracer, const glm::dvec3& from, const glm::dvec3& to)
{
    std::vector<uint32_t> regions;
    const double length = glm::length(to - from);
    if (!(length > 0.0))
        return regions;
    TreeTracer::Scratch scratch;
    tracer.trace(from, (to - from) / length, length, scratch, [&](int32_t region, double, double) {
        if (regions.empty() || regions.back() != uint32_t(region))
            regions.push_back(uint32_t(region));
    });
    return regions;
}

// The flow's chain from a to b, if it holds the pair (into e.chain, e.portals): the registry's
// portal-full over the zone's own portals (never clusters), with a probe; returns the flow's PVS.
Pvs find_chain(const Zone& zone, uint32_t a, uint32_t b, const ExplainOptions& options, PairExplanation& e)
{
    MethodSettings settings = options.flow;
    settings.box_clusters = false;
    settings.portals = nullptr;
    const PortalInput input = zone_portal_input(zone, settings);
    e.portals = input.portals;
    e.chain_2d = zone_uses_2d_vis(zone, settings);
    ChainProbe probe;
    probe.from = a;
    probe.to = b;
    settings.portals = &input;
    settings.chain_probe = &probe;
    MethodRun run = find_vis_method("portal-full")->run(zone, settings);
    e.flow_run = true;
    e.flow_holds = run.pvs->visible(a, b);
    if (const FlowChain* best = probe.best())
        e.chain = *best;
    return std::move(*run.pvs);
}

std::string describe(const PairExplanation& e)
{
    char text[512];
    const char* unit = e.chain_2d ? "units wide" : "square units";
    std::string chain_words = e.flow_run ? "portal-full has no chain from A to B" : "portal-full's flow was not run";
    if (e.chain) {
        size_t narrowest = 0;
        for (size_t k = 1; k < e.chain->steps.size(); ++k)
            if (e.chain->steps[k].window_size < e.chain->steps[narrowest].window_size)
                narrowest = k;
        std::snprintf(text, sizeof text, "portal-full reaches B through %zu portals, narrowest window %.3g %s at step %zu",
                      e.chain->steps.size(), e.chain->steps[narrowest].window_size, unit, narrowest + 1);
        chain_words = text;
    }
    const unsigned long long tries = e.witness_tries;
    switch (e.verdict) {
    case PairVerdict::Sees:
        return "sees: a sight line joins A and B, and the PVS holds B";
    case PairVerdict::Overdraw:
        if (e.grid) {
            std::snprintf(text, sizeof text, "overdraw: the PVS holds the object, but no sight line was found in %llu lines",
                          tries);
            return text;
        }
        std::snprintf(text, sizeof text, "overdraw: the PVS holds B, but no sight line was found in %llu lines; %s",
                      tries, chain_words.c_str());
        return text;
    case PairVerdict::WouldPop:
        if (e.flow_cut) {
            std::snprintf(text, sizeof text,
                          "would pop: a sight line joins A and B, but the PVS lacks B; along it, portal-full reaches "
                          "%zu of its %zu regions and stops before region %u",
                          *e.flow_cut, e.witness_regions.size(), e.witness_regions[*e.flow_cut]);
            return text;
        }
        return std::string("would pop: a sight line joins A and B, but the PVS lacks B") +
               (e.flow_holds ? " (portal-full holds it)" : "");
    case PairVerdict::Hidden:
        std::snprintf(text, sizeof text, "hidden: no sight line was found in %llu lines, and the PVS lacks B", tries);
        return text;
    case PairVerdict::Unexplained:
        std::snprintf(text, sizeof text,
                      "unexplained: the PVS holds B with no sight line found in %llu lines and no chain of portal-full "
                      "(a bit set by hand or by a looser rule)",
                      tries);
        return text;
    }
    return {};
}

} // namespace

const char* pair_verdict_name(PairVerdict verdict)
{
    switch (verdict) {
    case PairVerdict::Sees: return "sees";
    case PairVerdict::Overdraw: return "overdraw";
    case PairVerdict::WouldPop: return "would-pop";
    case PairVerdict::Hidden: return "hidden";
    case PairVerdict::Unexplained: return "unexplained";
    }
    return "?";
}

WitnessCamera camera_looking(const glm::dvec3& from, const glm::dvec3& to)
{
    const glm::dvec3 d = to - from;
    WitnessCamera camera;
    camera.eye = from;
    camera.yaw_degrees = std::atan2(d.y, d.x) * 180.0 / M_PI;
    camera.pitch_degrees = std::atan2(d.z, std::hypot(d.x, d.y)) * 180.0 / M_PI;
    return camera;
}

namespace {

// A grid zone: A is a view cell, B an object; the witness by the mesh, no portal flow.
PairExplanation explain_grid_pair(const Zone& zone, const Pvs* pvs, uint32_t cell, uint32_t object,
                                  const ExplainOptions& options)
{
    const uint64_t cells = zone.view_grid->cell_count();
    if (cell >= cells)
        throw std::invalid_argument("cell " + std::to_string(cell) + " is out of range: " + zone.source.path + " has " +
                                    std::to_string(cells) + " view cells");
    if (object >= zone.region_count())
        throw std::invalid_argument("object " + std::to_string(object) + " is out of range: " + zone.source.path +
                                    " has " + std::to_string(zone.region_count()) + " objects");
    PairExplanation e;
    e.a = cell;
    e.b = object;
    e.grid = true;
    e.has_pvs = pvs != nullptr && cell < pvs->row_count() && object < pvs->region_count();
    e.in_pvs = !e.has_pvs || pvs->visible(cell, object);
    const MeshTracer tracer(zone);
    e.witness = find_grid_sight_line(zone, tracer, cell, object, options.witness_budget, options.seed, &e.witness_tries);
    if (e.witness)
        e.camera = camera_looking(e.witness->from, e.witness->to);
    e.verdict = e.witness ? (e.in_pvs ? PairVerdict::Sees : PairVerdict::WouldPop)
                          : (e.in_pvs ? PairVerdict::Overdraw : PairVerdict::Hidden);
    e.summary = describe(e);
    return e;
}

} // namespace

PairExplanation explain_pair(const Zone& zone, const Pvs* pvs, uint32_t a, uint32_t b, const ExplainOptions& options)
{
    const size_t regions = zone.region_count();
    if (zone.view_grid)
        return explain_grid_pair(zone, pvs, a, b, options);
    if (!zone.tree.exists())
        throw std::invalid_argument(zone.source.path + " has no BSP tree of regions to explain a pair on");
    for (const uint32_t r : {a, b})
        if (r >= regions)
            throw std::invalid_argument("region " + std::to_string(r) + " is out of range: " + zone.source.path +
                                        " has " + std::to_string(regions) + " regions");
    PairExplanation e;
    e.a = a;
    e.b = b;
    std::optional<Pvs> flow;
    if (options.want_chain)
        flow = find_chain(zone, a, b, options, e);
    if (options.explain_the_flow) {
        if (!flow)
            throw std::invalid_argument("explaining portal-full's own PVS needs its flow (want_chain)");
        pvs = &*flow;
    }
    e.has_pvs = pvs != nullptr && a < pvs->row_count() && b < pvs->region_count();
    e.in_pvs = !e.has_pvs || pvs->visible(a, b); // no PVS: every region is drawn

    const TreeTracer tracer(zone.tree, zone.regions, options.flow.sky);
    const RegionSampler sampler(zone);
    const Aabb box = zone.bounds();
    WitnessSearch search;
    search.seed = options.seed;
    search.reach = box.empty() ? 1e5 : 2.0 * double(glm::length(box.max - box.min)) + 1.0;
    search.world = zone_portal_world(zone); // as the reference: no sight line through a region's part beyond it
    // Half the lines where the flow's chain says they are (its first and last windows), then
    // through any portal of A and any of B.
    const std::vector<std::vector<glm::dvec3>> a_portals = region_portal_polygons(e.portals, a);
    const std::vector<std::vector<glm::dvec3>> b_portals = region_portal_polygons(e.portals, b);
    std::vector<std::vector<glm::dvec3>> first, last;
    if (e.chain && !e.chain_2d && e.chain->steps.size() >= 2) {
        first.push_back(e.chain->steps.front().window);
        last.push_back(e.chain->steps.back().window);
    }
    uint64_t used = 0;
    for (int phase = first.empty() ? 1 : 0; phase < 2 && !e.witness; ++phase) {
        search.near_a = phase == 0 ? first : a_portals;
        search.near_b = phase == 0 ? last : b_portals;
        search.budget = phase == 0 ? options.witness_budget / 2 : options.witness_budget - used;
        search.seed = options.seed + uint64_t(phase);
        uint64_t tries = 0;
        e.witness = find_sight_line(tracer, sampler, a, b, search, &tries);
        used += tries;
    }
    e.witness_tries = used;
    if (e.witness) {
        e.camera = camera_looking(e.witness->from, e.witness->to);
        e.witness_regions = regions_along(tracer, e.witness->from, e.witness->to);
        for (size_t k = 0; flow && k < e.witness_regions.size() && !e.flow_cut; ++k)
            if (!flow->visible(a, e.witness_regions[k]))
                e.flow_cut = k;
    }

    if (e.witness)
        e.verdict = e.in_pvs ? PairVerdict::Sees : PairVerdict::WouldPop;
    else if (!e.in_pvs)
        e.verdict = PairVerdict::Hidden;
    else
        e.verdict = e.has_pvs && options.want_chain && !e.chain && a != b ? PairVerdict::Unexplained : PairVerdict::Overdraw;
    if (a == b && e.in_pvs)
        e.verdict = PairVerdict::Sees;
    e.summary = describe(e);
    return e;
}

} // namespace pvs
