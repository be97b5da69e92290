// The portal-vis baker (see portal_vis.h for the method, the determinism rule and the limits).
//
// Layout, after ericw-tools vis: directed portals in one array (2i forward, 2i+1 backward, the
// twin of d is d^1), their points in one array of doubles, the portals leaving each region as
// compressed rows (leaf_first / leaf_portals), and every bit set (mightsee, visbits) as rows of
// 64-bit words in one flat array per kind. The flow is ericw's RecursiveLeafFlow written as a
// loop over an explicit stack of frames, so deep chains cannot overflow a thread's stack, and a
// frame's windings live in the frame (three fixed 24-point windings, like pstack_t).
#include "visibility/portal/portal_vis.h"

#include "visibility/bit_row.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cassert>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace pvs {
namespace {

// ericw-tools vis constants (§3.7).
constexpr double kOnEpsilon = 0.1;            // VIS_ON_EPSILON: side tests, clips, separators
constexpr double kEqualEpsilon = 0.001;       // VIS_EQUAL_EPSILON: coplanar exit, per component
constexpr double kCoplanarFacing = -0.99;     // base vis: coplanar portals facing each other
constexpr double kSeparatorMinLengthSq = 0.1; // ClipToSeparators: unnormalised |cross|^2
constexpr uint32_t kStackPoints = 24;         // MAX_WINDING_FIXED: points of a frame's winding
constexpr int kStackWindings = 3;             // STACK_WINDINGS: windings per frame
constexpr uint32_t kMaxSeparators = 64;       // MAX_SEPARATORS: cached planes per test per frame
constexpr uint32_t kCancelCheckSteps = 1024;  // flow steps between looks at the cancel flag
constexpr double kBaseWeight = 0.1;           // Full: share of the progress bar given to base vis
constexpr double kPassageWeight = 0.1;        // Full: share given to the passages, when built
constexpr uint32_t kTargetCheckLeaves = 16;   // target checks: most unseen leaves worth checking

enum PortalState : uint8_t { kNone = 0, kWorking = 1, kDone = 2, kAborted = 3 };

using Vec = glm::dvec3;

struct DPlane {
    Vec normal{0.0};
    double dist = 0.0;
    double distance(const Vec& p) const { return glm::dot(normal, p) - dist; }
    DPlane flipped() const { return {-normal, -dist}; }
};

struct DirectedPortal {
    DPlane plane;    // normal into `leaf`
    Vec origin{0.0}; // bounding sphere of the winding: centre = mean of the points
    double radius = 0.0;
    uint32_t first_point = 0;
    uint32_t point_count = 0;
    uint32_t leaf = 0;  // the region it leads into
    uint32_t owner = 0; // the region it leaves
};

struct Graph {
    uint32_t leaf_count = 0;
    size_t words = 0;
    std::vector<DirectedPortal> portals;
    std::vector<Vec> points;
    std::vector<uint32_t> leaf_first; // leaf_count + 1 offsets into leaf_portals
    std::vector<uint32_t> leaf_portals;
    uint32_t max_points = 0;
    size_t used = 0;
    size_t skipped = 0;

