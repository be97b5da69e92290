// The 2-D flow's clips (visibility/portal/segment_clip_2d.h) against exact rational arithmetic
// (GMP): no clip removes a point that some exact sight line needs, and no clip keeps much more than
// that, so a window that exact geometry closes is closed. The second property is the one a slack of
// 1e-3 broke: a widened pass endpoint, seen through a separator from a near source, widened a far
// target's window by the slack times the lever arm, and Freedoom 2 MAP12's flow entered fifteen
// times the leaves.
#include "visibility/portal/segment_clip_2d.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <random>

namespace {

using namespace pvs::flow2d;

struct ExactPoint {
    mpq_class x, y;
};
ExactPoint exact(Vec2 p) { return {mpq_class(p.x), mpq_class(p.y)}; }

// Twice the signed area of (a, b, c): > 0 when c is left of the line a -> b.
mpq_class orient(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The point of segment `s` at parameter t (exact).
ExactPoint at(const Segment& s, const mpq_class& t)
{
    const ExactPoint a = exact(s.p[0]), b = exact(s.p[1]);
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

// Where the exact line through p and q meets the exact line of segment s, as the parameter along
// s; false when they are parallel.
bool meet(const ExactPoint& p, const ExactPoint& q, const Segment& s, mpq_class& t)
{
    const ExactPoint a = exact(s.p[0]), b = exact(s.p[1]);
    const mpq_class denom = orient(p, q, b) - orient(p, q, a);
    if (sgn(denom) == 0)
        return false;
    t = -orient(p, q, a) / denom;
    return true;
}

// Whether a point of a segment at parameter t lies between its endpoints.
bool within(const mpq_class& t) { return t >= 0 && t <= 1; }

// A point on a grid of 1/65536 (Doom's 16.16) within +-limit.
Vec2 grid_point(std::mt19937_64& rng, double limit)
{
    std::uniform_int_distribution<int64_t> coord(int64_t(-limit * 65536), int64_t(limit * 65536));
    return {double(coord(rng)) / 65536.0, double(coord(rng)) / 65536.0};
}

TEST(SegmentClip2d, SlackFollowsTheCoordinatesAndStaysFarBelowOnLine)
{
    const FlowTolerances2d doom = FlowTolerances2d::for_extent(32768.0);
    EXPECT_LT(doom.slack, 1e-7);
    EXPECT_GE(doom.slack, 128.0 * 0x1p-53 * 32768.0); // the bound the header derives
    EXPECT_EQ(doom.on_line, 1e-6);
    EXPECT_GT(FlowTolerances2d::for_extent(0x1p40).on_line, 1e-6); // never below 4 slack
}

// clip_front keeps every point of the segment the exact line has in front, and at most a sliver
// behind it.
TEST(SegmentClip2d, ClipFrontKeepsTheExactFrontPart)
{
    std::mt19937_64 rng(7);
    const FlowTolerances2d tol = FlowTolerances2d::for_extent(32768.0);
    int cuts = 0;
    for (int i = 0; i < 5000; ++i) {
        Segment s{{grid_point(rng, 32768), grid_point(rng, 32768)}};
        // The line through two grid points, its unit normal rounded: the line clip_front uses is
        // the one these doubles describe.
        const Vec2 a = grid_point(rng, 32768), b = grid_point(rng, 32768);
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        if (len < 1)
            continue;
        Line l{{-(b.y - a.y) / len, (b.x - a.x) / len}, 0};
        l.d = dot(l.n, a);
        Segment kept = s;
        if (!clip_front(kept, l, tol))
            continue;
        // Exact distance (times nothing: the normal is taken as given) of each original endpoint.
        const mpq_class nx(l.n.x), ny(l.n.y), d(l.d);
        const auto dist = [&](Vec2 p) -> mpq_class { return nx * mpq_class(p.x) + ny * mpq_class(p.y) - d; };
        for (int e = 0; e < 2; ++e) {
            if (kept.p[e].x == s.p[e].x && kept.p[e].y == s.p[e].y)
                continue;
            ++cuts;
            // The moved endpoint lies behind the exact line (so everything in front stays) and
            // at most a few slacks behind it.
            const mpq_class moved = dist(kept.p[e]);
            EXPECT_LE(moved, 0) << "a clip cut into the front part, case " << i;
            EXPECT_GE(moved, mpq_class(-4 * tol.slack)) << "a clip kept far more than its slack, case " << i;
        }
    }
    EXPECT_GT(cuts, 1200); // the sweep exercises the cutting path
}

// Every exact sight line from the source through the pass that meets the target segment meets
// the part clip_to_separators keeps.
TEST(SegmentClip2d, SeparatorsKeepEveryExactSightLine)
{
    std::mt19937_64 rng(11);
    const FlowTolerances2d tol = FlowTolerances2d::for_extent(4096.0);
    int clipped = 0, lines_checked = 0;
    for (int i = 0; i < 1200; ++i) {
        const Segment source{{grid_point(rng, 4096), grid_point(rng, 4096)}};
        const Segment pass{{grid_point(rng, 4096), grid_point(rng, 4096)}};
        const Segment target{{grid_point(rng, 4096), grid_point(rng, 4096)}};
        Segment kept = target;
        SeparatorCounts counts;
        const bool any = clip_to_separators(source, pass, kept, false, tol, counts);
        if (any && kept.p[0].x == target.p[0].x && kept.p[0].y == target.p[0].y && kept.p[1].x == target.p[1].x &&
            kept.p[1].y == target.p[1].y)
            continue;
        ++clipped;
        // Exact lines from 13 x 13 points of the source through points of the pass.
        for (int si = 0; si <= 12; ++si)
            for (int pj = 0; pj <= 12; ++pj) {
                const ExactPoint from = at(source, mpq_class(si, 12)), through = at(pass, mpq_class(pj, 12));
                if (from.x == through.x && from.y == through.y)
                    continue;
                mpq_class t;
                if (!meet(from, through, target, t) || !within(t))
                    continue;
                // Only the half-line beyond the pass is a sight line through it.
                const ExactPoint hit = at(target, t);
                const mpq_class beyond = (hit.x - through.x) * (through.x - from.x) + (hit.y - through.y) * (through.y - from.y);
                if (beyond <= 0)
                    continue;
                ++lines_checked;
                ASSERT_TRUE(any) << "case " << i << ": the target was dropped but an exact sight line reaches it";
                // The hit must be on the kept part: its parameter along the kept segment in [0, 1].
                mpq_class u;
                const ExactPoint k0 = exact(kept.p[0]), k1 = exact(kept.p[1]);
                const mpq_class dx = k1.x - k0.x, dy = k1.y - k0.y;
                u = ((hit.x - k0.x) * dx + (hit.y - k0.y) * dy) / (dx * dx + dy * dy);
                EXPECT_TRUE(u >= 0 && u <= 1) << "case " << i << ": a sight line's hit was cut off";
            }
    }
    EXPECT_GT(clipped, 120);
    EXPECT_GT(lines_checked, 4000) << clipped;
}

// The lever arm: a pass cut by a wall, a source one unit before it, a target a thousand units on,
// half a unit outside the exact cone. A slack of 1e-3 on the cut pass endpoint widens the cone at
// the target by 1e-3 * 1001 = 1.0 and kept the target; the error-bounded slack drops it.
TEST(SegmentClip2d, AWindowThatExactGeometryClosesIsClosedFarAway)
{
    const FlowTolerances2d tol = FlowTolerances2d::for_extent(2048.0);
    const Segment source{{{0, 0}, {0, 1}}};
    Segment pass{{{1, -1}, {1, 2}}};
    const Line wall{{0, -1}, -1}; // front: y < 1
    ASSERT_TRUE(clip_front(pass, wall, tol));
    EXPECT_NEAR(pass.p[1].y, 1.0, 2 * tol.slack);
    // Exact cone at x = 1001: lines from (0, s), s in [0, 1], through (1, p), p in [-1, 1], reach
    // y = s + 1001 (p - s) <= 1001. The target starts half a unit above.
    Segment target{{{1001, 1001.5}, {1001, 1003}}};
    {
        const ExactPoint from{0, 0}, through{1, 1};
        mpq_class t;
        ASSERT_TRUE(meet(from, through, target, t));
        EXPECT_LT(t, 0); // the extreme exact line passes below the target
    }
    SeparatorCounts counts;
    EXPECT_FALSE(clip_to_separators(source, pass, target, false, tol, counts));
    EXPECT_GT(counts.clips, 0u);

    // The same with the old fixed slack of 1e-3 keeps the target: the failure this guards.
    FlowTolerances2d loose = tol;
    loose.slack = 1e-3;
    Segment loose_pass{{{1, -1}, {1, 2}}};
    ASSERT_TRUE(clip_front(loose_pass, wall, loose));
    Segment loose_target{{{1001, 1001.5}, {1001, 1003}}};
    EXPECT_TRUE(clip_to_separators(source, loose_pass, loose_target, false, loose, counts));
}

} // namespace
