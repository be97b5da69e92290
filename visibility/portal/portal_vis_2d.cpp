#include "visibility/portal/portal_vis_2d.h"

#include "visibility/bit_row.h"
#include "visibility/portal/prune_lag.h"
#include "visibility/portal/segment_clip_2d.h"
#include "visibility/worker_pool.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

namespace pvs {

namespace {

using portal_vis::FlowTicket;
using portal_vis::PruneLag;

// Portals ranked more than this below a walk's own prune it with their final vis. Part of the
// definition of the result. 8 rather than the 3-D baker's 32: the 2-D walks are short, so a
// smaller lag seldom makes a thread wait and prunes more (MAP28 1.82 s -> 1.73 s).
constexpr uint32_t kPruneLag2d = 8;
// Target checks look at most this many unseen leaves (as the 3-D flow's).
constexpr uint32_t kTargetCheckLeaves = 64;


using flow2d::FlowTolerances2d;
using flow2d::Line;
using flow2d::Segment;
using flow2d::Vec2;

struct Portal2 {
    Segment seg;
    Line line;      // normal into `leaf`
    uint32_t leaf;  // the region it leads into
    uint32_t owner; // the region it is stored in
};

struct Graph {
    std::vector<Portal2> portals;        // directed: 2i and 2i + 1
    std::vector<uint32_t> first_of_leaf; // leaf r's outgoing portals: order[first[r] .. first[r + 1])
    std::vector<uint32_t> order;
    std::vector<uint32_t> input_portal; // per pair 2i, 2i + 1: the input portal's index
    uint32_t leaf_count = 0;
    size_t words = 0;
    size_t skipped = 0;
    FlowTolerances2d tol; // for the largest coordinate of any portal (segment_clip_2d.h)
};

// The portal's segment and line in the plane, or false when it is not a vertical portal.
bool project(const PortalSet& set, const Portal& portal, Segment& seg, Line& line)
{
    if (portal.point_count < 3)
        return false;
    const glm::vec3* pts = set.points.data() + portal.first_point;
    // Newell's normal: robust for any planar polygon (the orientation of the first three points).
    glm::dvec3 normal(0.0);
    for (uint32_t i = 0; i < portal.point_count; ++i) {
        const glm::dvec3 a(pts[i]), b(pts[(i + 1) % portal.point_count]);
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    // PRT1 points are clockwise seen from the front: Newell's normal of a clockwise polygon
    // points to the back, so negate it to point into regions[0] (portal_vis.h).
    normal = -normal;
    const double length = std::sqrt(normal.x * normal.x + normal.y * normal.y + normal.z * normal.z);
    if (!(length > 0) || std::abs(normal.z) / length > 0.01)
        return false;
    const double planar = std::hypot(normal.x, normal.y);
    line.n = {normal.x / planar, normal.y / planar};
    double best = -1;
    for (uint32_t i = 0; i < portal.point_count; ++i)
        for (uint32_t j = i + 1; j < portal.point_count; ++j) {
            const double dx = double(pts[i].x) - pts[j].x, dy = double(pts[i].y) - pts[j].y;
            if (dx * dx + dy * dy > best) {
                best = dx * dx + dy * dy;
                seg.p[0] = {pts[i].x, pts[i].y};
                seg.p[1] = {pts[j].x, pts[j].y};
            }
        }
    if (!(best > 0.0)) // a portal with any width is kept: dropping one would cut sight through it
        return false;
    line.d = dot(line.n, seg.p[0]);
    return true;
}

Graph build_graph(const PortalSet& set, uint32_t region_count)
{
    Graph g;
    g.leaf_count = region_count;
    g.words = bits::words_for(region_count);
    for (uint32_t input = 0; input < uint32_t(set.portals.size()); ++input) {
        const Portal& portal = set.portals[input];
        Segment seg;
        Line line;
        const int32_t r0 = portal.regions[0], r1 = portal.regions[1];
        if (r0 < 0 || r1 < 0 || uint32_t(r0) >= region_count || uint32_t(r1) >= region_count || r0 == r1 ||
            !project(set, portal, seg, line)) {
            ++g.skipped;
            continue;
        }
        // 2i: stored in regions[0], leads into regions[1] (normal negated to point there).
        g.portals.push_back({seg, line.flipped(), uint32_t(r1), uint32_t(r0)});
        g.portals.push_back({seg, line, uint32_t(r0), uint32_t(r1)});
        g.input_portal.push_back(input);
    }
    double extent = 0;
    for (const Portal2& p : g.portals)
        for (const Vec2& v : p.seg.p)
            extent = std::max({extent, std::abs(v.x), std::abs(v.y)});
    g.tol = FlowTolerances2d::for_extent(extent);
    g.first_of_leaf.assign(region_count + 1, 0);
    for (const Portal2& p : g.portals)
        ++g.first_of_leaf[p.owner + 1];
    std::partial_sum(g.first_of_leaf.begin(), g.first_of_leaf.end(), g.first_of_leaf.begin());
    g.order.resize(g.portals.size());
    std::vector<uint32_t> fill(g.first_of_leaf.begin(), g.first_of_leaf.end() - 1);
    for (uint32_t i = 0; i < g.portals.size(); ++i)
        g.order[fill[g.portals[i].owner]++] = i;
    return g;
}

// Base vis of directed portal pi: the leaves a flood through the portals in front of it reaches.
void base_vis(const Graph& g, uint32_t pi, std::vector<uint32_t>& stack, uint64_t* flood)
{
    const Portal2& p = g.portals[pi];
    const std::span<uint64_t> row(flood, g.words);
    stack.assign(1, p.leaf);
    bits::set(row, p.leaf);
    while (!stack.empty()) {
        const uint32_t leaf = stack.back();
        stack.pop_back();
        for (uint32_t k = g.first_of_leaf[leaf]; k < g.first_of_leaf[leaf + 1]; ++k) {
            const Portal2& t = g.portals[g.order[k]];
            if (bits::test(row, t.leaf) || !flow2d::has_point_in_front(t.seg, p.line, g.tol) ||
                !flow2d::has_point_behind(p.seg, t.line, g.tol))
                continue;
            bits::set(row, t.leaf);
            stack.push_back(t.leaf);
        }
    }
}

struct Frame {
    std::vector<uint64_t> mightsee; // only words [lo, hi) are meaningful (the rest: zero)
    size_t lo = 0, hi = 0;
    Segment source, pass;
    Line line;
    bool has_pass = false;
    // The separators from source through pass, found when first needed (sep_count < 0: not yet):
    // the targets leaving this frame's leaf whose clip leaves the source whole, and the target
    // checks, all use these.
    flow2d::SeparatorLine seps[2];
    int sep_count = -1;
};

class Walker {
public:
    Walker(const Graph& g, int level, const std::vector<uint64_t>& flood, const std::vector<uint64_t>& rows,
           const std::vector<uint32_t>& rank, const std::atomic<uint8_t>* state, const std::atomic<bool>& stop)
        : g_(g), level_(level), flood_(flood), rows_(rows), rank_(rank), lag_(rank.data(), state, kPruneLag2d),
          stop_(stop), on_chain_(g.leaf_count, 0)
    {
    }

    // The row of region r into `out` (words): the walks of its outgoing portals, which share it.
    // False when stopped.
    bool run_region(uint32_t r, uint64_t* out)
    {
        out_ = std::span<uint64_t>(out, g_.words);
        std::fill(out_.begin(), out_.end(), 0);
        bits::set(out_, r);
        my_rank_ = rank_[r];
        for (uint32_t k = g_.first_of_leaf[r]; k < g_.first_of_leaf[r + 1]; ++k)
            if (!run(g_.order[k]))
                return false;
        portal_visible += bits::count(out_);
        return true;
    }

private:
    // Walks from directed portal pi into out_. False when stopped.
    bool run(uint32_t pi)
    {
        const Portal2& p = g_.portals[pi];
        head_ = &p;
        Frame& head = frame(0);
        std::copy_n(flood_.data() + size_t(pi) * g_.words, g_.words, head.mightsee.data());
        head.lo = 0;
        head.hi = g_.words;
        head.source = p.seg;
        head.line = p.line;
        head.has_pass = false;
        head_portal_ = pi;
        watching_ = probe_ != nullptr && p.owner == probe_->from;
        path_entry_.assign(1, pi);
        stopped_ = false;
        steps_ = 0;
        if (first_window_.empty()) {
            first_window_.assign(g_.portals.size(), kNone);
            window_count_.assign(g_.portals.size(), 0);
        }
        walk(p.leaf, 0);
        for (uint32_t t : touched_) {
            first_window_[t] = kNone;
            window_count_[t] = 0;
        }
        touched_.clear();
        windows_.clear();
        memo_words_.clear();
        return !stopped_;
    }

public:
    // Record chains into probe->found (flow_chain.h), as the 3-D flow does.
    void watch(ChainProbe* probe) { probe_ = probe; }

    size_t leaf_recursions = 0;
    uint64_t waited_nanos = 0;
    size_t dominated = 0; // walks not taken: an earlier window held them
    size_t frames = 0;    // leaves entered
    size_t portal_visible = 0;
    size_t clips = 0;     // targets clipped (the geometry tried)
    size_t target_checks = 0, target_check_prunes = 0;
    flow2d::SeparatorCounts separator_counts;

private:
    const Graph& g_;
    int level_;
    const std::vector<uint64_t>& flood_;
    const std::vector<uint64_t>& rows_; // per region: its row once final
    const std::vector<uint32_t>& rank_; // per region
    PruneLag lag_; // prune_lag.h: which portals' final vis a walk uses, and the wait for it
    const std::atomic<bool>& stop_;
    std::vector<uint8_t> on_chain_;
    std::vector<Frame> frames_;
    std::span<uint64_t> out_;
    const Portal2* head_ = nullptr;
    uint32_t my_rank_ = 0;
    bool stopped_ = false;
    size_t steps_ = 0;
    ChainProbe* probe_ = nullptr;
    bool watching_ = false;
    uint32_t head_portal_ = 0;
    std::vector<uint32_t> path_entry_; // per depth: the directed portal the walk entered through

    // Windows already walked on from each portal in this walk (see "Dominated windows").
    struct Window {
        double s0, s1, p0, p1; // source and pass as intervals along the head's and the portal's segments
        size_t words_at;       // mightsee words [lo, hi) copied to memo_words_
        uint32_t lo, hi;
        uint32_t next;         // the portal's next window, or kNone
    };
    static constexpr uint32_t kNone = UINT32_MAX;
    static constexpr uint32_t kWindowsPerPortal = 8;
    std::vector<uint32_t> first_window_; // per directed portal
    std::vector<uint8_t> window_count_;
    std::vector<uint32_t> touched_;
    std::vector<Window> windows_;
    std::vector<uint64_t> memo_words_;

    Frame& frame(size_t depth)
    {
        while (frames_.size() <= depth) {
            frames_.emplace_back();
            frames_.back().mightsee.assign(g_.words, 0);
        }
        return frames_[depth];
    }

    // The row a walk ANDs in when it passes portal t: the final row of the region t leads into
    // when that region ranks well below this walk's (waiting for it when needed: every leaf a
    // line through t reaches is seen from t's region), else t's mightsee (also when that region's
    // walk was aborted: a cancelled bake keeps what it has).
    const uint64_t* prune_row(uint32_t t)
    {
        const uint32_t q = g_.portals[t].leaf;
        if (lag_.uses_final(q, my_rank_) && lag_.await_final(q, waited_nanos))
            return rows_.data() + size_t(q) * g_.words;
        return flood_.data() + size_t(t) * g_.words;
    }

    static double length(const Segment& s) { return std::hypot(s.p[1].x - s.p[0].x, s.p[1].y - s.p[0].y); }

    // The chain of the walk into `leaf` at `depth` (path_entry_[0..depth]), into probe_->found.
    void record_chain(size_t depth)
    {
        FlowChain chain;
        chain.directed_portal = head_portal_;
        for (size_t k = 0; k <= depth; ++k) {
            const uint32_t into = path_entry_[k];
            const Segment& seen = k == 0 ? g_.portals[into].seg : frames_[k].pass;
            ChainStep step;
            step.region = g_.portals[into].leaf;
            step.portal = g_.input_portal[into >> 1];
            step.portal_size = length(g_.portals[into].seg);
            step.window_size = length(seen);
            step.window = {glm::dvec3(seen.p[0].x, seen.p[0].y, 0.0), glm::dvec3(seen.p[1].x, seen.p[1].y, 0.0)};
            chain.steps.push_back(std::move(step));
        }
        probe_->found[head_portal_] = std::move(chain);
        watching_ = false;
    }

    void walk(uint32_t leaf, size_t depth)
    {
        bits::set(out_, leaf);
        ++frames;
        if (watching_ && leaf == probe_->to)
            record_chain(depth);
        if ((++steps_ & 1023) == 0 && stop_.load(std::memory_order_relaxed))
            stopped_ = true;
        if (stopped_)
            return;
        on_chain_[leaf] = 1;
        for (uint32_t k = g_.first_of_leaf[leaf]; k < g_.first_of_leaf[leaf + 1] && !stopped_; ++k) {
            const uint32_t ti = g_.order[k];
            const Portal2& t = g_.portals[ti];
            Frame& prev = frames_[depth];
            const size_t leaf_word = t.leaf >> 6;
            if (leaf_word < prev.lo || leaf_word >= prev.hi || !bits::test(prev.mightsee, t.leaf))
                continue;
            if (on_chain_[t.leaf]) {
                ++leaf_recursions;
                continue;
            }
            Frame& cur = frame(depth + 1);
            Frame& before = frames_[depth]; // frame() may have grown the vector
            // The geometry first (a few dot products), then the rows.
            const Line back = t.line.flipped();
            if (before.line.n.x == back.n.x && before.line.n.y == back.n.y)
                continue; // cannot go out through a coplanar face
            ++clips;
            cur.pass = t.seg;
            if (!flow2d::clip_front(cur.pass, head_->line, g_.tol))
                continue;
            cur.source = before.source;
            if (!flow2d::clip_front(cur.source, back, g_.tol))
                continue;
            cur.line = t.line;
            cur.has_pass = true;
            cur.sep_count = -1;
            if (before.has_pass && !clip_separators(before, cur))
                continue;
            const uint64_t* row = prune_row(ti);
            const uint64_t* might = flood_.data() + size_t(ti) * g_.words;
            // The walk's rows shrink fast: AND only the words still holding bits, and keep the
            // span of the result's non-zero words.
            uint64_t more = 0;
            size_t lo = SIZE_MAX, hi = 0;
            for (size_t w = before.lo; w < before.hi; ++w) {
                const uint64_t m = before.mightsee[w] & row[w] & might[w];
                cur.mightsee[w] = m;
                more |= m & ~out_[w];
                if (m) {
                    lo = std::min(lo, w);
                    hi = w + 1;
                }
            }
            cur.lo = lo == SIZE_MAX ? 0 : lo;
            cur.hi = hi;
            if (!more && bits::test(out_, t.leaf))
                continue;
            if (dominated_or_remember(ti, cur)) {
                ++dominated;
                continue;
            }
            if (bits::test(out_, t.leaf) && !may_add_leaf(cur)) {
                ++target_check_prunes;
                continue;
            }
            if (watching_) {
                path_entry_.resize(depth + 2);
                path_entry_[depth + 1] = ti;
            }
            walk(t.leaf, depth + 1);
        }
        on_chain_[leaf] = 0;
    }

    // In the plane, the separators of tests 1 and 3 are those of tests 0 and 2 (a line through
    // a0 and b1 with a1 and b0 strictly on opposite sides is the same line whichever segment is
    // called the source, and both keep the same side), so levels 1 and 3 add nothing.
    // Where along segment `seg` point x lies (0 at p[0], 1 at p[1]).
    static double along(const Segment& seg, Vec2 x)
    {
        const Vec2 d{seg.p[1].x - seg.p[0].x, seg.p[1].y - seg.p[0].y};
        return dot({x.x - seg.p[0].x, x.y - seg.p[0].y}, d) / dot(d, d);
    }

    // True when an earlier window through portal ti held this one: its source and pass
    // intervals contain cur's and its mightsee holds cur's. Else cur is remembered (up to
    // kWindowsPerPortal windows a portal) and false returned.
    void intervals(uint32_t ti, const Frame& cur, double& s0, double& s1, double& p0, double& p1) const
    {
        const Segment& head = head_->seg;
        const Segment& t = g_.portals[ti].seg;
        s0 = along(head, cur.source.p[0]);
        s1 = along(head, cur.source.p[1]);
        p0 = along(t, cur.pass.p[0]);
        p1 = along(t, cur.pass.p[1]);
        if (s0 > s1)
            std::swap(s0, s1);
        if (p0 > p1)
            std::swap(p0, p1);
    }

    bool held(uint32_t ti, double s0, double s1, double p0, double p1, const Frame& rows) const
    {
        for (uint32_t k = first_window_[ti]; k != kNone; k = windows_[k].next) {
            const Window& w = windows_[k];
            if (w.s0 > s0 || w.s1 < s1 || w.p0 > p0 || w.p1 < p1) // held only when truly inside
                continue;
            bool holds = true;
            for (size_t word = rows.lo; word < rows.hi && holds; ++word) {
                const uint64_t old = word >= w.lo && word < w.hi ? memo_words_[w.words_at + word - w.lo] : 0;
                holds = (rows.mightsee[word] & ~old) == 0;
            }
            if (holds)
                return true;
        }
        return false;
    }

    bool dominated_or_remember(uint32_t ti, const Frame& cur)
    {
        double s0, s1, p0, p1;
        intervals(ti, cur, s0, s1, p0, p1);
        if (held(ti, s0, s1, p0, p1, cur))
            return true;
        if (window_count_[ti] >= kWindowsPerPortal)
            return false;
        if (window_count_[ti]++ == 0)
            touched_.push_back(ti);
        windows_.push_back({s0, s1, p0, p1, memo_words_.size(), uint32_t(cur.lo), uint32_t(cur.hi), first_window_[ti]});
        first_window_[ti] = uint32_t(windows_.size() - 1);
        memo_words_.insert(memo_words_.end(), cur.mightsee.begin() + ptrdiff_t(cur.lo), cur.mightsee.begin() + ptrdiff_t(cur.hi));
        return false;
    }

    // Target checks (as the 3-D flow's, portal_vis.h): the walk below `cur` can only add the
    // leaves of its mightsee not yet visible. When there are at most 64, each is checked: a line
    // from the source through the pass that reaches it crosses a portal into it in front of the
    // head's and the pass's lines and inside the separators from the source through the pass.
    // Leaves no such portal survives for are taken out of cur's mightsee; false when none is left.
    bool may_add_leaf(Frame& cur)
    {
        ++target_checks;
        uint32_t unseen = 0;
        for (size_t w = cur.lo; w < cur.hi && unseen <= kTargetCheckLeaves; ++w)
            unseen += bits::popcount(cur.mightsee[w] & ~out_[w]);
        if (unseen > kTargetCheckLeaves)
            return true;
        bool any = false;
        for (size_t w = cur.lo; w < cur.hi; ++w)
            for (uint64_t m = cur.mightsee[w] & ~out_[w]; m != 0; m &= m - 1) {
                const uint32_t leaf = uint32_t(w * 64 + size_t(std::countr_zero(m)));
                if (leaf_reachable(leaf, cur))
                    any = true;
                else
                    cur.mightsee[w] &= ~(uint64_t{1} << std::countr_zero(m));
            }
        return any;
    }

    bool leaf_reachable(uint32_t leaf, Frame& cur)
    {
        for (uint32_t k = g_.first_of_leaf[leaf]; k < g_.first_of_leaf[leaf + 1]; ++k) {
            Segment into = g_.portals[g_.order[k] ^ 1u].seg; // the portal's twin leads into `leaf`
            if (flow2d::clip_front(into, head_->line, g_.tol) && flow2d::clip_front(into, cur.line, g_.tol) &&
                flow2d::clip_by_separators(into, cur.seps, separators_of(cur), g_.tol, separator_counts))
                return true;
        }
        return false;
    }

    // The separators from f's source through its pass (test 0), found once per frame.
    int separators_of(Frame& f)
    {
        if (f.sep_count < 0)
            f.sep_count = flow2d::find_separators(f.source, f.pass, false, g_.tol, separator_counts, f.seps);
        return f.sep_count;
    }

    static bool same(const Segment& a, const Segment& b)
    {
        return a.p[0].x == b.p[0].x && a.p[0].y == b.p[0].y && a.p[1].x == b.p[1].x && a.p[1].y == b.p[1].y;
    }

    bool clip_separators(Frame& prev, Frame& cur)
    {
        // Test 0 from the source the target left whole is the previous frame's: reuse its lines.
        const bool test0 = same(cur.source, prev.source)
                               ? flow2d::clip_by_separators(cur.pass, prev.seps, separators_of(prev), g_.tol,
                                                            separator_counts)
                               : flow2d::clip_to_separators(cur.source, prev.pass, cur.pass, false, g_.tol,
                                                            separator_counts);
        if (!test0)
            return false;
        if (level_ > 1 && !flow2d::clip_to_separators(cur.pass, prev.pass, cur.source, false, g_.tol, separator_counts))
            return false;
        return true;
    }
};

} // namespace

Pvs bake_portal_vis_2d(const PortalSet& input, uint32_t region_count, const VisParams& params, VisReport* report)
{
    const auto start = std::chrono::steady_clock::now();
    const auto since = [](auto t0) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    VisReport rep;
    const Graph g = build_graph(input, region_count);
    const uint32_t n = uint32_t(g.portals.size());
    rep.portals = n / 2;
    rep.portals_skipped = g.skipped;
    rep.threads = thread_count(params.threads, n);
    std::atomic<bool> stop{false};
    std::atomic<size_t> finished{0};
    const bool full = params.method == VisParams::Method::Full;
    const double base_share = full ? 0.05 : 1.0;
    const auto fraction = [&] { return double(finished.load()) / std::max<uint32_t>(n, 1); }; // of the phase

    if (params.probe != nullptr)
        params.probe->found.assign(n, std::nullopt);
    std::vector<uint64_t> flood(size_t(n) * g.words, 0);
    const auto base_progress = params.progress ? std::function<bool(double)>([&](double f) { return params.progress(f * base_share); })
                                               : std::function<bool(double)>();
    bool ok = parallel_items(
        n, rep.threads, base_progress, fraction, stop, [] { return std::vector<uint32_t>(); },
        [&](size_t i, std::vector<uint32_t>& stack) {
            base_vis(g, uint32_t(i), stack, flood.data() + i * g.words);
            finished.fetch_add(1, std::memory_order_relaxed);
        });
    rep.base_seconds = since(start);
    const bool base_finished = ok;

    // Rows per region; a region whose walk did not finish keeps the union of its portals' mightsee.
    std::vector<uint64_t> rows(size_t(region_count) * g.words, 0);
    if (ok)
        for (uint32_t r = 0; r < region_count; ++r) {
            uint64_t* row = rows.data() + size_t(r) * g.words;
            for (uint32_t k = g.first_of_leaf[r]; k < g.first_of_leaf[r + 1]; ++k) {
                const uint64_t* src = flood.data() + size_t(g.order[k]) * g.words;
                for (size_t w = 0; w < g.words; ++w)
                    row[w] |= src[w];
            }
            bits::set(std::span<uint64_t>(row, g.words), r);
        }
    if (ok && full) {
        // Regions by increasing mightsee (ties by index), handed out in that order.
        std::vector<uint32_t> by_rank(region_count);
        std::iota(by_rank.begin(), by_rank.end(), 0u);
        std::vector<size_t> counts(region_count);
        for (uint32_t r = 0; r < region_count; ++r)
            counts[r] = bits::count(std::span<const uint64_t>(rows.data() + size_t(r) * g.words, g.words));
        std::stable_sort(by_rank.begin(), by_rank.end(), [&](uint32_t a, uint32_t b) { return counts[a] < counts[b]; });
        std::vector<uint32_t> rank(region_count);
        for (uint32_t r = 0; r < region_count; ++r)
            rank[by_rank[r]] = r;
        std::unique_ptr<std::atomic<uint8_t>[]> state(new std::atomic<uint8_t>[region_count]);
        for (uint32_t i = 0; i < region_count; ++i)
            state[i].store(portal_vis::kNone, std::memory_order_relaxed);
        finished.store(0);
        std::atomic<size_t> recursions{0}, frames{0}, portal_visible{0}, clips{0}, dominated{0};
        std::atomic<size_t> separator_candidates{0}, separators{0}, checks{0}, prunes{0};
        std::atomic<uint64_t> waited_nanos{0};
        const auto flow_progress = params.progress ? std::function<bool(double)>([&](double f) {
            return params.progress(base_share + f * (1.0 - base_share));
        })
                                                   : std::function<bool(double)>();
        const auto region_fraction = [&] { return double(finished.load()) / std::max<uint32_t>(region_count, 1); };
        struct Scratch {
            std::unique_ptr<Walker> walker;
            std::vector<uint64_t> row;
        };
        ok = parallel_items(
            region_count, thread_count(params.threads, region_count), flow_progress, region_fraction, stop,
            [&] {
                Scratch s;
                s.walker = std::make_unique<Walker>(g, std::clamp(params.level, 0, 3), flood, rows, rank, state.get(), stop);
                s.walker->watch(params.probe);
                s.row.assign(g.words, 0);
                return s;
            },
            [&](size_t item, Scratch& s) {
                const uint32_t r = by_rank[item];
                FlowTicket ticket(state[r]); // Aborted unless done(): a walk waiting on r goes on
                Walker& w = *s.walker;
                const size_t before[] = {w.leaf_recursions, w.frames, w.portal_visible, w.clips, w.dominated,
                                         size_t(w.separator_counts.candidates), size_t(w.separator_counts.clips),
                                         w.target_checks, w.target_check_prunes};
                const uint64_t before_wait = w.waited_nanos;
                if (w.run_region(r, s.row.data())) {
                    std::copy(s.row.begin(), s.row.end(), rows.begin() + ptrdiff_t(size_t(r) * g.words));
                    ticket.done();
                }
                recursions.fetch_add(w.leaf_recursions - before[0]);
                frames.fetch_add(w.frames - before[1]);
                portal_visible.fetch_add(w.portal_visible - before[2]);
                clips.fetch_add(w.clips - before[3]);
                dominated.fetch_add(w.dominated - before[4]);
                separator_candidates.fetch_add(size_t(w.separator_counts.candidates) - before[5]);
                separators.fetch_add(size_t(w.separator_counts.clips) - before[6]);
                checks.fetch_add(w.target_checks - before[7]);
                prunes.fetch_add(w.target_check_prunes - before[8]);
                waited_nanos.fetch_add(w.waited_nanos - before_wait, std::memory_order_relaxed);
                finished.fetch_add(1, std::memory_order_relaxed);
            });
        rep.leaf_recursions = recursions.load();
        rep.frames = frames.load();
        rep.portal_visible = portal_visible.load();
        rep.clips = clips.load();
        rep.dominated_windows = dominated.load();
        rep.separator_candidates = separator_candidates.load();
        rep.separators = separators.load();
        rep.target_checks = checks.load();
        rep.target_check_prunes = prunes.load();
        rep.wait_seconds = double(waited_nanos.load()) * 1e-9;
    }
    rep.cancelled = !ok;

    // A region sees what its walks reached, and itself.
    size_t total = 0;
    Pvs pvs = Pvs::build(region_count, [&](uint32_t r, std::span<uint64_t> row) {
        if (!base_finished) { // no mightsee yet: everything, the only safe answer
            bits::fill(row, region_count);
            total += region_count;
            return true;
        }
        std::copy_n(rows.data() + size_t(r) * g.words, g.words, row.begin());
        total += bits::count(row);
        return true;
    });
    rep.mean_visible = region_count ? double(total) / region_count : 0.0;
    rep.peak_bytes_estimate = (flood.size() + rows.size()) * sizeof(uint64_t) + g.portals.size() * sizeof(Portal2);
    rep.seconds = since(start);
    if (params.progress && !rep.cancelled)
        params.progress(1.0);
    if (report)
        *report = rep;
    return pvs;
}

} // namespace pvs
