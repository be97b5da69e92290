// The sampled reference: ground truth for every PVS pvscope bakes or reads. Region A sees region
// B when some segment from a point of A to a point of B stays in open space; this estimates
// that relation from below by tracing sight lines and keeping what they prove.
//
// Sampling. Ray i of region A starts at a point uniform in A's volume (region_sampler.h: its
// convex cells, not its box), drawn from a counter-based hash of (seed, A, i), and goes in a
// direction uniform on the sphere, stratified: point i of the (0,2)-sequence of Sobol's first two
// dimensions, digitally shifted per region, through the equal-area map (z = 1 - 2u, phi = 2 pi v),
// so the first 2^k directions of a region fill every elementary box of the unit square once. Each
// ray is traced through the tree (tree_trace.h: exact in double, the content rule of media.h)
// until it enters a solid, outside or opaque leaf, or leaves the world box. A sample whose trace
// does not start in A (a point in the cells' epsilon margin) is rejected and counted.
//
// What a ray proves. Every region the ray passes through is visible from A, and more: any two
// regions X and Y on its open stretch see each other, since the part of the ray between them is
// itself such a segment (and the content rule is symmetric). So a ray crossing k regions may set
// the k x k pairs among them, rows and columns alike; a pair is set only when its segment is open
// as a beam kBeamMargin wide (line_witness.h: lines that only graze a corner or slip through a
// sub-epsilon gap prove nothing). Every bit set is witnessed by a segment through open space: the result is a LOWER
// bound of the true PVS (what a PVS must contain not to pop), where a conservative portal vis is an upper bound.
// Symmetric by construction.
//
// Walks. Volume lines find wide openings quickly and narrow ones (a sight line through two
// doorways far apart) slowly: both ends must fall in the thin set of lines that pass. So each round
// also walks from eyes on every region's portals (point_walk.h): from one eye the walk finds, by
// clipping portals to the cone through the portals before them, every region the eye sees, and
// for each that the region did not see when the round began a line is traced from the eye through
// the walk's window into it. The walk only aims: the line proves what it traces, like any other.
// A sight line from A leaves A through one of its portals, so eyes on A's portals see all A sees.
// Three in four eyes lie on the portal's boundary, 6 * kBeamMargin inside it, stratified along
// the perimeter; one in four anywhere on the portal. Lines that see round a corner best start at
// the door frame (on e1m1, with the eyes uniform on the portals the last doubling to 2048 lines
// per region still added 0.149 % of the bits; with three in four on the boundary, 0.060 %), and
// the interior eyes keep the sight lines that pass only a portal's middle within reach.
//
// Convergence. Rounds double the lines: round 0 traces params.initial_samples volume lines per
// region and walks params.initial_walks eyes; round k brings the totals to 2^k times those (the
// new lines and eyes are the next indices, so every round's total is stratified again). After
// each round the new bits are counted; the bake stops after a round whose new bits are fewer than
// converge_share of all bits (it is then "converged"), or when the total would pass max_samples,
// or on cancel. The report lists every round (lines, bits, new bits, time): how close it came.
// Measured (docs/performance.md): e1m1 converges (under 0.1 % new on a doubling) at 2048 volume
// lines and 256 eyes per region, in about 21 s on 2 cores.
//
// Deterministic for a seed: line i and eye i of region A depend only on the seed, A and i, the
// lines a walk aims only on its eye and the rows when the round began, and bits are only ever
// OR-ed in, so neither the thread count nor timing changes the result.
//
// Sources (ReferenceParams::per_source). By default a walk skips the regions that any region's
// lines had proved visible from its region when the round began, so region A's lines depend on
// every other region's. Per source, A's walks skip the regions that A's own lines have proved
// visible from A so far (the same beam test, line_witness.h: witness_source_pairs; its volume
// lines and the lines its walks aimed, in their fixed order), and nothing else. With a fixed
// budget (converge_share 0: every round up to max_samples) every line of A is then a function of
// the seed, A and the budget, and the bits are the OR over regions of what their lines prove: a
// bake of some regions' lines (ReferenceParams::sources, a shard) sets exactly the bits those
// lines set in the whole bake, and the OR of the shards is the whole bake. On e1m1 at 2048 lines
// a region it finds the same mean visible (141.3) with 13 % fewer lines (a walk skips what the
// region's earlier eyes in the same round found) at about the same time, and keeps a second
// matrix (each region's own proved row).
//
// Threads, progress, cancel: as bake_portal_vis (params.threads workers, 0 = all cores; the
// calling thread calls progress(fraction) about every 50 ms with the fraction done of the work up
// to max_samples, walks included, and at 1; false cancels: the rows found so far are returned,
// still a lower bound, and report.cancelled is set). on_round, when set, is called on the calling thread after
// each finished round with the rows so far (compare keeps them as the reference at that count).
//
// Memory: the rows as a dense bit matrix while sampling (regions^2 / 8 bytes: 182 KB for e1m1,
// 230 MB for a 43 000-region zone), the sampler's tetrahedra, the portals in double for the
// walks, and per thread a small stack and the walk's scratch.
// Zones without a tree are refused: every zone pvscope loads today has one (a mesh tracer for
// tree-less OBJ zones comes with them).
#pragma once

