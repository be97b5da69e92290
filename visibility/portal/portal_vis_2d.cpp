#include "visibility/portal/portal_vis_2d.h"

#include "visibility/bit_row.h"
#include "visibility/portal/prune_lag.h"
#include "visibility/worker_pool.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

namespace pvs {

namespace {

using portal_vis::FlowTicket;
using portal_vis::PruneLag;

// The flow's tolerances (portal_vis_2d.h, "Conservative"):
//  - kOnLine: a segment is in front of a line when some point of it is more than kOnLine in
//    front. Lines through a segment with no point further in front pass within kOnLine of
//    the line's wall: a window under 2 kOnLine wide, far below what a pixel or the reference's
//    beam (0.05) can show, and exactly nothing for the collinear portals Doom's split lines make
//    (walks along them would otherwise multiply). glVIS's ON_EPSILON was 0.1 here, which lost
//    sight lines up to 0.1 wide.
//  - kSlack: a clip keeps the part of a segment up to kSlack behind its line, a superset of the
//    exact front part. kSlack is three orders above the round-off of a clip or a separator (a
//    line through two points at least kMinSeparator apart, coordinates up to 2^15: its distance
//    error 2^15 units away is about 1e-6).
//  - kMinSeparator: separators through two points closer than this are not used (glVIS's
//    ON_EPSILON as a length): not clipping is always safe, and a short base makes a line whose
//    direction round-off grows with distance.
constexpr double kOnLine = 1e-6;
constexpr double kSlack = 1e-3;
constexpr double kMinSeparator = 0.1;
// Portals ranked more than this below a walk's own prune it with their final vis. Part of the
// definition of the result. 8 rather than the 3-D baker's 32: the 2-D walks are short, so a
// smaller lag seldom makes a thread wait and prunes more (MAP28 1.82 s -> 1.73 s).
constexpr uint32_t kPruneLag2d = 8;

struct Vec2 {
    double x = 0, y = 0;
};
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

struct Line {
    Vec2 n; // unit normal
    double d = 0;
    double distance(Vec2 p) const { return dot(n, p) - d; }
    Line flipped() const { return {{-n.x, -n.y}, -d}; }
};

struct Segment {
    Vec2 p[2];
};

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

// Some point more than kOnLine in front of (behind) `l`.
bool has_point_in_front(const Segment& s, const Line& l)
{
    return l.distance(s.p[0]) > kOnLine || l.distance(s.p[1]) > kOnLine;
}
bool has_point_behind(const Segment& s, const Line& l)
{
    return l.distance(s.p[0]) < -kOnLine || l.distance(s.p[1]) < -kOnLine;
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
            if (bits::test(row, t.leaf) || !has_point_in_front(t.seg, p.line) || !has_point_behind(p.seg, t.line))
                continue;
            bits::set(row, t.leaf);
            stack.push_back(t.leaf);
        }
    }
}

// Keeps the part of `s` in front of `l`, and up to kSlack behind it: a superset of the exact
// front part. False when no point of `s` is more than kOnLine in front; `s` unchanged when none
// is more than kSlack behind.
[[gnu::always_inline]] inline bool clip_front(Segment& s, const Line& l)
{
    const double d0 = l.distance(s.p[0]), d1 = l.distance(s.p[1]);
    if (!(d0 > kOnLine) && !(d1 > kOnLine))
        return false;
    const bool back0 = d0 < -kSlack, back1 = d1 < -kSlack;
    if (!back0 && !back1)
        return true;
    const double t = (d0 + kSlack) / (d0 - d1); // where the distance is -kSlack
    const Vec2 mid{s.p[0].x + t * (s.p[1].x - s.p[0].x), s.p[0].y + t * (s.p[1].y - s.p[0].y)};
    s.p[back0 ? 0 : 1] = mid;
    return true;
}

// clip_front against the line through `b` with the unnormalised normal `n` (|n|^2 = length2):
// distances are n . (p - b), compared as squares against the tolerances times |n|, so a clip that
// cuts nothing (most separator clips) takes no square root.
[[gnu::always_inline]] inline bool clip_front_scaled(Segment& s, Vec2 n, Vec2 b, double length2)
{
    const double d0 = n.x * (s.p[0].x - b.x) + n.y * (s.p[0].y - b.y);
    const double d1 = n.x * (s.p[1].x - b.x) + n.y * (s.p[1].y - b.y);
    const double on2 = kOnLine * kOnLine * length2, slack2 = kSlack * kSlack * length2;
    if (!(d0 > 0 && d0 * d0 > on2) && !(d1 > 0 && d1 * d1 > on2))
        return false;
    const bool back0 = d0 < 0 && d0 * d0 > slack2, back1 = d1 < 0 && d1 * d1 > slack2;
    if (!back0 && !back1)
        return true;
    const double t = (d0 + kSlack * std::sqrt(length2)) / (d0 - d1); // where the distance is -kSlack
    const Vec2 mid{s.p[0].x + t * (s.p[1].x - s.p[0].x), s.p[0].y + t * (s.p[1].y - s.p[0].y)};
    s.p[back0 ? 0 : 1] = mid;
    return true;
}