    size_t bytes() const
    {
        return portals.capacity() * sizeof(DirectedPortal) + points.capacity() * sizeof(Vec) +
               (leaf_first.capacity() + leaf_portals.capacity()) * sizeof(uint32_t);
    }
};

void set_sphere(const Graph& g, DirectedPortal& p)
{
    Vec sum(0.0);
    for (uint32_t i = 0; i < p.point_count; ++i)
        sum += g.points[p.first_point + i];
    p.origin = sum / double(p.point_count);
    double r2 = 0.0;
    for (uint32_t i = 0; i < p.point_count; ++i) {
        const Vec d = g.points[p.first_point + i] - p.origin;
        r2 = std::max(r2, glm::dot(d, d));
    }
    p.radius = std::sqrt(r2);
}

// Directed portals and per-region portal lists from the input (§2.5, §3.1).
Graph build_graph(const PortalSet& set, uint32_t region_count)
{
    Graph g;
    g.leaf_count = region_count;
    g.words = bits::words_for(region_count);
    std::vector<Vec> pts;
    for (const Portal& in : set.portals) {
        const bool regions_ok = in.regions[0] >= 0 && in.regions[1] >= 0 &&
                                uint32_t(in.regions[0]) < region_count && uint32_t(in.regions[1]) < region_count &&
                                in.regions[0] != in.regions[1];
        const bool range_ok = in.point_count >= 3 && in.first_point <= set.points.size() &&
                              in.point_count <= set.points.size() - in.first_point;
        if (!regions_ok || !range_ok) {
            ++g.skipped;
            continue;
        }
        pts.clear();
        bool finite = true;
        for (uint32_t i = 0; i < in.point_count; ++i) {
            const glm::vec3& p = set.points[in.first_point + i];
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            pts.emplace_back(p);
        }
        // The plane of the first three points, normal into regions[0] (§2.5); Newell's normal of
        // all points (the same orientation: id's points are clockwise seen from the normal's
        // side) when those three are colinear.
        Vec n = glm::cross(pts[0] - pts[1], pts[2] - pts[1]);
        double len = glm::length(n);
        if (!(len > 1e-9)) {
            Vec ccw(0.0);
            for (size_t i = 0; i < pts.size(); ++i)
                ccw += glm::cross(pts[i], pts[(i + 1) % pts.size()]);
            n = -ccw;
            len = glm::length(n);
        }
        if (!finite || !(len > 1e-9) || !std::isfinite(len)) {
            ++g.skipped;
            continue;
        }
        n /= len;
        const DPlane plane{n, glm::dot(n, pts[0])};

        const uint32_t first = uint32_t(g.points.size());
        const uint32_t count = uint32_t(pts.size());
        g.points.insert(g.points.end(), pts.begin(), pts.end());             // forward: as given
        g.points.insert(g.points.end(), pts.rbegin(), pts.rend());           // backward: reversed
        const uint32_t r0 = uint32_t(in.regions[0]), r1 = uint32_t(in.regions[1]);
        DirectedPortal forward{plane.flipped(), Vec(0.0), 0.0, first, count, r1, r0};
        DirectedPortal backward{plane, Vec(0.0), 0.0, first + count, count, r0, r1};
        set_sphere(g, forward);
        set_sphere(g, backward);
        g.portals.push_back(forward);
        g.portals.push_back(backward);
        g.max_points = std::max(g.max_points, count);
        ++g.used;
    }
    // Portals leaving each region, in directed-index order (as ericw's leaf lists).
    g.leaf_first.assign(size_t{region_count} + 1, 0);
    for (const DirectedPortal& p : g.portals)
        ++g.leaf_first[p.owner + 1];
    for (uint32_t r = 0; r < region_count; ++r)
        g.leaf_first[r + 1] += g.leaf_first[r];
    g.leaf_portals.resize(g.portals.size());
    std::vector<uint32_t> fill(g.leaf_first.begin(), g.leaf_first.end() - 1);
    for (uint32_t i = 0; i < uint32_t(g.portals.size()); ++i)
        g.leaf_portals[fill[g.portals[i].owner]++] = i;
    return g;
}

// ---------------------------------------------------------------------------------------------
// Base portal vis (§3.2)

// ericw's BasePortalThread tests: may directed portal p see directed portal t (p != t)?
bool portal_might_see(const Graph& g, const DirectedPortal& p, const DirectedPortal& t)
{
    const Vec* pp = &g.points[p.first_point];
    const Vec* tp = &g.points[t.first_point];

    // 1. t is not entirely behind p: a vertex in front, or all on p's plane (coplanar).
    double d = p.plane.distance(t.origin);
    if (d < -t.radius)
        return false;
    bool t_coplanar = false;
    {
        uint32_t not_behind = 0, j = 0;
        for (; j < t.point_count; ++j) {
            d = p.plane.distance(tp[j]);
            not_behind += d > -kOnEpsilon;
            if (d > kOnEpsilon)
                break;
        }
        if (j == t.point_count) {
            if (not_behind != t.point_count)
                return false; // no point in front
            t_coplanar = true;
        }
    }
    // 2. p is not entirely in front of t: a vertex behind t's plane, or all on it.
    d = t.plane.distance(p.origin);
    if (d > p.radius)
        return false;
    bool p_coplanar = false;
    {
        uint32_t not_front = 0, j = 0;
        for (; j < p.point_count; ++j) {
            d = t.plane.distance(pp[j]);
            not_front += d < kOnEpsilon;
            if (d < -kOnEpsilon)
                break;
        }
        if (j == p.point_count) {
            if (not_front != p.point_count)
                return false; // no point behind
            p_coplanar = true;
        }
    }
    // 3. Coplanar exception used: reject a portal facing back at p (p's twin, among others).
    if ((t_coplanar || p_coplanar) && glm::dot(p.plane.normal, t.plane.normal) < kCoplanarFacing)
        return false;
    return true;
}

// p.mightsee: the flood from p's destination through the portals p might see. A portal is
// tested only when the flood meets it and its destination is not marked yet, which gives
// exactly ericw's SimpleFlood over the full portalsee set (a marked leaf is never re-entered).
// Returns nummightsee.
uint32_t base_portal_vis(const Graph& g, uint32_t pi, std::vector<uint32_t>& stack, uint64_t* mightsee)
{
    const std::span<uint64_t> row(mightsee, g.words);
    std::fill(row.begin(), row.end(), 0);
    const DirectedPortal& p = g.portals[pi];
    uint32_t count = 1;
    bits::set(row, p.leaf);
    stack.clear();
    stack.push_back(p.leaf);
    while (!stack.empty()) {
        const uint32_t leaf = stack.back();
        stack.pop_back();
        for (uint32_t k = g.leaf_first[leaf]; k < g.leaf_first[leaf + 1]; ++k) {
            const uint32_t ti = g.leaf_portals[k];
            const DirectedPortal& t = g.portals[ti];
            if (ti == pi || bits::test(row, t.leaf) || !portal_might_see(g, p, t))
                continue;
            bits::set(row, t.leaf);
            ++count;
            stack.push_back(t.leaf);
        }
    }
    return count;
}

// ---------------------------------------------------------------------------------------------
// Full portal flow (§3.3, §3.4)

// A winding seen through a handle: its points belong to a portal (owner == nullptr) or to one
// of a frame's fixed windings. Clipped windings keep their input's sphere (still a bound).
struct WRef {
    const Vec* points = nullptr; // nullptr: no winding
    uint32_t count = 0;
    Vec origin{0.0};
    double radius = 0.0;
    const void* owner = nullptr;
    int slot = -1;

    explicit operator bool() const { return points != nullptr; }
};

// A frame's planes for test 0 or 1, found edge by edge as targets need them: a target is
// clipped by the planes found so far, then by new ones until it is gone or every edge of A has
// been tried. Every target thus meets the same planes in the same order as if all had been
// built first; the ones never needed are never built.
struct SeparatorCache {
    uint32_t next_edge = 0; // edges of A tried so far
    uint32_t count = 0;
    DPlane planes[kMaxSeparators];
    std::vector<int8_t> b_side; // sides_to_plane of B, found with the first edge
};

struct Frame {
    uint32_t leaf = 0;
    uint32_t entry = 0; // the directed portal that led into leaf
    uint32_t cursor = 0, end = 0; // the leaf's outgoing portals still to try
    WRef source, pass;            // for the child frame: what is left of the source, the pass
    DPlane portalplane;           // for the child frame: the plane of the portal it came through
    std::vector<uint64_t> mightsee; // for the child frame; zero outside words [lo, hi)
    uint32_t lo = 0, hi = 0;
    bool slot_used[kStackWindings] = {};
    SeparatorCache separators[2];
    Vec slots[kStackWindings][kStackPoints];

