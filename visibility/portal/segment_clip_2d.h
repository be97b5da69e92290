// The geometry of the 2-D portal flow (portal_vis_2d.h): segments in the plane clipped to the
// front of lines, and glVIS's separating lines between a source and a pass segment, evaluated in
// double with tolerances that follow from the round-off, not from taste.
//
// Contract. Every clip returns a superset of the exact result for the segments it is given (their
// endpoints taken as exact numbers): the part of a segment in front of a line is kept together with
// at most `slack` of it behind the line, so a chain of clips never removes a point that exact
// arithmetic would keep, and never keeps more than `slack` beyond it per clip. The one deliberate
// loss is `on_line`: a segment with no point more than on_line in front of a line is dropped (the
// lines through it that stay in front form a window under 2 on_line wide; along Doom's split lines,
// where portals are collinear, exactly nothing).
//
// Why `slack` is safe (u = 2^-53, M = the largest coordinate magnitude of any endpoint; clipped
// endpoints stay on their input segments, so within M):
//  - a distance to a portal's line (unit normal n, offset d, computed from its endpoints) is off by
//    at most ~9 u M from rounding the dot product and ~12 u M from the normal's own rounding;
//  - a distance to a separator through two endpoints a, b (normal perp(b - a), not normalised) is
//    off by at most ~26 u M |b - a| (the differences, the products and the sum each round once);
//  - a clip cuts where the computed distance is -slack: the cut point's true distance is within
//    3 times the distance error plus u M of it.
// So any slack of 128 u M or more keeps the exact front part; FlowTolerances2d::for_extent takes
// 2^-40 M (64 times that): 3e-8 at Doom's largest coordinates (2^15). A fixed slack must not be
// larger than needed: every clip widens a window by it, a separator through widened endpoints
// widens the next window by it times the chain's lever arm (a far target over a near base), and
// on a map of small subsectors windows that should close then stay open for thousands of steps
// (a slack of 1e-3 made Freedoom 2 MAP12's flow enter 3.45 billion leaves instead of 0.23).
//
// Separators: for each endpoint a of the source, the first endpoint b of the pass that gives a
// line with the other source endpoint more than slack behind and the other pass endpoint more than
// slack in front (then every line from the source through the pass stays in front of it beyond
// the pass); an unsure candidate is skipped, which only keeps more. Candidates through points
// closer than min_separator are not used (not clipping is always safe).
#pragma once

namespace pvs::flow2d {

struct Vec2 {
    double x = 0, y = 0;
};
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

struct Line {
    Vec2 n; // unit normal, pointing to the front
    double d = 0;
    double distance(Vec2 p) const { return dot(n, p) - d; }
    Line flipped() const { return {{-n.x, -n.y}, -d}; }
};

struct Segment {
    Vec2 p[2];
};

struct FlowTolerances2d {
    double on_line = 1e-6;       // a segment is in front when a point is more than this in front
    double slack = 0x1p-25;      // a clip keeps up to this behind its line
    double min_separator = 0.1;  // separators through closer points are not used
    // The tolerances for coordinates up to `extent` in magnitude (see above): slack = 2^-40
    // extent, on_line = 1e-6 or, for extents past 2^34 (no real map), 4 slack.
    static FlowTolerances2d for_extent(double extent);
};

// Some point more than on_line in front of (behind) `l`.
inline bool has_point_in_front(const Segment& s, const Line& l, const FlowTolerances2d& tol)
{
    return l.distance(s.p[0]) > tol.on_line || l.distance(s.p[1]) > tol.on_line;
}
inline bool has_point_behind(const Segment& s, const Line& l, const FlowTolerances2d& tol)
{
    return l.distance(s.p[0]) < -tol.on_line || l.distance(s.p[1]) < -tol.on_line;
}

// Keeps the part of `s` in front of `l`, and up to slack behind it. False when no point of `s` is
// more than on_line in front; `s` unchanged when none is more than slack behind.
[[gnu::always_inline]] inline bool clip_front(Segment& s, const Line& l, const FlowTolerances2d& tol)
{
    const double d0 = l.distance(s.p[0]), d1 = l.distance(s.p[1]);
    if (!(d0 > tol.on_line) && !(d1 > tol.on_line))
        return false;
    const bool back0 = d0 < -tol.slack, back1 = d1 < -tol.slack;
    if (!back0 && !back1)
        return true;
    const double t = (d0 + tol.slack) / (d0 - d1); // where the distance is -slack
    const Vec2 mid{s.p[0].x + t * (s.p[1].x - s.p[0].x), s.p[0].y + t * (s.p[1].y - s.p[0].y)};
    s.p[back0 ? 0 : 1] = mid;
    return true;
}

// Counts what the separator search does, for the flow's work counters.
struct SeparatorCounts {
    unsigned long long candidates = 0; // candidate lines evaluated
    unsigned long long clips = 0;      // separators a target was clipped by
};

// A separating line through `b` with the unnormalised normal `n` (|n|^2 = length2), the side to
// keep in front.
struct SeparatorLine {
    Vec2 n, b;
    double length2 = 0;
};

// The separators from `source` through `pass` (at most one per source endpoint, in endpoint
// order), keeping the pass side (the source side when `flip`). Returns how many were found.
int find_separators(const Segment& source, const Segment& pass, bool flip, const FlowTolerances2d& tol,
                    SeparatorCounts& counts, SeparatorLine out[2]);

// Clips `target` by `count` separators in order. False when the target is clipped away.
bool clip_by_separators(Segment& target, const SeparatorLine* lines, int count, const FlowTolerances2d& tol,
                        SeparatorCounts& counts);

// find_separators, then clip_by_separators: `target` clipped to the pass side of the separators
// from `source` through `pass` (the source side when `flip`). False when it is clipped away.
bool clip_to_separators(const Segment& source, const Segment& pass, Segment& target, bool flip,
                        const FlowTolerances2d& tol, SeparatorCounts& counts);

} // namespace pvs::flow2d
