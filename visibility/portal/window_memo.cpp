// Dominated windows of the 3-D portal flow (window_memo.h).
#include "visibility/portal/window_memo.h"

#include <cmath>

namespace pvs::portal_vis {

bool polygon_inside(const Vec* inner, uint32_t inner_count, const Vec* outer, uint32_t outer_count, const Vec& normal)
{
    if (outer_count < 3)
        return false;
    Vec centre(0.0);
    for (uint32_t i = 0; i < outer_count; ++i)
        centre += outer[i];
    centre /= double(outer_count);
    for (uint32_t i = 0; i < outer_count; ++i) {
        const Vec& a = outer[i];
        const Vec edge = outer[i + 1 == outer_count ? 0 : i + 1] - a;
        Vec inward = glm::cross(normal, edge);
        const double length = glm::length(inward);
        if (!(length > 1e-12))
            continue; // a repeated point: no edge
        inward /= length;
        const double centre_side = glm::dot(inward, centre - a);
        if (std::abs(centre_side) < 1e-9)
            return false; // a degenerate outer: its inside is unknown
        if (centre_side < 0.0)
            inward = -inward;
        for (uint32_t k = 0; k < inner_count; ++k)
            if (glm::dot(inward, inner[k] - a) < -kInsideTolerance)
                return false;
    }
    return true;
}

bool WindowMemo::holds(const Window& w, const WRef& source, const Vec& source_normal, const WRef& pass,
                       const Vec& pass_normal, const uint64_t* mightsee, uint32_t lo, uint32_t hi) const
{
    // The mightsee first (a few words), then the polygons.
    for (uint32_t word = lo; word < hi; ++word) {
        const uint64_t old = word >= w.lo && word < w.hi ? words_[w.words_at + (word - w.lo)] : 0;
        if ((mightsee[word] & ~old) != 0)
            return false;
    }
    return polygon_inside(pass.points, pass.count, &points_[w.pass_at], w.pass_count, pass_normal) &&
           polygon_inside(source.points, source.count, &points_[w.source_at], w.source_count, source_normal);
}

bool WindowMemo::dominated_or_remember(uint32_t q, const WRef& source, const Vec& source_normal, const WRef& pass,
                                       const Vec& pass_normal, const uint64_t* mightsee, uint32_t lo, uint32_t hi)
{
    for (uint32_t k = first_[q]; k != kNone; k = windows_[k].next)
        if (holds(windows_[k], source, source_normal, pass, pass_normal, mightsee, lo, hi)) {
            ++dominated_;
            return true;
        }
    if (count_[q] >= kWindowsPerPortal)
        return false;
    if (count_[q]++ == 0)
        touched_.push_back(q);
    Window w;
    w.source_at = uint32_t(points_.size());
    w.source_count = source.count;
    points_.insert(points_.end(), source.points, source.points + source.count);
    w.pass_at = uint32_t(points_.size());
    w.pass_count = pass.count;
    points_.insert(points_.end(), pass.points, pass.points + pass.count);
    w.words_at = words_.size();
    w.lo = lo;
    w.hi = hi;
    words_.insert(words_.end(), mightsee + lo, mightsee + hi);
    w.next = first_[q];
    first_[q] = uint32_t(windows_.size());
    windows_.push_back(w);
    return false;
}

void WindowMemo::clear()
{
    for (uint32_t q : touched_) {
        first_[q] = kNone;
        count_[q] = 0;
    }
    touched_.clear();
    windows_.clear();
    points_.clear();
    words_.clear();
}

} // namespace pvs::portal_vis