    Frame(size_t words, uint32_t max_points) : mightsee(words, 0)
    {
        for (SeparatorCache& cache : separators)
            cache.b_side.resize(max_points);
    }
};

bool normals_equal(const Vec& a, const Vec& b)
{
    return std::abs(a.x - b.x) <= kEqualEpsilon && std::abs(a.y - b.y) <= kEqualEpsilon &&
           std::abs(a.z - b.z) <= kEqualEpsilon;
}

// Which side of A's plane each point of B lies on (+1 above +ON_EPSILON, -1 below -ON_EPSILON,
// 0 on it): edge_separator's first look at B, the same for every edge of A, so found once.
void sides_to_plane(const WRef& b, const DPlane& a_plane, int8_t* side)
{
    for (uint32_t j = 0; j < b.count; ++j) {
        const double d = a_plane.distance(b.points[j]);
        side[j] = int8_t(int(d > kOnEpsilon) - int(d < -kOnEpsilon));
    }
}

// ericw's separating plane for edge i of winding A and winding B (b_side: sides_to_plane of B
// against A's plane): the first vertex of B making a plane through the edge with B in front
// (none of it below -ON_EPSILON, some of it above +ON_EPSILON) and A behind; `mirror` negates
// it (tests 1 and 3). False when no vertex of B gives one.
// The candidates are tested with the unnormalised normal n, d = dot(n, b - b_j) / |n| compared
// as d^2 against ON_EPSILON^2 with d's sign, so a rejected vertex costs no square root or
// division; the plane returned is computed exactly as ericw's (normalised, then its distance).
bool edge_separator(const WRef& a, const WRef& b, const int8_t* b_side, uint32_t i, bool mirror, DPlane& out)
{
    const Vec ai = a.points[i];
    const Vec v1 = a.points[i + 1 == a.count ? 0 : i + 1] - ai;
    const Vec* bp = b.points;
    const uint32_t bn = b.count;
    for (uint32_t j = 0; j < bn; ++j) {
        if (b_side[j] == 0)
            continue; // on A's plane
        const Vec bj = bp[j];
        const Vec cross = glm::cross(v1, bj - ai);
        const double len_sq = glm::dot(cross, cross);
        if (len_sq < kSeparatorMinLengthSq)
            continue; // the three points make no plane
        // The side of A that holds this vertex of B is the side of the new plane that holds B.
        const Vec n = b_side[j] < 0 ? -cross : cross;
        const double limit = kOnEpsilon * kOnEpsilon * len_sq;
        // B's points from j's neighbours out: on a convex B, a vertex that is not the one the
        // plane wants has a neighbour behind, so most candidates fail at the first look (the
        // order does not change the outcome, every point must pass).
        const double nj = glm::dot(n, bj);
        bool front = false, behind = false;
        for (uint32_t step = 1; step < bn && !behind; ++step) {
            // j+1, j-1, j+2, j-2, ...: every other point once.
            const uint32_t offset = (step & 1) != 0 ? (step + 1) / 2 : bn - step / 2;
            const uint32_t k = j + offset < bn ? j + offset : j + offset - bn;
            const double u = glm::dot(n, bp[k]) - nj;
            const bool beyond_epsilon = u * u > limit;
            behind = (u < 0.0) & beyond_epsilon;
            front |= (u > 0.0) & beyond_epsilon;
        }
        if (behind || !front)
            continue;
        DPlane sep;
        sep.normal = cross * (1.0 / std::sqrt(len_sq));
        sep.dist = glm::dot(bj, sep.normal);
        if (b_side[j] < 0)
            sep = sep.flipped();
        out = mirror ? sep.flipped() : sep;
        return true; // the first separator of each edge only (Antony Suter's optimisation)
    }
    return false;
}

// ericw's ClipToSeparators, less the clipping: use(plane) gets the separator of each edge of A
// with B in turn (a_plane: A's plane; b_side: scratch for B's points), while it returns true.
template <class Use>
void for_each_separator(const WRef& a, const DPlane& a_plane, const WRef& b, bool mirror, int8_t* b_side, Use&& use)
{
    sides_to_plane(b, a_plane, b_side);
    DPlane sep;
    for (uint32_t i = 0; i < a.count; ++i)
        if (edge_separator(a, b, b_side, i, mirror, sep) && !use(sep))
            return;
}

// Passages (portal_vis.h, "Passages"): for directed portal a and the k-th portal b leaving a's
// destination, the leaves a line through a and then b can reach. A row keeps only its words
// [lo, hi) (the others are zero): such a line reaches a few nearby leaves, and BSP leaf numbers
// follow the tree, so on e1m1 a row spans 5 of 19 words.
// Stored as a header word (lo in the low half, hi in the high half) followed by the words, so
// that reading a row touches one place.
struct PassageRow {
    uint32_t lo = 0, hi = 0;
    const uint64_t* words = nullptr; // word w of the row, for w in [lo, hi), is words[w - lo]

    bool test(uint32_t leaf) const
    {
        const uint32_t w = leaf >> 6;
        return w >= lo && w < hi && ((words[w - lo] >> (leaf & 63)) & 1u) != 0;
    }
};

struct Passages {
    std::vector<size_t> first;   // n + 1 offsets: a's pairs are [first[a], first[a + 1])
    std::vector<uint32_t> start; // per pair: the index of its header in `words`
    std::vector<uint64_t> words;

    PassageRow row(uint32_t a, size_t k) const
    {
        const uint64_t* header = &words[start[first[a] + k]];
        return {uint32_t(*header), uint32_t(*header >> 32), header + 1};
    }
    size_t pairs() const { return start.size(); }
    size_t bytes() const
    {
        return first.capacity() * sizeof(size_t) + start.capacity() * sizeof(uint32_t) +
               words.capacity() * sizeof(uint64_t);
    }
};

// Every portal a's mightsee narrowed to its destination plus what its passages reach: a line
// from a into a leaf beyond its destination leaves the destination through some portal b.
void narrow_mightsee(const Graph& g, const Passages& passages, std::vector<uint64_t>& mightsee)
{
    const size_t words = g.words;
    std::vector<uint64_t> reach(words);
    for (uint32_t a = 0; a < uint32_t(g.portals.size()); ++a) {
        std::fill(reach.begin(), reach.end(), 0);
        bits::set(reach, g.portals[a].leaf);
        for (size_t k = 0; k < passages.first[a + 1] - passages.first[a]; ++k) {
            const PassageRow row = passages.row(a, k);
            for (size_t w = row.lo; w < row.hi; ++w)
                reach[w] |= row.words[w - row.lo];
        }
        uint64_t* might = &mightsee[size_t{a} * words];
        for (size_t w = 0; w < words; ++w)
            might[w] &= reach[w];
    }
}

// One worker thread's flow state: the stack of frames (grown only when a walk goes deeper than
// any before it), the visbits being built, which leaves are on the chain, clip scratch.
class FlowWorker {
public:
    FlowWorker(const Graph& g, int level)
        : g_(g), level_(level), vis_(g.words, 0), on_stack_(g.leaf_count, 0),
          dists_(point_capacity() + 1), sides_(point_capacity() + 1), b_side_(point_capacity()),
          ones_(g.words, ~uint64_t{0})
    {
    }

    // The flow of directed portal pi, into vis(). prune_row(q) gives the set q may still
    // reach (its visbits or its mightsee), or nullptr when the bake is cancelled. Returns
    // false when cancelled.
    template <class PruneRow>
    bool run(uint32_t pi, const uint64_t* head_mightsee, PruneRow&& prune_row, const std::atomic<bool>& cancel);

