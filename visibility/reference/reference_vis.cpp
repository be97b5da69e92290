#include "visibility/reference/reference_vis.h"

#include "visibility/worker_pool.h"

#include "visibility/portal/portalize.h"
#include "visibility/reference/line_witness.h"
#include "visibility/reference/point_walk.h"
#include "visibility/reference/portal_sampler.h"
#include "visibility/reference/region_sampler.h"
#include "visibility/reference/sample_sequence.h"
#include "visibility/reference/tree_trace.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

namespace pvs {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Salts that keep the two samplers' streams apart.
constexpr uint64_t kVolumeStream = 0x564f4c554d45ull;   // "VOLUME"
constexpr uint64_t kWalkStream = 0x57414c4bull;         // "WALK"

// Of every kInteriorEvery eyes on a portal, one is uniform on the portal and the others are on its
// boundary, kEyeInset inside it (see reference_vis.h, "Walks").
constexpr uint64_t kInteriorEvery = 4;
constexpr double kEyeInset = 6.0 * kBeamMargin;

// What every worker reads, and the counters they share.
struct Shared {
    const TreeTracer& tracer;
    const RegionSampler& volumes;
    const PortalSampler& portals;
    const PortalWalker& walker;
    WitnessRows& rows;
    std::span<const uint64_t> before; // the rows when the round began: what counts as new
    // Per source: row A holds the regions A's own lines have proved visible from A (what A's
    // walks skip); nullptr otherwise.
    WitnessRows* own;
    uint64_t seed;
    Aabb world; // lines end where they leave it (zone_portal_world: where regions are taken)
    std::atomic<uint64_t> lines{0};
    std::atomic<uint64_t> rejected{0};
    std::atomic<uint64_t> walks{0};
    std::atomic<uint64_t> truncated_walks{0};
    std::atomic<bool> stop{false};
};

// Per-worker scratch, kept across items so nothing is allocated per line.
struct Scratch {
    TreeTracer::Scratch trace;
    Stretch stretch;
    PortalWalker::Scratch walk;
};

// Sets the pairs of the line's open stretch; per source, also the pairs of `source` it proves in
// `source`'s own row.
void prove(Shared& s, uint32_t source, const glm::dvec3& point, const glm::dvec3& direction, Scratch& scratch)
{
    scratch.stretch.regions.clear();
    if (!open_stretch(s.tracer, point, direction, s.world, scratch.trace, scratch.stretch))
        return;
    if (s.own)
        witness_source_pairs(s.tracer, point, direction, scratch.stretch, source, *s.own, scratch.trace);
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
        prove(s, r, point, sampling::stratified_direction(uint32_t(i), shift), scratch);
    }
    s.lines.fetch_add(end - first, std::memory_order_relaxed);
    s.rejected.fetch_add(rejected, std::memory_order_relaxed);
}

// Eye i of region r (whose portals are `out_of`): on portal i mod |out_of|, the (i / |out_of|)-th
// eye there. Three in four lie on the portal's boundary, kEyeInset inside it, at the next point
// of a shifted van der Corput sequence along the perimeter; the fourth is uniform on the portal.
glm::dvec3 walk_eye(const Shared& s, uint32_t r, std::span<const PortalSampler::Link> out_of, uint64_t i)
{
    const uint64_t slot = i % out_of.size(), on_portal = i / out_of.size();
    const uint32_t portal = out_of[slot].portal;
    const uint64_t key = sampling::sample_key(s.seed, kWalkStream, r, i);
    if (on_portal % kInteriorEvery == kInteriorEvery - 1)
        return s.portals.point(portal, sampling::hash_unit(key, 0), sampling::hash_unit(key, 1),
                               sampling::hash_unit(key, 2));
    const uint64_t shift = sampling::sample_key(s.seed, kWalkStream, r, ~slot);
    const uint64_t boundary_index = on_portal - on_portal / kInteriorEvery; // the boundary eyes' own count
    return s.walker.boundary_point(portal, sampling::stratified_unit(uint32_t(boundary_index), uint32_t(shift)),
                                   kEyeInset);
}

// Walks [first, end) of region r's stream (point_walk.h): from each eye, a line through the
// window of every region the walk reaches that r did not see when the round began. (The rows as
// the round began, not as they are: what other threads have found must not change which lines
// are traced.) Per source: every region r's own lines have not proved so far (only r's worker
// writes that row, in a fixed order).
void sample_walks(Shared& s, uint32_t r, uint64_t first, uint64_t end, Scratch& scratch)
{
    const std::span<const PortalSampler::Link> out_of = s.portals.links(r);
    if (out_of.empty())
        return;
    const std::span<const uint64_t> seen =
        s.own ? s.own->row(r) : s.before.subspan(size_t(r) * s.rows.words_per_row(), s.rows.words_per_row());
    uint64_t lines = 0, truncated = 0;
    for (uint64_t i = first; i < end; ++i) {
        const glm::dvec3 eye = walk_eye(s, r, out_of, i);
        s.walker.walk(eye, out_of[i % out_of.size()].portal, r, scratch.walk);
        truncated += scratch.walk.truncated ? 1 : 0;
        for (const PortalWalker::Sight& sight : scratch.walk.sights) {
            if ((seen[sight.region >> 6] >> (sight.region & 63)) & 1u)
                continue;
            const glm::dvec3 d = sight.aim - eye;
            const double length = glm::length(d);
            if (!(length > 0.0))
                continue;
            prove(s, r, eye + 0.5 * d, d / length, scratch); // from a point surely off the portal
            ++lines;
        }
    }
    s.walks.fetch_add(end - first, std::memory_order_relaxed);
    s.truncated_walks.fetch_add(truncated, std::memory_order_relaxed);
    s.lines.fetch_add(lines, std::memory_order_relaxed);
}