// Quake's ClipToSeparators in the plane: for each endpoint of `source`, the first endpoint of
// `pass` giving a line with the other source endpoint strictly on one side and the other pass
// endpoint strictly on the other; `target` is clipped to the pass side (the source side when
// `flip`). False when the target is clipped away.
bool clip_to_separators(const Segment& source, const Segment& pass, Segment& target, bool flip)
{
    for (int i = 0; i < 2; ++i) {
        const Vec2 a = source.p[i], other_a = source.p[1 - i];
        for (int j = 0; j < 2; ++j) {
            const Vec2 b = pass.p[j];
            const Vec2 v{b.x - a.x, b.y - a.y};
            const double length2 = v.x * v.x + v.y * v.y;
            if (length2 < kMinSeparator * kMinSeparator)
                continue;
            // The candidate's unnormalised normal: distances are compared against kSlack times
            // its length, so only the line that is used needs a square root. (|d| <= slack *
            // length is tested as d^2 <= slack^2 * length^2.) A candidate is used only when the
            // other source end is surely behind it and the other pass end surely in front: then
            // every line from the source through the pass stays in front beyond the pass, so the
            // clip removes nothing visible; an unsure candidate is skipped, which only adds.
            Vec2 n{-v.y, v.x};
            const double limit2 = kSlack * kSlack * length2;
            double ds = n.x * (other_a.x - b.x) + n.y * (other_a.y - b.y);
            if (ds * ds <= limit2)
                continue; // the source lies along it
            if (ds > 0)
                n = {-n.x, -n.y}; // the source behind
            const double dp = n.x * (pass.p[1 - j].x - b.x) + n.y * (pass.p[1 - j].y - b.y);
            if (!(dp > 0 && dp * dp > limit2))
                continue; // the pass not strictly in front: not a separator
            if (flip)
                n = {-n.x, -n.y};
            if (!clip_front_scaled(target, n, b, length2))
                return false;
            break;
        }
    }
    return true;
}

struct Frame {
    std::vector<uint64_t> mightsee; // only words [lo, hi) are meaningful (the rest: zero)
    size_t lo = 0, hi = 0;
    Segment source, pass;
    Line line;
    bool has_pass = false;
};

class Walker {
public:
    Walker(const Graph& g, int level, const std::vector<uint64_t>& flood, const std::vector<uint64_t>& vis,
           const std::vector<uint32_t>& rank, const std::atomic<uint8_t>* state, const std::atomic<bool>& stop)
        : g_(g), level_(level), flood_(flood), vis_(vis), rank_(rank), lag_(rank.data(), state, kPruneLag2d), stop_(stop),
          on_chain_(g.leaf_count, 0)
    {
    }

