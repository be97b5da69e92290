#include "visibility/portal/segment_clip_2d.h"

#include <algorithm>
#include <cmath>

namespace pvs::flow2d {

FlowTolerances2d FlowTolerances2d::for_extent(double extent)
{
    FlowTolerances2d tol;
    tol.slack = std::ldexp(std::max(extent, 1.0), -40);
    tol.on_line = std::max(1e-6, 4.0 * tol.slack);
    return tol;
}

namespace {

// clip_front against the line through `b` with the unnormalised normal `n` (|n|^2 = length2):
// distances are n . (p - b), compared as squares against the tolerances times |n|, so a clip that
// cuts nothing (most separator clips) takes no square root.
[[gnu::always_inline]] inline bool clip_front_scaled(Segment& s, Vec2 n, Vec2 b, double length2,
                                                     const FlowTolerances2d& tol)
{
    const double d0 = n.x * (s.p[0].x - b.x) + n.y * (s.p[0].y - b.y);
    const double d1 = n.x * (s.p[1].x - b.x) + n.y * (s.p[1].y - b.y);
    const double on2 = tol.on_line * tol.on_line * length2, slack2 = tol.slack * tol.slack * length2;
    if (!(d0 > 0 && d0 * d0 > on2) && !(d1 > 0 && d1 * d1 > on2))
        return false;
    const bool back0 = d0 < 0 && d0 * d0 > slack2, back1 = d1 < 0 && d1 * d1 > slack2;
    if (!back0 && !back1)
        return true;
    const double t = (d0 + tol.slack * std::sqrt(length2)) / (d0 - d1); // where the distance is -slack
    const Vec2 mid{s.p[0].x + t * (s.p[1].x - s.p[0].x), s.p[0].y + t * (s.p[1].y - s.p[0].y)};
    s.p[back0 ? 0 : 1] = mid;
    return true;
}

} // namespace

int find_separators(const Segment& source, const Segment& pass, bool flip, const FlowTolerances2d& tol,
                    SeparatorCounts& counts, SeparatorLine out[2])
{
    int found = 0;
    for (int i = 0; i < 2; ++i) {
        const Vec2 a = source.p[i], other_a = source.p[1 - i];
        for (int j = 0; j < 2; ++j) {
            const Vec2 b = pass.p[j];
            const Vec2 v{b.x - a.x, b.y - a.y};
            const double length2 = v.x * v.x + v.y * v.y;
            if (length2 < tol.min_separator * tol.min_separator)
                continue;
            ++counts.candidates;
            // The unnormalised normal: |d| <= slack * length is tested as d^2 <= slack^2 *
            // length^2, so only the line that is used needs a square root.
            Vec2 n{-v.y, v.x};
            const double limit2 = tol.slack * tol.slack * length2;
            const double ds = n.x * (other_a.x - b.x) + n.y * (other_a.y - b.y);
            if (ds * ds <= limit2)
                continue; // the source lies along it
            if (ds > 0)
                n = {-n.x, -n.y}; // the source behind
            const double dp = n.x * (pass.p[1 - j].x - b.x) + n.y * (pass.p[1 - j].y - b.y);
            if (!(dp > 0 && dp * dp > limit2))
                continue; // the pass not surely in front: not a separator
            if (flip)
                n = {-n.x, -n.y};
            out[found++] = {n, b, length2};
            break;
        }
    }
    return found;
}

bool clip_by_separators(Segment& target, const SeparatorLine* lines, int count, const FlowTolerances2d& tol,
                        SeparatorCounts& counts)
{
    for (int k = 0; k < count; ++k) {
        ++counts.clips;
        if (!clip_front_scaled(target, lines[k].n, lines[k].b, lines[k].length2, tol))
            return false;
    }
    return true;
}

bool clip_to_separators(const Segment& source, const Segment& pass, Segment& target, bool flip,
                        const FlowTolerances2d& tol, SeparatorCounts& counts)
{
    SeparatorLine lines[2];
    const int count = find_separators(source, pass, flip, tol, counts, lines);
    return clip_by_separators(target, lines, count, tol, counts);
}

} // namespace pvs::flow2d