#include "visibility/portal/media.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace pvs {

struct ReferenceRound {
    uint64_t samples_per_region = 0; // rays per region so far (the round's total)
    uint64_t rays = 0;               // lines traced so far (volume and aimed by walks, rejected samples included)
    uint64_t bits = 0;               // set bits of all rows after this round
    uint64_t new_bits = 0;           // of which this round found
    double seconds = 0.0;            // wall clock since the bake started
    uint64_t eyes_per_region = 0;    // eyes walked per region so far (point_walk.h)
    double new_share() const { return bits ? double(new_bits) / double(bits) : 0.0; }
};

struct ReferenceParams {
    uint64_t seed = 1;
    uint32_t initial_samples = 64;     // volume lines per region in round 0 (rounded up to a power of two)
    uint32_t initial_walks = 8;        // eyes walked per region in round 0 (point_walk.h); 0: none
    uint64_t max_samples = 8192;       // volume lines per region at most (e1m1: converged at 2048)
    double converge_share = 0.001;     // stop after a round adding fewer than this share of the bits; 0: never
    SkyPortals sky = SkyPortals::SkyToSky;
    unsigned threads = 0;              // 0 = std::thread::hardware_concurrency()
    // Per source (see "Sources" above): a region's walks aim by what its own lines proved, so
    // every line of region A depends on the seed, A and the budget alone.
    bool per_source = false;
    // Trace only these regions' lines (a shard's; with per_source and converge_share 0 the bits
    // are then exactly those the same lines set in the whole bake). Empty: every region's.
    std::span<const uint32_t> sources;
    std::function<bool(double fraction)> progress;
    std::function<void(const ReferenceRound& round, const Pvs& rows)> on_round;
};

struct ReferenceReport {
    std::vector<ReferenceRound> rounds;
    bool converged = false;            // the last round added fewer than converge_share of the bits
    bool cancelled = false;
    uint64_t rays = 0;
    uint64_t rejected_samples = 0;     // samples whose trace did not start in their region
    uint64_t walks = 0;                // eyes walked
    uint64_t truncated_walks = 0;      // of which stopped at the walk's depth limit or window budget
    uint32_t regions_without_volume = 0; // regions with nothing to sample (they see only themselves)
    double seconds = 0.0;
    unsigned threads = 0;
    double mean_visible = 0.0;
    size_t peak_bytes_estimate = 0;
};

// Throws std::invalid_argument for a zone without a BSP tree (nothing to trace here).
Pvs bake_reference_vis(const Zone& zone, const ReferenceParams& params, ReferenceReport* report = nullptr);

// The ray of index i of a region, as the bake draws it (exposed for tests and the inspector):
// u[0..3] for RegionSampler::point, and the unit direction.
struct ReferenceRay {
    double u[4];
    glm::dvec3 direction;
};
ReferenceRay reference_ray(uint64_t seed, uint32_t region, uint64_t index);

} // namespace pvs