    std::span<const uint64_t> vis() const { return vis_; }
    void use_passages(const Passages* p) { passages_ = p; }
    void use_target_checks(bool on) { target_checks_ = on; }
    size_t target_checks() const { return target_check_count_; }
    size_t target_check_prunes() const { return target_check_prunes_; }
    // The passage row of directed portal ai and the k-th portal leaving its destination.
    void passage_row(uint32_t ai, uint32_t k, const std::vector<uint64_t>& mightsee, uint64_t* out);
    size_t leaf_recursions() const { return leaf_recursions_; }
    size_t bytes() const
    {
        return frames_.size() * (sizeof(Frame) + g_.words * sizeof(uint64_t) + 2 * point_capacity()) +
               vis_.size() * sizeof(uint64_t) + on_stack_.size() + dists_.size() * sizeof(double) + sides_.size() +
               b_side_.size();
    }

private:
    // The most points any winding of the walk can have: a portal's or a frame winding's.
    uint32_t point_capacity() const { return std::max(g_.max_points, kStackPoints); }

    Frame& frame(size_t depth)
    {
        while (frames_.size() <= depth)
            frames_.push_back(std::make_unique<Frame>(g_.words, point_capacity()));
        return *frames_[depth];
    }

    WRef portal_winding(uint32_t pi) const
    {
        const DirectedPortal& p = g_.portals[pi];
        return WRef{&g_.points[p.first_point], p.point_count, p.origin, p.radius, nullptr, -1};
    }

    static void release(const WRef& w, Frame& f)
    {
        if (w.owner == &f)
            f.slot_used[w.slot] = false;
    }

    static int acquire(Frame& f)
    {
        for (int i = 0; i < kStackWindings; ++i)
            if (!f.slot_used[i]) {
                f.slot_used[i] = true;
                return i;
            }
        assert(false && "portal vis: a frame needs at most three windings");
        return -1;
    }

    // ericw's ClipStackWinding: the front part of `in`; the input itself when it has no point
    // behind, when all its points are on the plane, or when the result would not fit in a
    // frame's winding; an empty handle when nothing is in front. Frees `in` when it was one of
    // f's windings and a new one is returned (or none).
    WRef clip(const WRef& in, const DPlane& split, Frame& f);

    // A clip whose result would not fit in a frame's winding: the slot back, the unclipped input
    // (conservative).
    static WRef overflowed(Frame& f, int slot, const WRef& in)
    {
        f.slot_used[slot] = false;
        return in;
    }

    // Enters `leaf` below the frame at depth_ (false when it is already on the chain).
    bool enter(uint32_t leaf, uint32_t entry);
    // Leaves the frame at depth_.
    void leave()
    {
        on_stack_[frames_[depth_]->leaf] = 0;
        --depth_;
    }

    // `w` clipped by the planes of tests 0 and 1 (as far as level_ asks) of frame f, whose
    // previous frame is prev. The planes depend only on prev, so f finds them once, edge by
    // edge as windings need them (SeparatorCache), and every winding meets them in one order.
    WRef clip_to_frame_separators(WRef w, Frame& f, const Frame& prev, const DPlane& head_plane);

    // The target check of the frame just entered (portal_vis.h, "Target checks"): false when
    // no leaf the walk below it could add is reachable through its source and pass. Removes
    // the unreachable ones from its mightsee. Uses the frame's windings as scratch.
    bool may_add_leaf(const Frame& head);
    // Whether a portal into `leaf` survives frame f's clips: in front of the head and of the
    // pass, and inside the planes of tests 0 and 1.
    bool leaf_reachable(uint32_t leaf, Frame& f, const Frame& prev, const Frame& head);

    const Graph& g_;
    int level_;
    std::vector<std::unique_ptr<Frame>> frames_;
    std::vector<uint64_t> vis_;
    std::vector<uint8_t> on_stack_;
    std::vector<double> dists_;
    std::vector<uint8_t> sides_;
    std::vector<int8_t> b_side_; // tests 2 and 3: sides_to_plane of B
    std::vector<DPlane> passage_planes_;
    std::vector<uint32_t> passage_stack_;
    size_t depth_ = 0;
    size_t leaf_recursions_ = 0;
    const Passages* passages_ = nullptr;
    std::vector<uint64_t> ones_;
    bool target_checks_ = false;
    size_t target_check_count_ = 0;
    size_t target_check_prunes_ = 0;
};

void FlowWorker::passage_row(uint32_t ai, uint32_t k, const std::vector<uint64_t>& mightsee, uint64_t* out)
{
    const size_t words = g_.words;
    std::fill(out, out + words, 0);
    const DirectedPortal& a = g_.portals[ai];
    const uint32_t bi = g_.leaf_portals[g_.leaf_first[a.leaf] + k];
    const DirectedPortal& b = g_.portals[bi];
    if (bi == (ai ^ 1u))
        return;
    Frame& f = frame(0);
    for (bool& used : f.slot_used)
        used = false;
    if (normals_equal(a.plane.normal, -b.plane.normal))
        return;
    const WRef bw = clip(portal_winding(bi), a.plane, f);
    if (!bw)
        return;
    bits::set(std::span<uint64_t>(out, words), b.leaf);
    const WRef aw = portal_winding(ai);
    std::vector<DPlane>& planes = passage_planes_;
    planes.clear();
    const auto keep = [&](const DPlane& sep) {
        planes.push_back(sep);
        return true;
    };
    if (level_ > 0) // test 0: a -> b
        for_each_separator(aw, a.plane, bw, false, b_side_.data(), keep);
    if (level_ > 1) // test 1: b -> a, mirrored
        for_each_separator(bw, b.plane, aw, true, b_side_.data(), keep);
    const uint64_t* ma = &mightsee[size_t(ai) * words];
    const uint64_t* mb = &mightsee[size_t(bi) * words];
    // Flood from b's leaf through the portals a line through a and b can cross.
    std::vector<uint32_t>& stack = passage_stack_;
    stack.clear();
    stack.push_back(b.leaf);
    const std::span<uint64_t> row(out, words);
    while (!stack.empty()) {
        const uint32_t y = stack.back();
        stack.pop_back();
        for (uint32_t o = g_.leaf_first[y]; o < g_.leaf_first[y + 1]; ++o) {
            const uint32_t ri = g_.leaf_portals[o];
            const DirectedPortal& r = g_.portals[ri];
            const uint32_t x = r.leaf;
            if (bits::test(row, x) || !bits::test(std::span<const uint64_t>(ma, words), x) ||
                !bits::test(std::span<const uint64_t>(mb, words), x))
                continue;
            // Spheres first: one dot product per plane.
            bool behind = false, inside = true;
            auto sphere = [&](const DPlane& pl) {
                const double c = pl.distance(r.origin);
                behind |= c < -r.radius;
                inside &= c > r.radius;
            };
            sphere(a.plane);
            sphere(b.plane);
            for (size_t pl = 0; pl < planes.size() && !behind; ++pl)
                sphere(planes[pl]);
            if (behind)
                continue;
            bool seen = inside;
            if (!seen) {
                for (int s2 = 0; s2 < kStackWindings; ++s2)
                    f.slot_used[s2] = s2 == bw.slot && bw.owner == &f;
                WRef w = clip(portal_winding(ri), a.plane, f);
                w = clip(w, b.plane, f);
                for (size_t pl = 0; pl < planes.size() && w; ++pl)
                    w = clip(w, planes[pl], f);
                seen = bool(w);
            }
            if (!seen)
                continue;
            bits::set(row, x);
            stack.push_back(x);
        }
    }
}

WRef FlowWorker::clip(const WRef& in, const DPlane& split, Frame& f)
{
    enum : uint8_t { kFront = 0, kBack = 1, kOn = 2 };
    if (!in)
        return in;
    const double centre = split.distance(in.origin);
    if (centre < -in.radius) {
        release(in, f);
        return {};
    }
    if (centre > in.radius)
        return in;

    // Locals, not members: the byte stores to `sides` would otherwise make the compiler reload
    // every pointer after each of them.
    const Vec* points = in.points;
    const uint32_t n = in.count;
    double* dists = dists_.data();
    uint8_t* sides = sides_.data();
    const Vec normal = split.normal;
    const double dist = split.dist;
    // Branch-free: which side a point is on is data, not control flow.
    uint32_t front = 0, back = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const double d = glm::dot(normal, points[i]) - dist;
        dists[i] = d;
        const uint32_t is_front = d > kOnEpsilon, is_back = d < -kOnEpsilon;
        sides[i] = uint8_t(is_back + 2 * (1 - is_front - is_back)); // kFront, kBack or kOn
        front += is_front;
        back += is_back;
    }
    dists[n] = dists[0];
    sides[n] = sides[0];
    if (front == 0 && back == 0)
        return in; // lying on the plane: kept unclipped (ericw issue #261)
    if (front == 0) {
        release(in, f);
        return {};
    }
    if (back == 0)
        return in;