// parallel_items (worker_pool.h) with the reference's stop flag and scratch.
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
    const PortalSet portal_set = build_zone_portals(zone, portal_options);
    const PortalSampler portals(portal_set, regions);
    const PortalWalker walker(portal_set, portals, regions);
    WitnessRows rows(regions);

    ReferenceReport report;
    report.threads = thread_count(params.threads, zone.region_count());
    for (uint32_t r = 0; r < regions; ++r)
        report.regions_without_volume += volumes.has_volume(r) ? 0 : 1;

    std::optional<WitnessRows> own;
    if (params.per_source)
        own.emplace(regions);
    // The regions whose lines are traced: params.sources (a shard's), else every region.
    for (uint32_t r : params.sources)
        if (r >= regions)
            throw std::invalid_argument("reference: source " + std::to_string(r) + " of " + std::to_string(regions));
    const size_t source_count = params.sources.empty() ? regions : params.sources.size();
    const auto source = [&](size_t item) { return params.sources.empty() ? uint32_t(item) : params.sources[item]; };

    const Aabb world = zone_portal_world(zone);
    Shared shared{tracer, volumes, portals, walker, rows, {}, own ? &*own : nullptr, params.seed, world};
    // Volume line indices feed a 32-bit (0,2)-sequence: at most 2^32 per region.
    const uint64_t max_samples = std::clamp<uint64_t>(params.max_samples, 1, uint64_t{1} << 32);
    const uint64_t initial = std::min<uint64_t>(std::bit_ceil(std::max<uint32_t>(params.initial_samples, 1)), max_samples);
    // Progress: the work done against the work of every round up to max_samples, a walk counted
    // as kWalkCost lines (its measured cost on e1m1). The lines aimed by walks are not known in
    // advance; they are few (under a line per walk), so the bar may end a little early.
    constexpr double kWalkCost = 300.0;
    uint32_t regions_with_portals = 0, sources_with_volume = 0;
    for (size_t i = 0; i < source_count; ++i) {
        regions_with_portals += portals.links(source(i)).empty() ? 0 : 1;
        sources_with_volume += volumes.has_volume(source(i)) ? 1 : 0;
    }
    const double planned =
        double(sources_with_volume) * double(max_samples) +
        kWalkCost * double(regions_with_portals) * double(params.initial_walks) * double(max_samples / initial);
    auto fraction = [&] {
        const double done = double(shared.lines.load()) + kWalkCost * double(shared.walks.load());
        return planned > 0 ? std::min(1.0, done / planned) : 1.0;
    };

    uint64_t bits_before = rows.count();
    bool cancelled = false;
    for (uint64_t first = 0, end = initial, round = 0; first < end && !cancelled; ++round) {
        const std::vector<uint64_t> before = own ? std::vector<uint64_t>{} : rows.snapshot();
        shared.before = before;
        ReferenceRound summary;
        // Volume lines: the next indices of every region's stream, up to `end` in all.
        cancelled =
            !parallel_items(shared, source_count, report.threads, params.progress, fraction,
                            [&](size_t i, Scratch& scratch) { sample_volume(shared, source(i), first, end, scratch); });
        // Walks: the next eyes of every region's stream, doubling like the volume lines.
        const uint64_t walks_end = uint64_t(params.initial_walks) << round;
        if (!cancelled && walks_end > 0)
            cancelled = !parallel_items(
                shared, source_count, report.threads, params.progress, fraction, [&](size_t i, Scratch& scratch) {
                    sample_walks(shared, source(i), round == 0 ? 0 : walks_end / 2, walks_end, scratch);
                });
        if (cancelled)
            break;
        summary.samples_per_region = end;
        summary.eyes_per_region = walks_end;
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
    report.walks = shared.walks.load();
    report.truncated_walks = shared.truncated_walks.load();
    report.seconds = seconds_since(start);
    report.mean_visible = regions ? double(rows.count()) / double(regions) : 0.0;
    report.peak_bytes_estimate = 2 * rows.memory_bytes() + (own ? own->memory_bytes() : 0) + volumes.memory_bytes() +
                                 portals.memory_bytes() + pvs.memory_bytes();
    if (report_out)
        *report_out = std::move(report);
    return pvs;
}

} // namespace pvs
