// The portal-vis baker: a PVS from a zone's portals, as Quake's vis does it
// (../shared/formats/quake-doom-hepvs.md §2.5, §3.1-§3.5, §3.7-§3.8; ericw-tools vis as of 2023).
//
// Input. A PortalSet whose portals follow PRT1's orientation (build_portals and quake::parse_prt
// both give it): the plane of a portal's first three points, n = normalize((p0-p1) x (p2-p1)),
// points into regions[0]. Each portal becomes two directed portals (§2.5, §3.1): 2i, stored in
// regions[0], leads into regions[1] with the negated plane and the points as given; 2i+1,
// stored in regions[1], leads into regions[0] with the plane as computed and the points
// reversed. Every directed plane's normal points into the region the portal leads to. Portals
// that cannot be used are skipped and counted (VisReport::portals_skipped): a region out of
// [0, region_count), the same region on both sides, fewer than three points, or no area (when
// the first three points are colinear the plane comes from all points, Newell's method).
//
// Method::Fast, base portal vis (§3.2). For each directed portal p, the portals it might see
// through its destination pass ericw's tests: the target is not behind p (a vertex beyond
// +ON_EPSILON, or all vertices within ON_EPSILON: coplanar), p is not entirely in front of the
// target (a vertex of p below -ON_EPSILON, or coplanar), and a coplanar pair facing each other
// (dot of normals < -0.99) is rejected; bounding spheres reject first. p.mightsee is the flood
// from p's destination through the portals that pass. The tests are evaluated lazily, only for
// the portals the flood meets (the same result as testing every pair, at a fraction of the
// cost). Fast uses mightsee as the final visbits: a loose, over-inclusive PVS.
//
// Method::Full, portal flow (§3.3, §3.4). For each directed portal, a depth-first walk through
// the portal chain from its destination, clipping as ericw's RecursiveLeafFlow does: the
// mightsee prune, the "nothing new" prune, the coplanar-exit prune (normals equal within 0.001
// per component), the target clipped by the source's and the pass's planes, the source clipped
// behind the target, then the separating planes of test levels 0-4 (ClipToSeparators: for each
// edge of A the first vertex of B giving a plane with all of B in front, none of B below
// -ON_EPSILON, degenerate when |cross|^2 < 0.1; tests 1 and 3 mirrored). Clips keep "on"
// points, return an all-on winding unclipped, and give up (keep the input, conservative) when
// a result would exceed 24 points. One departure from ericw, so that no sight line the
// reference can prove is lost: a winding with no point beyond +ON_EPSILON but some beyond
// kDropEpsilon (0.02, below the reference's beam margin of 0.05) is kept whole where ericw
// drops it (such drops lost sight lines up to 0.1 wide: two directed pairs on Freedoom 2 MAP10
// with --heights). It adds a few bits (the six id maps: 0.01-0.06 %). The planes of tests 0 and 1 depend only on the previous
// frame, so they are cached per frame and re-applied to every target; they are found edge by
// edge as targets need them, and every target meets all of them in the same order (ericw
// caches only the ones found while clipping its first target, a partial set when that target
// was clipped away).
// A leaf already on the chain is not entered again (counted in VisReport::leaf_recursions).
//
// Passages (Method::Full; after q3map's passage vis). Before the flow, for every directed
// portal a and every portal b leaving a's destination, the leaves a line through a and then b
// can reach: a flood from b's destination through the portals that survive a's plane, b's plane
// and the separating planes between a and b' (b clipped to the front of a; test 0 at level >= 1,
// test 1 mirrored at level >= 2), restricted to a.mightsee & b.mightsee, bounding spheres first.
// A line crossing a, b, then r1..rk crosses each r_i in front of a and b and inside the
// separators, so every leaf it reaches is in the flood: the rows are conservative. The flow
// then ANDs the row of (the portal it came in by, the target) into the child's mightsee, and
// a target whose own leaf is not in that row is skipped; each portal's mightsee is first
// narrowed to its destination plus its passages' rows. In exact arithmetic these only remove
// branches that could not add a leaf (the flow's own clips are tighter than a passage's); with
// the epsilons, the windings kept whole and the 24-point give-up a row can differ: on e1m2 the
// flow without passages holds 2 bits more, neither a bit the reference proves
// (tests/wld/test_portal_vis.cpp checks that), at about half the time (docs/performance.md). They cost one row per pair (pairs = sum over directed portals of
// the portals leaving their destination), kept as the span of words that hold set bits (on
// e1m1 55 000 pairs spanning 5 of 19 words on average, about 3.5 MB); when the rows would
// exceed VisParams::passage_budget_bytes the flow runs without them (a decision that depends
// on their total size only, so the result stays deterministic).
//
// Target checks (Method::Full; after ericw's target checks, §3.6, restricted). A walk that
// enters a leaf already in the portal's visbits can only matter for the leaves it could still
// add: those of the child's mightsee not yet visible. Before walking on, when there are at most
// 64 of them, each is checked: a portal into it is clipped to the front of the head's plane and
// of the pass's plane, then by the frame's separators of tests 0 and 1 (the planes the walk
// below would cache first anyway). A leaf none of whose portals survives is removed from the
// child's mightsee; when no leaf survives, the leaf is left at once. In exact arithmetic this
// removes nothing visible: a line from the source through the pass that reaches such a leaf
// crosses one of its portals inside those planes. It can remove a bit the plain flow sets
// where the flow's own approximations (epsilons, first separator per edge, the 24-point
// give-up) let a portal through deeper down that the check's planes already exclude: on the
// six maps in ../shared/data/quake, 2 bits in all (e1m2, end), neither set by the maps' own
// vis either (tests/wld/test_portal_vis.cpp checks it). About a third of the flow's time on
// those maps (docs/performance.md). VisParams::target_checks turns them off.
//
// Symmetry (Method::Full, beyond ericw). A line from the head portal's region A through target
// q, reversed, leaves q's region through q's twin and reaches A; so when the twin's prune row
// (its visbits once final, else its mightsee: the rule of Determinism below) lacks A, the walk
// does not go on through q. The twin's flow is conservative, so no sight line is lost; it
// removes bits the flow's separators cannot (lqdm5 per leaf: mean visible 370.0 -> 368.8).
//
// Dominated windows (Method::Full, window_memo.h): a walk arriving at q with a source, pass and
// mightsee inside those of an earlier walk past q from the same head is skipped (lqdm5 per leaf:
// about 6 % of the walks, a fifth of the time).
//
// Sources (Method::Full, VisParams::source). Source::Portal walks each directed portal on its own,
// as ericw does. Source::Region walks a region's outgoing portals one after the other into one
// row: the "nothing new" prune and the target checks then see what the region's other walks
// already found, and the row a walk prunes with at portal q is the final row of the region q
// leads into (every leaf a line through q reaches is seen from there; a looser bound than q's own
// visbits, which this mode does not make), ranked and lagged per region as below. Fewer frames
// (e1m1: 0.84 million against 1.16), rows about 0.4 % looser (e1m1 mean visible 142.9 against
// 142.3).
//
// Aggregation (§3.5): a region sees the union of its outgoing directed portals' visbits, plus
// itself (VisReport::saw_into_own_region counts regions that already saw themselves, ericw's
// "portals saw into leaf" warning).
//
// Determinism. The result depends on nothing but the input and VisParams::method/level: not on
// the thread count, not on timing. Base vis is per-portal independent. In the flow, ericw lets
// a portal prune with the finished visbits of other portals (the "nothing new" test and the
// narrowed mightsee of the next frame use q.visbits when q is done, else q.mightsee); that is a
// big speed-up, but which portals happen to be done depends on timing, and the flow's
// approximations (24-point give-up, first separator per edge, epsilons) make the result depend
// on it slightly. Here the portals are ranked once by increasing nummightsee (ties by index),
// handed to the threads in rank order, and portal p prunes with q.visbits exactly when
// rank(q) + kPruneLag < rank(p), otherwise with q.mightsee. If such a q is still being worked
// on when p needs it, p's thread waits for it (q was handed out earlier, and q itself only
// waits for lower ranks, so this cannot deadlock). With one thread nothing ever waits and the
// result is a fixed function of the ranking; with more threads it is the same function. The
// lag leaves the last few portals handed out unused as pruning sets so that threads seldom
// wait for each other (measured in docs/architecture.md, "Portal vis").
//
// Threads, progress, cancellation. VisParams::threads workers (0 = hardware concurrency) take
// portals from a shared counter (one thread and no progress callback: the calling thread does
// the work itself); otherwise the calling thread only watches: it calls
// VisParams::progress(fraction) once before any work (fraction 0), then about every 50 ms, and
// once with 1.0 at the end, always on the calling thread. Returning false cancels: the workers
// stop within a few thousand flow steps, and the returned PVS is conservative: rows from
// finished portals' visbits and unfinished portals' mightsee (a superset of the full result,
// a subset of the fast one), or every region visible when base vis had not finished.
// VisReport::cancelled says so. An exception thrown by the callback stops the workers and is
// rethrown.
//
// Speed (tests/bench/bench_vis.cpp, docs/performance.md "Portal vis"). The flow's time
// goes to finding separators (test 0-3) and clipping windings by them, a few dozen dot products
// per step on windings of about four points. ClipToSeparators finds the sides of B against A's
// plane once per (A, B) pair instead of once per edge of A, tests a candidate plane with its
// unnormalised normal (d^2 against ON_EPSILON^2 with d's sign: no square root or division for
// the candidates that fail) starting from the candidate's neighbours on B (where a failing
// candidate fails), and normalises only the plane it returns; clips classify
// points without branches; passages (above) then halve the number of flow steps, and target
// checks (above) cut another third. The benchmark's baseline is this baker with passages and
// target checks off.
//
// Memory. Two bit rows per directed portal (mightsee, visbits), dense (64-bit words of
// region_count bits) only while a worker builds them, then kept as runs of nonzero words
// (run_rows.h: a portal's leaves sit in a few runs, as leaf numbers follow the tree; on the
// generated 1500-room zone 6.8 of 198 words for visbits), in pools that never move; the flow
// reads them as runs and only over the words they span. The passage rows (above), kept the
// same way; the portals' points in double; and per thread a stack of frames, grown only when
// a walk goes deeper than before (a frame holds three fixed 24-point windings, the cached
// separators and a dense mightsee, ericw's pstack_t): no allocation inside the walk otherwise.
// Figures in docs/performance.md, "Memory of the bake".
#pragma once