    const int slot = acquire(f);
    if (slot < 0)
        return in; // cannot happen (see acquire); unclipped is conservative
    Vec* out = f.slots[slot];
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const Vec& p1 = points[i];
        if (sides[i] != kBack) {
            if (m == kStackPoints)
                return overflowed(f, slot, in);
            out[m++] = p1;
            if (sides[i] == kOn)
                continue;
        }
        if (sides[i + 1] == kOn || sides[i + 1] == sides[i])
            continue;
        const Vec& p2 = points[i + 1 == n ? 0 : i + 1];
        const double t = dists[i] / (dists[i] - dists[i + 1]);
        Vec mid;
        for (int j = 0; j < 3; ++j) {
            if (normal[j] == 1.0)
                mid[j] = dist; // axial plane: no round-off on its axis
            else if (normal[j] == -1.0)
                mid[j] = -dist;
            else
                mid[j] = p1[j] + t * (p2[j] - p1[j]);
        }
        if (m == kStackPoints)
            return overflowed(f, slot, in);
        out[m++] = mid;
    }
    const WRef result{out, m, in.origin, in.radius, &f, slot};
    release(in, f);
    return result;
}

bool FlowWorker::enter(uint32_t leaf, uint32_t entry)
{
    if (on_stack_[leaf]) {
        ++leaf_recursions_;
        return false;
    }
    Frame& f = frame(depth_ + 1);
    ++depth_;
    f.leaf = leaf;
    f.entry = entry;
    f.cursor = g_.leaf_first[leaf];
    f.end = g_.leaf_first[leaf + 1];
    f.separators[0].next_edge = f.separators[1].next_edge = 0;
    f.separators[0].count = f.separators[1].count = 0;
    on_stack_[leaf] = 1;
    bits::set(vis_, leaf);
    return true;
}

WRef FlowWorker::clip_to_frame_separators(WRef w, Frame& f, const Frame& prev, const DPlane& head_plane)
{
    for (int t = 0; t < 2 && w && level_ > t; ++t) {
        SeparatorCache& cache = f.separators[t];
        const WRef& a = t == 0 ? prev.source : prev.pass;
        const DPlane& a_plane = t == 0 ? head_plane : prev.portalplane;
        const WRef& b = t == 0 ? prev.pass : prev.source;
        for (uint32_t k = 0; w; ++k) {
            if (k == cache.count) {
                // More planes are needed: the next edges of A (at most kMaxSeparators kept:
                // fewer planes clip less, so the result stays conservative).
                if (cache.next_edge == 0)
                    sides_to_plane(b, a_plane, cache.b_side.data());
                bool found = false;
                while (!found && cache.next_edge < a.count && cache.count < kMaxSeparators)
                    found = edge_separator(a, b, cache.b_side.data(), cache.next_edge++, t == 1,
                                           cache.planes[cache.count]);
                if (!found)
                    break; // no edge left
                ++cache.count;
            }
            w = clip(w, cache.planes[k], f);
        }
    }
    return w;
}

bool FlowWorker::may_add_leaf(const Frame& head)
{
    Frame& f = *frames_[depth_];
    Frame& prev = *frames_[depth_ - 1]; // the source, pass and plane f was entered with, f's mightsee
    uint32_t unseen = 0;
    for (uint32_t w = prev.lo; w < prev.hi; ++w)
        unseen += uint32_t(std::popcount(prev.mightsee[w] & ~vis_[w]));
    if (unseen > kTargetCheckLeaves)
        return true; // checking them all would cost more than the walk it might save
    ++target_check_count_;
    bool any_reachable = false;
    for (uint32_t w = prev.lo; w < prev.hi; ++w) {
        for (uint64_t left = prev.mightsee[w] & ~vis_[w]; left != 0; left &= left - 1) {
            const uint32_t leaf = w * 64 + uint32_t(std::countr_zero(left));
            if (leaf_reachable(leaf, f, prev, head))
                any_reachable = true;
            else
                prev.mightsee[w] &= ~(uint64_t{1} << (leaf & 63)); // no walk below reaches it
        }
    }
    target_check_prunes_ += !any_reachable;
    return any_reachable;
}

