#include "visibility/reference/reference_vis.h"

#include "visibility/parallel_items.h"

#include "visibility/portal/portalize.h"
#include "visibility/reference/frontier.h"
#include "visibility/reference/line_witness.h"
#include "visibility/reference/portal_sampler.h"
#include "visibility/reference/region_sampler.h"
#include "visibility/reference/sample_sequence.h"
#include "visibility/reference/tree_trace.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace pvs {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Salts that keep the two samplers' streams apart.
constexpr uint64_t kVolumeStream = 0x564f4c554d45ull;   // "VOLUME"
constexpr uint64_t kFrontierStream = 0x46524f4e54ull;   // "FRONT"

// What every worker reads, and the counters they share.
struct Shared {
    const TreeTracer& tracer;
    const RegionSampler& volumes;
    const PortalSampler& portals;
    WitnessRows& rows;
    std::span<const uint64_t> before; // the rows when the round began: what counts as new
    uint64_t seed;
    double reach; // every line leaves the world box within this distance of a point inside it
    std::atomic<uint64_t> lines{0};
    std::atomic<uint64_t> rejected{0};
    std::atomic<uint64_t> frontier_found{0};
    std::atomic<bool> stop{false};
};

// Per-worker scratch, kept across items so nothing is allocated per line.
struct Scratch {
    TreeTracer::Scratch trace;
    Stretch stretch;
    std::vector<uint32_t> ways_in[2];
};

// Sets the pairs of the line's open stretch.
void prove(Shared& s, const glm::dvec3& point, const glm::dvec3& direction, Scratch& scratch)
{
    scratch.stretch.regions.clear();
    if (open_stretch(s.tracer, point, direction, s.reach, scratch.trace, scratch.stretch))
        witness_pairs(s.tracer, point, direction, scratch.stretch, s.rows, scratch.trace);
}

// Lines [first, end) of region r's volume stream: through a uniform point of r's volume, in a
// stratified direction. A point whose line does not start in r (the cells' epsilon margin) is
// rejected.
void sample_volume(Shared& s, uint32_t r, uint64_t first, uint64_t end, Scratch& scratch)
{
    if (!s.volumes.has_volume(r))
        return;
    const uint64_t shift = sampling::sample_key(s.seed, kVolumeStream, r, ~uint64_t{0});
    uint64_t rejected = 0;
    for (uint64_t i = first; i < end; ++i) {
        const uint64_t key = sampling::sample_key(s.seed, kVolumeStream, r, i);
        const glm::dvec3 point = s.volumes.point(r, sampling::hash_unit(key, 0), sampling::hash_unit(key, 1),
                                                 sampling::hash_unit(key, 2), sampling::hash_unit(key, 3));
        if (s.tracer.region_at(point) != int32_t(r)) {
            ++rejected;
            continue;
        }
        prove(s, point, sampling::stratified_direction(uint32_t(i), shift), scratch);
    }
    s.lines.fetch_add(end - first, std::memory_order_relaxed);
    s.rejected.fetch_add(rejected, std::memory_order_relaxed);
}

// Lines [first, end) of a frontier pair's stream: through a point on a portal of one side and a
// point on a frontier portal of the other (a portal of it whose other side the first side sees),
// the two sides taking turns where both have such portals.
void sample_frontier(Shared& s, FrontierPair pair, uint64_t first, uint64_t end, Scratch& scratch)
{
    const uint32_t regions = s.rows.region_count();
    frontier_portals(s.before, regions, s.portals, pair.a, pair.b, scratch.ways_in[0]); // into b, from a's side
    frontier_portals(s.before, regions, s.portals, pair.b, pair.a, scratch.ways_in[1]); // into a, from b's side
    const bool sides[2] = {!scratch.ways_in[0].empty() && !s.portals.links(pair.a).empty(),
                           !scratch.ways_in[1].empty() && !s.portals.links(pair.b).empty()};
    if (!sides[0] && !sides[1])
        return;
    bool joined = false;
    for (uint64_t i = first; i < end; ++i) {
        const int side = sides[0] && sides[1] ? int(i & 1) : sides[0] ? 0 : 1;
        const uint32_t from = side == 0 ? pair.a : pair.b, to = side == 0 ? pair.b : pair.a;
        const std::vector<uint32_t>& ways_in = scratch.ways_in[side];
        const std::span<const PortalSampler::Link> out_of = s.portals.links(from);
        const uint64_t key = sampling::sample_key(s.seed, kFrontierStream, uint64_t(pair.a) << 32 | pair.b, i);
        const uint32_t exit = out_of[size_t(sampling::hash_unit(key, 0) * double(out_of.size()))].portal;
        const uint32_t entry = ways_in[size_t(sampling::hash_unit(key, 1) * double(ways_in.size()))];
        const glm::dvec3 p = s.portals.point(exit, sampling::hash_unit(key, 2), sampling::hash_unit(key, 3),
                                             sampling::hash_unit(key, 4));
        const glm::dvec3 q = s.portals.point(entry, sampling::hash_unit(key, 5), sampling::hash_unit(key, 6),
                                             sampling::hash_unit(key, 7));
        const glm::dvec3 d = q - p;
        const double length = glm::length(d);
        if (!(length > 0.0))
            continue;
        // A line in a portal's plane (coplanar portals) runs along the wall the portal is cut
        // from; the beam test of witness_pairs rejects what it would prove, as any grazing line.
        const glm::dvec3 dir = d / length;
        prove(s, p, dir, scratch);
        const std::vector<uint32_t>& crossed = scratch.stretch.regions;
        joined = joined || (std::find(crossed.begin(), crossed.end(), to) != crossed.end() &&
                            std::find(crossed.begin(), crossed.end(), from) != crossed.end());
    }
    s.lines.fetch_add(end - first, std::memory_order_relaxed);
    s.frontier_found.fetch_add(joined ? 1 : 0, std::memory_order_relaxed);
}