#include "visibility/portal/flow_chain.h"
#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace pvs {

struct VisParams {
    enum class Method : uint8_t { Fast, Full };
    Method method = Method::Full;
    int level = 4;        // Full: separator test level 0..4 (clamped), ericw's default 4
    unsigned threads = 0; // 0 = std::thread::hardware_concurrency()
    // Full: passages are built when their rows take at most this many bytes (0 = never).
    size_t passage_budget_bytes = size_t{64} << 20;
    // Full: target checks (above) before walking on from a leaf already visible.
    bool target_checks = true;
    // Full, 3-D flow: the symmetry prune and the dominated windows (above); both off is ericw's flow
    // (with passages and target checks, which change no real bit either).
    bool symmetry = true;
    bool dominated_windows = true;
    // Full: what a walk starts from. Portal: each directed portal walks on its own (Quake's vis;
    // a region then sees the union of its portals' rows). Region: the walks of a region's portals
    // share one row, so a walk stops where its siblings already saw what it could add, and the
    // rows a walk prunes with are regions' (see "Sources" above). The 2-D flow always walks per
    // region.
    enum class Source : uint8_t { Portal, Region };
    Source source = Source::Portal;
    // Called on the calling thread with the fraction done in [0, 1]; return false to cancel.
    std::function<bool(double fraction)> progress;
    // Full: when given, the flow records the chains along which it reached probe->to from
    // probe->from (flow_chain.h); the result is the same. Its `found` is resized by the bake.
    ChainProbe* probe = nullptr;
};