bool FlowWorker::leaf_reachable(uint32_t leaf, Frame& f, const Frame& prev, const Frame& head)
{
    for (uint32_t k = g_.leaf_first[leaf]; k < g_.leaf_first[leaf + 1]; ++k) {
        const uint32_t into = g_.leaf_portals[k] ^ 1u; // the twin of a portal out of `leaf` leads in
        for (bool& used : f.slot_used)
            used = false;
        WRef w = clip(portal_winding(into), head.portalplane, f);
        w = clip(w, prev.portalplane, f);
        if (clip_to_frame_separators(w, f, prev, head.portalplane))
            return true;
    }
    return false;
}

template <class PruneRow>
bool FlowWorker::run(uint32_t pi, const uint64_t* head_mightsee, PruneRow&& prune_row, const std::atomic<bool>& cancel)
{
    const DirectedPortal& p = g_.portals[pi];
    const size_t words = g_.words;
    std::fill(vis_.begin(), vis_.end(), 0);

    Frame& head = frame(0);
    head.source = portal_winding(pi);
    head.pass = {};
    head.portalplane = p.plane;
    std::copy(head_mightsee, head_mightsee + words, head.mightsee.begin());
    head.lo = 0;
    head.hi = uint32_t(words);
    depth_ = 0;
    enter(p.leaf, pi);

    uint32_t steps = 0;
    bool cancelled = false;
    while (depth_ > 0) {
        Frame& f = *frames_[depth_];
        const Frame& prev = *frames_[depth_ - 1];
        if (f.cursor == f.end) {
            leave();
            continue;
        }
        if (++steps == kCancelCheckSteps) {
            steps = 0;
            if (cancel.load(std::memory_order_relaxed)) {
                cancelled = true;
                break;
            }
        }
        const uint32_t qi = g_.leaf_portals[f.cursor++];
        const DirectedPortal& q = g_.portals[qi];
        // The windings of the previous target are dead: its subtree is done.
        for (bool& used : f.slot_used)
            used = false;

        // Mightsee prune, then "nothing new": might = prev.mightsee & (q's visbits or mightsee).
        const uint32_t leaf_word = q.leaf >> 6;
        if (leaf_word < prev.lo || leaf_word >= prev.hi || !bits::test(prev.mightsee, q.leaf))
            continue;
        // Can't go out a coplanar face.
        if (normals_equal(prev.portalplane.normal, -q.plane.normal))
            continue;
        // The passage (the portal into this leaf, q): q's own leaf, then the words it spans.
        uint32_t lo = prev.lo, hi = prev.hi;
        const uint64_t* passage = ones_.data(); // indexed from lo
        if (passages_ != nullptr) {
            const PassageRow row = passages_->row(f.entry, f.cursor - 1 - g_.leaf_first[f.leaf]);
            if (!row.test(q.leaf))
                continue;
            lo = std::max(lo, row.lo);
            hi = std::min(hi, row.hi);
            passage = row.words + (lo - row.lo);
        }
        const uint64_t* test = prune_row(qi);
        if (test == nullptr) {
            cancelled = true;
            break;
        }
        {
            uint32_t w = lo;
            while (w < hi && (prev.mightsee[w] & test[w] & passage[w - lo] & ~vis_[w]) == 0)
                ++w;
            if (w >= hi)
                continue;
        }
        const auto narrow = [&] {
            for (uint32_t w = lo; w < hi; ++w)
                f.mightsee[w] = prev.mightsee[w] & test[w] & passage[w - lo];
            f.lo = lo;
            f.hi = hi;
        };

        // The part of the target in front of the source portal.
        WRef pass = clip(portal_winding(qi), head.portalplane, f);
        if (!pass)
            continue;
        if (!prev.pass) {
            // The second leaf: only coplanarity can block it.
            f.source = prev.source;
            f.pass = pass;
            f.portalplane = q.plane;
            narrow();
            enter(q.leaf, qi);
            continue;
        }
        // The part of the target in front of the pass portal, and of the source behind the target.
        pass = clip(pass, prev.portalplane, f);
        if (!pass)
            continue;
        WRef source = clip(prev.source, q.plane.flipped(), f);
        if (!source)
            continue;

        // Test 0: source -> pass separators clip the target. Test 1: pass -> source, mirrored.
        pass = clip_to_frame_separators(pass, f, prev, head.portalplane);
        if (!pass)
            continue;
        // Test 2: target -> pass separators clip the source. Test 3: pass -> target, mirrored.
        const auto clip_source = [&](const DPlane& sep) {
            source = clip(source, sep, f);
            return bool(source);
        };
        if (level_ > 2)
            for_each_separator(pass, q.plane, prev.pass, false, b_side_.data(), clip_source);
        if (level_ > 3 && source)
            for_each_separator(prev.pass, prev.portalplane, pass, true, b_side_.data(), clip_source);
        if (!source)
            continue;

        f.source = source;
        f.pass = pass;
        f.portalplane = q.plane;
        narrow();
        const bool seen_before = bits::test(vis_, q.leaf);
        if (enter(q.leaf, qi) && seen_before && target_checks_ && !may_add_leaf(head))
            leave(); // nothing below could add a leaf
    }
    if (cancelled) {
        while (depth_ > 0)
            leave();
        return false;
    }
    return true;
}

// ---------------------------------------------------------------------------------------------
// Threads

unsigned thread_count(unsigned requested, size_t items)
{
    unsigned n = requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
    n = std::min(n, 256u);
    if (items < n)
        n = unsigned(std::max<size_t>(items, 1));
    return n;
}