// parallel_items (parallel_items.h) with the reference's stop flag and scratch.
template <class Work>
bool parallel_items(Shared& shared, size_t count, unsigned threads, const std::function<bool(double)>& progress,
                    const std::function<double()>& fraction, Work&& work)
{
    return pvs::parallel_items(count, threads, progress, fraction, shared.stop, [] { return Scratch{}; },
                               std::forward<Work>(work));
}

} // namespace

ReferenceRay reference_ray(uint64_t seed, uint32_t region, uint64_t index)
{
    const uint64_t key = sampling::sample_key(seed, kVolumeStream, region, index);
    ReferenceRay ray;
    for (int k = 0; k < 4; ++k)
        ray.u[k] = sampling::hash_unit(key, uint64_t(k));
    ray.direction =
        sampling::stratified_direction(uint32_t(index), sampling::sample_key(seed, kVolumeStream, region, ~uint64_t{0}));
    return ray;
}

Pvs bake_reference_vis(const Zone& zone, const ReferenceParams& params, ReferenceReport* report_out)
{
    const auto start = std::chrono::steady_clock::now();
    const TreeTracer tracer(zone.tree, zone.regions, params.sky);
    if (!tracer.has_tree())
        throw std::invalid_argument("the zone has no BSP tree to trace sight lines through");
    const uint32_t regions = uint32_t(zone.region_count());
    const RegionSampler volumes(zone);
    PortalOptions portal_options;
    portal_options.sky = params.sky;
    const PortalSampler portals(build_zone_portals(zone, portal_options), regions);
    WitnessRows rows(regions);

    ReferenceReport report;
    report.threads = params.threads ? params.threads : std::max(1u, std::thread::hardware_concurrency());
    for (uint32_t r = 0; r < regions; ++r)
        report.regions_without_volume += volumes.has_volume(r) ? 0 : 1;

    const Aabb world = zone_portal_world(zone);
    Shared shared{tracer, volumes, portals, rows, {}, params.seed,
                  world.empty() ? 0.0 : glm::length(glm::dvec3(world.max) - glm::dvec3(world.min)) * 1.001};
    // Volume line indices feed a 32-bit (0,2)-sequence: at most 2^32 per region.
    const uint64_t max_samples = std::clamp<uint64_t>(params.max_samples, 1, uint64_t{1} << 32);
    const uint64_t initial = std::min<uint64_t>(std::bit_ceil(std::max<uint32_t>(params.initial_samples, 1)), max_samples);
    const uint64_t initial_frontier = std::max<uint32_t>(1, params.initial_frontier_samples);
    // Progress: lines so far against the volume lines of every round up to max_samples (the
    // frontier's share is not known in advance, so the bar may reach its end early or jump).
    const double planned = 2.0 * double(regions - report.regions_without_volume) * double(max_samples);
    auto fraction = [&] { return planned > 0 ? std::min(1.0, double(shared.lines.load()) / planned) : 1.0; };

    uint64_t bits_before = rows.count();
    bool cancelled = false;
    for (uint64_t first = 0, end = initial, round = 0; first < end && !cancelled; ++round) {
        const std::vector<uint64_t> before = rows.snapshot();
        shared.before = before;
        ReferenceRound summary;
        // Volume lines: the next indices of every region's stream, up to `end` in all.
        cancelled = !parallel_items(shared, regions, report.threads, params.progress, fraction,
                                    [&](size_t r, Scratch& scratch) {
                                        sample_volume(shared, uint32_t(r), first, end, scratch);
                                    });
        // Frontier lines: every frontier pair of the rows as the round began, its next indices.
        if (!cancelled) {
            const std::vector<FrontierPair> frontier = frontier_pairs(before, regions, portals);
            const uint64_t f_first = initial_frontier * ((uint64_t{1} << round) - 1);
            const uint64_t f_end = initial_frontier * ((uint64_t{2} << round) - 1);
            shared.frontier_found.store(0);
            cancelled = !parallel_items(shared, frontier.size(), report.threads, params.progress, fraction,
                                        [&](size_t k, Scratch& scratch) {
                                            sample_frontier(shared, frontier[k], f_first, f_end, scratch);
                                        });
                summary.frontier_pairs = frontier.size();
            summary.frontier_found = shared.frontier_found.load();
        }
        if (cancelled)
            break;
        summary.samples_per_region = end;
        summary.rays = shared.lines.load();
        summary.bits = rows.count();
        summary.new_bits = summary.bits - bits_before;
        summary.seconds = seconds_since(start);
        bits_before = summary.bits;
        report.rounds.push_back(summary);
        if (params.on_round)
            params.on_round(summary, rows.to_pvs());
        if (report.rounds.size() > 1 && summary.new_share() < params.converge_share) {
            report.converged = true;
            break;
        }
        first = end;
        end = std::min(end * 2, max_samples);
    }
    if (params.progress && !cancelled)
        params.progress(1.0);

    Pvs pvs = rows.to_pvs();
    report.cancelled = cancelled;
    report.rays = shared.lines.load();
    report.rejected_samples = shared.rejected.load();
    report.seconds = seconds_since(start);
    report.mean_visible = regions ? double(rows.count()) / double(regions) : 0.0;
    report.peak_bytes_estimate =
        2 * rows.memory_bytes() + volumes.memory_bytes() + portals.memory_bytes() + pvs.memory_bytes();
    if (report_out)
        *report_out = std::move(report);
    return pvs;
}

} // namespace pvs