    // Walks from directed portal pi into `out` (words). False when stopped.
    bool run(uint32_t pi, uint64_t* out)
    {
        const Portal2& p = g_.portals[pi];
        out_ = std::span<uint64_t>(out, g_.words);
        std::fill(out_.begin(), out_.end(), 0);
        head_ = &p;
        my_rank_ = rank_[pi];
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

    // Record chains into probe->found (flow_chain.h), as the 3-D flow does.
    void watch(ChainProbe* probe) { probe_ = probe; }

    size_t leaf_recursions = 0;
    uint64_t waited_nanos = 0;
    size_t dominated = 0; // walks not taken: an earlier window held them

private:
    const Graph& g_;
    int level_;
    const std::vector<uint64_t>& flood_;
    const std::vector<uint64_t>& vis_;
    const std::vector<uint32_t>& rank_;
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

    // The row a walk ANDs in when it passes portal t: its final vis when t ranks well below
    // this walk's portal (waiting for it when needed), else its mightsee (also when t's walk was
    // aborted: a cancelled bake keeps what it has).
    const uint64_t* prune_row(uint32_t t)
    {
        if (lag_.uses_final(t, my_rank_) && lag_.await_final(t, waited_nanos))
            return vis_.data() + size_t(t) * g_.words;
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
            cur.pass = t.seg;
            if (!clip_front(cur.pass, head_->line))
                continue;
            cur.source = before.source;
            if (!clip_front(cur.source, back))
                continue;
            cur.line = t.line;
            cur.has_pass = true;
            if (before.has_pass && !clip_separators(before, cur))
                continue;
            const uint64_t* row = prune_row(ti);
            // The walk's rows shrink fast: AND only the words still holding bits, and keep the
            // span of the result's non-zero words.
            uint64_t more = 0;
            size_t lo = SIZE_MAX, hi = 0;
            for (size_t w = before.lo; w < before.hi; ++w) {
                const uint64_t m = before.mightsee[w] & row[w];
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

    bool clip_separators(const Frame& prev, Frame& cur) const
    {
        if (!clip_to_separators(cur.source, prev.pass, cur.pass, false))
            return false;
        if (level_ > 1 && !clip_to_separators(cur.pass, prev.pass, cur.source, false))
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

    std::vector<uint64_t> vis = flood; // unfinished portals keep their mightsee
    std::vector<uint8_t> finished_walk(n, 0);
    if (ok && full) {
        std::vector<uint32_t> by_rank(n);
        std::iota(by_rank.begin(), by_rank.end(), 0u);
        std::vector<size_t> counts(n);
        for (uint32_t i = 0; i < n; ++i)
            counts[i] = bits::count(std::span<const uint64_t>(flood.data() + size_t(i) * g.words, g.words));
        std::stable_sort(by_rank.begin(), by_rank.end(), [&](uint32_t a, uint32_t b) { return counts[a] < counts[b]; });
        std::vector<uint32_t> rank(n);
        for (uint32_t r = 0; r < n; ++r)
            rank[by_rank[r]] = r;
        std::unique_ptr<std::atomic<uint8_t>[]> state(new std::atomic<uint8_t>[n]);
        for (uint32_t i = 0; i < n; ++i)
            state[i].store(portal_vis::kNone, std::memory_order_relaxed);
        finished.store(0);
        std::atomic<size_t> recursions{0};
        std::atomic<uint64_t> waited_nanos{0};
        const auto flow_progress = params.progress ? std::function<bool(double)>([&](double f) {
            return params.progress(base_share + f * (1.0 - base_share));
        })
                                                   : std::function<bool(double)>();
        struct Scratch {
            std::unique_ptr<Walker> walker;
            std::vector<uint64_t> row;
        };
        ok = parallel_items(
            n, rep.threads, flow_progress, fraction, stop,
            [&] {
                Scratch s;
                s.walker = std::make_unique<Walker>(g, std::clamp(params.level, 0, 3), flood, vis, rank, state.get(), stop);
                s.walker->watch(params.probe);
                s.row.assign(g.words, 0);
                return s;
            },
            [&](size_t item, Scratch& s) {
                const uint32_t pi = by_rank[item];
                FlowTicket ticket(state[pi]); // Aborted unless done(): a walk waiting on pi goes on
                const size_t before_recursions = s.walker->leaf_recursions;
                const uint64_t before_wait = s.walker->waited_nanos;
                if (s.walker->run(pi, s.row.data())) {
                    std::copy(s.row.begin(), s.row.end(), vis.begin() + ptrdiff_t(size_t(pi) * g.words));
                    finished_walk[pi] = 1;
                    ticket.done();
                }
                recursions.fetch_add(s.walker->leaf_recursions - before_recursions);
                waited_nanos.fetch_add(s.walker->waited_nanos - before_wait, std::memory_order_relaxed);
                finished.fetch_add(1, std::memory_order_relaxed);
            });
        rep.leaf_recursions = recursions.load();
        rep.wait_seconds = double(waited_nanos.load()) * 1e-9;
    }
    rep.cancelled = !ok;

    // A region sees the union of its outgoing portals' vis, and itself.
    size_t total = 0;
    Pvs pvs = Pvs::build(region_count, [&](uint32_t r, std::span<uint64_t> row) {
        if (!base_finished) { // no mightsee yet: everything, the only safe answer
            bits::fill(row, region_count);
            total += region_count;
            return true;
        }
        std::fill(row.begin(), row.end(), 0);
        for (uint32_t k = g.first_of_leaf[r]; k < g.first_of_leaf[r + 1]; ++k) {
            const uint64_t* src = vis.data() + size_t(g.order[k]) * g.words;
            if (bits::test(std::span<const uint64_t>(src, g.words), r))
                ++rep.saw_into_own_region;
            for (size_t w = 0; w < g.words; ++w)
                row[w] |= src[w];
        }
        bits::set(row, r);
        total += bits::count(row);
        return true;
    });
    rep.mean_visible = region_count ? double(total) / region_count : 0.0;
    rep.peak_bytes_estimate = (flood.size() + vis.size()) * sizeof(uint64_t) + g.portals.size() * sizeof(Portal2);
    rep.seconds = since(start);
    if (params.progress && !rep.cancelled)
        params.progress(1.0);
    if (report)
        *report = rep;
    return pvs;
}

} // namespace pvs