// Runs worker(t) for t in [0, threads) on worker threads while the calling thread calls
// progress(fraction()) about every 50 ms; progress returning false sets `cancel`. Exceptions
// from workers or from progress are rethrown once every thread has joined.
template <class Worker, class Fraction>
void run_parallel(unsigned threads, Worker&& worker, std::atomic<bool>& cancel, std::atomic<bool>& user_cancel,
                  const std::function<bool(double)>& progress, Fraction&& fraction)
{
    std::exception_ptr error;
    std::mutex mutex;
    std::condition_variable finished_cv;
    unsigned finished = 0;
    auto body = [&](unsigned t) {
        try {
            worker(t);
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!error)
                error = std::current_exception();
            cancel.store(true);
        }
        {
            std::lock_guard lock(mutex);
            ++finished;
        }
        finished_cv.notify_all();
    };
    if (threads == 1 && !progress) {
        body(0);
    } else {
        std::vector<std::thread> pool;
        pool.reserve(threads);
        try {
            for (unsigned t = 0; t < threads; ++t)
                pool.emplace_back(body, t);
        } catch (...) {
            cancel.store(true);
            for (std::thread& th : pool)
                th.join();
            throw;
        }
        std::unique_lock lock(mutex);
        while (finished < pool.size()) {
            finished_cv.wait_for(lock, std::chrono::milliseconds(50), [&] { return finished == pool.size(); });
            if (finished == pool.size() || !progress || cancel.load())
                continue;
            lock.unlock();
            bool keep_going = false;
            try {
                keep_going = progress(fraction());
            } catch (...) {
                std::lock_guard error_lock(mutex);
                if (!error)
                    error = std::current_exception();
            }
            if (!keep_going) {
                user_cancel.store(true);
                cancel.store(true);
            }
            lock.lock();
        }
        lock.unlock();
        for (std::thread& th : pool)
            th.join();
    }
    if (error)
        std::rethrow_exception(error);
}

// Builds every pair's passage row with `threads` workers, then narrows each portal's mightsee
// to its passages. False, with `out` empty, when there are no portals, when the rows would take
// more than `budget` bytes (decided by their total size alone, so not by timing), or when
// cancelled.
bool build_passages(const Graph& g, int level, std::vector<uint64_t>& mightsee, size_t budget, unsigned threads,
                    std::atomic<bool>& cancel, std::atomic<bool>& user_cancel,
                    const std::function<bool(double)>& progress, Passages& out)
{
    const auto n = uint32_t(g.portals.size());
    if (n == 0)
        return false;
    out.first.assign(size_t{n} + 1, 0);
    for (uint32_t a = 0; a < n; ++a) {
        const uint32_t leaf = g.portals[a].leaf;
        out.first[a + 1] = out.first[a] + (g.leaf_first[leaf + 1] - g.leaf_first[leaf]);
    }
    const size_t pairs = out.first[n];
    const size_t fixed_bytes = out.first.size() * sizeof(size_t) + pairs * sizeof(uint32_t);
    if (fixed_bytes > budget) {
        out = {};
        return false;
    }
    out.start.assign(pairs, 0);
    // (uint32_t indices into `words`)
    const size_t word_budget = std::min<size_t>((budget - fixed_bytes) / sizeof(uint64_t), UINT32_MAX);
    std::atomic<size_t> total_words{0};
    std::atomic<bool> over_budget{false};
    std::mutex words_mutex;
    std::atomic<uint32_t> next_portal{0}, portals_done{0};
    run_parallel(
        threads,
        [&](unsigned) {
            FlowWorker worker(g, level);
            std::vector<uint64_t> dense(g.words), packed;
            while (!cancel.load(std::memory_order_relaxed) && !over_budget.load(std::memory_order_relaxed)) {
                const uint32_t a = next_portal.fetch_add(1);
                if (a >= n)
                    break;
                packed.clear();
                for (size_t k = 0; k < out.first[a + 1] - out.first[a]; ++k) {
                    worker.passage_row(a, uint32_t(k), mightsee, dense.data());
                    uint32_t lo = 0, hi = uint32_t(g.words);
                    while (lo < hi && dense[lo] == 0)
                        ++lo;
                    while (hi > lo && dense[hi - 1] == 0)
                        --hi;
                    out.start[out.first[a] + k] = uint32_t(packed.size()); // made absolute below
                    packed.push_back(uint64_t{lo} | uint64_t{hi} << 32);
                    packed.insert(packed.end(), dense.begin() + lo, dense.begin() + hi);
                }
                if (total_words.fetch_add(packed.size()) + packed.size() > word_budget) {
                    over_budget.store(true);
                    break;
                }
                size_t base = 0;
                {
                    std::lock_guard lock(words_mutex);
                    base = out.words.size();
                    out.words.insert(out.words.end(), packed.begin(), packed.end());
                }
                for (size_t k = 0; k < out.first[a + 1] - out.first[a]; ++k)
                    out.start[out.first[a] + k] += uint32_t(base);
                portals_done.fetch_add(1, std::memory_order_relaxed);
            }
        },
        cancel, user_cancel, progress,
        [&] { return kBaseWeight + kPassageWeight * double(portals_done.load()) / double(n); });
    if (cancel.load() || over_budget.load()) {
        out = {};
        return false;
    }
    narrow_mightsee(g, out, mightsee);
    return true;
}

} // namespace