struct VisReport {
    double seconds = 0.0;          // the whole bake, wall clock
    double base_seconds = 0.0;     // of which base vis (mightsee)
    size_t portals = 0;            // input portals used (each gives two directed portals)
    size_t portals_skipped = 0;    // input portals that could not be used (see above)
    double mean_visible = 0.0;     // mean set bits per row of the result
    bool cancelled = false;
    size_t peak_bytes_estimate = 0; // the bake's largest heap use, estimated from its arrays
    unsigned threads = 0;          // worker threads used
    size_t saw_into_own_region = 0; // regions whose portals' visbits held the region itself
    size_t leaf_recursions = 0;    // Full: walks that met a region already on their chain
    // Full: the leaves the walks entered (a walk's step into a leaf, ericw's recursions), and the
    // sum over directed portals of the leaves each sees. Every walk enters each leaf its portal
    // sees at least once, so portal_visible is the fewest frames any per-portal flow can enter
    // for this result: frames / portal_visible is how much the flow walks beyond that.
    size_t frames = 0;
    size_t portal_visible = 0;
    double wait_seconds = 0.0;     // Full: time worker threads spent waiting for an older portal
    size_t passage_pairs = 0;      // Full: passages built (0: none, over the budget)
    double passage_seconds = 0.0;  // Full: of the bake's time, building them
    size_t target_checks = 0;       // Full: target checks made
    size_t target_check_prunes = 0; // Full: of which found that the walk could add no leaf
    size_t dominated_windows = 0;   // Full: walks skipped, held by an earlier window (window_memo.h)
    // Full, the flow's work beyond frames: windings (segments in 2-D) clipped, separating planes
    // (lines) found and used, and in 2-D the separator candidates tried. Like frames, a fixed
    // function of the input and the parameters, whatever the thread count.
    size_t clips = 0;
    size_t separators = 0;
    size_t separator_candidates = 0;
};

// Portals older than this many ranks are used for pruning (see Determinism above). Part of the
// definition of the result: changing it may change the PVS slightly.
inline constexpr uint32_t kPruneLag = 32;

// The PVS of `region_count` regions from `portals` (regions[] are region ids). Regions with
// no portal see only themselves. `report`, when given, is overwritten.
Pvs bake_portal_vis(const PortalSet& portals, uint32_t region_count, const VisParams& params,
                    VisReport* report = nullptr);

} // namespace pvs