Pvs bake_portal_vis(const PortalSet& input, uint32_t region_count, const VisParams& params, VisReport* report)
{
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const bool full = params.method == VisParams::Method::Full;
    const int level = std::clamp(params.level, 0, 4);

    VisReport rep;
    const Graph g = build_graph(input, region_count);
    rep.portals = g.used;
    rep.portals_skipped = g.skipped;
    const uint32_t n = uint32_t(g.portals.size());
    const size_t words = g.words;
    rep.threads = thread_count(params.threads, n);

    std::vector<uint64_t> mightsee(size_t{n} * words, 0);
    std::vector<uint32_t> nummightsee(n, 0);
    std::vector<uint64_t> visbits; // Full only
    std::unique_ptr<std::atomic<uint8_t>[]> state(new std::atomic<uint8_t>[n]);
    for (uint32_t i = 0; i < n; ++i)
        state[i].store(kNone, std::memory_order_relaxed);
    std::atomic<bool> cancel{false}, user_cancel{false};
    size_t worker_bytes = 0;
    size_t passage_row_bytes = 0;
    std::mutex worker_bytes_mutex;

    bool base_done = false, flow_started = false;
    if (params.progress && !params.progress(0.0)) {
        user_cancel.store(true);
    } else {
        // Base vis: every directed portal on its own.
        std::atomic<uint32_t> next{0}, done{0};
        run_parallel(
            rep.threads,
            [&](unsigned) {
                std::vector<uint32_t> stack;
                stack.reserve(region_count);
                while (!cancel.load(std::memory_order_relaxed)) {
                    const uint32_t i = next.fetch_add(1);
                    if (i >= n)
                        break;
                    nummightsee[i] = base_portal_vis(g, i, stack, &mightsee[size_t{i} * words]);
                    done.fetch_add(1, std::memory_order_relaxed);
                }
            },
            cancel, user_cancel, params.progress,
            [&] { return (full ? kBaseWeight : 1.0) * double(done.load()) / double(std::max(n, 1u)); });
        base_done = !cancel.load();
    }
    rep.base_seconds = std::chrono::duration<double>(Clock::now() - start).count();

    std::atomic<uint64_t> wait_nanos{0};
    std::atomic<size_t> leaf_recursions{0};
    std::atomic<size_t> target_checks{0}, target_check_prunes{0};
    if (full && base_done) {
        flow_started = true;
        visbits.assign(size_t{n} * words, 0);
        // Rank by increasing nummightsee, ties by index: the order the portals are handed out in
        // and the order that decides which visbits a portal may prune with.
        std::vector<uint32_t> order(n), rank(n);
        for (uint32_t i = 0; i < n; ++i)
            order[i] = i;
        std::stable_sort(order.begin(), order.end(),
                         [&](uint32_t a, uint32_t b) { return nummightsee[a] < nummightsee[b]; });
        for (uint32_t r = 0; r < n; ++r)
            rank[order[r]] = r;
        uint64_t total_weight = 0;
        for (uint32_t i = 0; i < n; ++i)
            total_weight += nummightsee[i];
        // Passages, then every portal's mightsee narrowed to what its passages reach.
        Passages passages;
        const bool use_passages = build_passages(g, level, mightsee, params.passage_budget_bytes, rep.threads,
                                                 cancel, user_cancel, params.progress, passages);
        if (use_passages) {
            rep.passage_pairs = passages.pairs();
            passage_row_bytes = passages.bytes();
        }
        rep.passage_seconds = std::chrono::duration<double>(Clock::now() - start).count() - rep.base_seconds;
        std::atomic<uint32_t> next{0};
        std::atomic<uint64_t> done_weight{0};

        run_parallel(
            rep.threads,
            [&](unsigned) {
                FlowWorker worker(g, level);
                worker.use_target_checks(params.target_checks);
                if (use_passages)
                    worker.use_passages(&passages);
                uint64_t waited = 0;
                while (!cancel.load(std::memory_order_relaxed)) {
                    const uint32_t r = next.fetch_add(1);
                    if (r >= n)
                        break;
                    const uint32_t pi = order[r];
                    if (cancel.load(std::memory_order_relaxed)) {
                        // Handed out after a cancel: still marked, for any portal waiting on it.
                        state[pi].store(kAborted, std::memory_order_release);
                        state[pi].notify_all();
                        break;
                    }
                    state[pi].store(kWorking, std::memory_order_relaxed);
                    // q's visbits when q is at least kPruneLag + 1 ranks older (waiting for it if
                    // needed), else q's mightsee: a fixed rule, so timing never changes the result.
                    auto prune_row = [&](uint32_t qi) -> const uint64_t* {
                        if (rank[qi] + kPruneLag >= r)
                            return &mightsee[size_t{qi} * words];
                        uint8_t s = state[qi].load(std::memory_order_acquire);
                        if (s < kDone) {
                            const auto wait_start = Clock::now();
                            while ((s = state[qi].load(std::memory_order_acquire)) < kDone)
                                state[qi].wait(s, std::memory_order_acquire);
                            waited += uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                                   Clock::now() - wait_start)
                                                   .count());
                        }
                        return s == kDone ? &visbits[size_t{qi} * words] : nullptr;
                    };
                    bool ok = false;
                    try {
                        ok = worker.run(pi, &mightsee[size_t{pi} * words], prune_row, cancel);
                    } catch (...) {
                        cancel.store(true); // (bad_alloc growing the frames) release the waiters
                        state[pi].store(kAborted, std::memory_order_release);
                        state[pi].notify_all();
                        throw;
                    }
                    if (ok)
                        std::copy(worker.vis().begin(), worker.vis().end(), visbits.begin() + ptrdiff_t(size_t{pi} * words));
                    state[pi].store(ok ? kDone : kAborted, std::memory_order_release);
                    state[pi].notify_all();
                    done_weight.fetch_add(nummightsee[pi], std::memory_order_relaxed);
                    if (!ok)
                        break;
                }
                target_checks.fetch_add(worker.target_checks());
                target_check_prunes.fetch_add(worker.target_check_prunes());
                wait_nanos.fetch_add(waited);
                leaf_recursions.fetch_add(worker.leaf_recursions());
                std::lock_guard lock(worker_bytes_mutex);
                worker_bytes += worker.bytes();
            },
            cancel, user_cancel, params.progress,
            [&] {
                const double before = kBaseWeight + (use_passages ? kPassageWeight : 0.0);
                return before + (1.0 - before) * double(done_weight.load()) /
                                         double(std::max<uint64_t>(total_weight, 1));
            });
    }
    rep.cancelled = user_cancel.load();
    rep.leaf_recursions = leaf_recursions.load();
    rep.target_checks = target_checks.load();
    rep.target_check_prunes = target_check_prunes.load();
    rep.wait_seconds = double(wait_nanos.load()) * 1e-9;

    // Aggregation (§3.5): a region sees what its outgoing portals see, plus itself.
    size_t total_visible = 0;
    size_t saw_self = 0;
    Pvs pvs = Pvs::build(region_count, [&](uint32_t r, std::span<uint64_t> row) {
        if (!base_done) {
            bits::fill(row, region_count); // cancelled early: everything may be visible
        } else {
            for (uint32_t k = g.leaf_first[r]; k < g.leaf_first[r + 1]; ++k) {
                const uint32_t pi = g.leaf_portals[k];
                const bool use_vis = flow_started && state[pi].load(std::memory_order_acquire) == kDone;
                const uint64_t* src = use_vis ? &visbits[size_t{pi} * words] : &mightsee[size_t{pi} * words];
                for (size_t w = 0; w < words; ++w)
                    row[w] |= src[w];
            }
            saw_self += bits::test(row, r);
            bits::set(row, r);
        }
        total_visible += bits::count(row);
        return true;
    });
    rep.saw_into_own_region = saw_self;
    rep.mean_visible = region_count == 0 ? 0.0 : double(total_visible) / double(region_count);
    rep.peak_bytes_estimate = g.bytes() + (mightsee.capacity() + visbits.capacity()) * sizeof(uint64_t) +
                              size_t{n} * (sizeof(uint32_t) * 3 + 1) + worker_bytes + passage_row_bytes + pvs.memory_bytes() +
                              size_t{region_count} * sizeof(uint32_t) * rep.threads;
    rep.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (params.progress && !rep.cancelled)
        params.progress(1.0);
    if (report)
        *report = rep;
    return pvs;
}

} // namespace pvs
