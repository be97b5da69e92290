#include "visibility/terrain/horizon_parents.h"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace pvs {
namespace {

struct Point {
    int64_t x, y;
};

template <size_t N>
std::pair<int64_t, int64_t> project(const std::array<Point, N>& points, int64_t ax, int64_t ay)
{
    int64_t lo = points[0].x * ax + points[0].y * ay, hi = lo;
    for (const Point& p : points) {
        const int64_t v = p.x * ax + p.y * ay;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    return {lo, hi};
}

std::array<Point, 4> corners(int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    return {Point{x0, y0}, Point{x1, y0}, Point{x0, y1}, Point{x1, y1}};
}

} // namespace

HorizonParents::HorizonParents(uint32_t width, uint32_t height, uint32_t columns_x, uint32_t columns_y)
    : width_(width), height_(height), span_x_(int32_t(columns_x) - 1), span_y_(int32_t(columns_y) - 1),
      stride_(2 * columns_x - 1)
{
    const size_t offsets = size_t(stride_) * (2 * columns_y - 1);
    first_.assign(offsets + 1, 0);
    strips_.assign(offsets, 0);
    parents_.reserve(offsets * 4);
    const int32_t w = int32_t(width), h = int32_t(height);
    for (uint32_t index = 0; index < offsets; ++index) {
        first_[index] = uint32_t(parents_.size());
        const int32_t dx = offset_dx(index), dy = offset_dy(index);
        uint8_t strip = 0;
        // A strip needs a whole column (row) strictly between R and C.
        if (dx >= w + 1)
            add_strip(dx, dy, true, dx - 1, strip++);
        else if (dx <= -2)
            add_strip(dx, dy, true, dx + 1, strip++);
        if (dy >= h + 1)
            add_strip(dx, dy, false, dy - 1, strip++);
        else if (dy <= -2)
            add_strip(dx, dy, false, dy + 1, strip++);
        strips_[index] = strip;
    }
    first_[offsets] = uint32_t(parents_.size());
    parents_.shrink_to_fit();
    order_.resize(offsets);
    for (uint32_t i = 0; i < offsets; ++i)
        order_[i] = i;
    std::stable_sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) {
        return gap(offset_dx(a), offset_dy(a)) < gap(offset_dx(b), offset_dy(b));
    });
}

void HorizonParents::add_strip(int32_t dx, int32_t dy, bool column_strip, int32_t at, uint8_t strip)
{
    // The hull spans, across the strip, no more than R and C together do.
    const int32_t lo = column_strip ? std::min(0, dy) : std::min(0, dx);
    const int32_t hi = column_strip ? std::max(int32_t(height_) - 1, dy) : std::max(int32_t(width_) - 1, dx);
    const int32_t span = column_strip ? span_y_ : span_x_;
    // Segments along the strip's edges are parallel to it: at the coordinates both R and C
    // span (closed), [parallel_lo, parallel_hi]; empty when lo > hi.
    const int32_t parallel_lo = column_strip ? std::max(0, dy) : std::max(0, dx);
    const int32_t parallel_hi = column_strip ? std::min(int32_t(height_), dy + 1) : std::min(int32_t(width_), dx + 1);
    auto cell_at = [&](int32_t along, int32_t& px, int32_t& py) {
        px = column_strip ? at : along;
        py = column_strip ? along : at;
    };
    for (int32_t along = std::max(lo - 1, -span); along <= std::min(hi + 1, span); ++along) {
        int32_t px, py;
        cell_at(along, px, py);
        const bool inside = meets_hull(dx, dy, px, py, true);
        // A cell that only touches the hull matters to a segment along its side alone.
        const bool beside_parallel = along <= parallel_hi && along + 1 >= parallel_lo;
        if (inside) {
            parents_.push_back({offset_index(px, py), strip, 1, kNone});
        } else if (beside_parallel && meets_hull(dx, dy, px, py, false)) {
            uint32_t partner = kNone;
            for (const int32_t next : {along - 1, along + 1}) {
                int32_t qx, qy;
                cell_at(next, qx, qy);
                if (std::abs(next) <= span && meets_hull(dx, dy, qx, qy, true))
                    partner = offset_index(qx, qy);
            }
            parents_.push_back({offset_index(px, py), strip, 0, partner});
        }
    }
}

uint32_t HorizonParents::gap(int32_t dx, int32_t dy) const
{
    const int32_t x = std::max({0, -dx, dx - int32_t(width_) + 1});
    const int32_t y = std::max({0, -dy, dy - int32_t(height_) + 1});
    return uint32_t(x + y);
}

size_t HorizonParents::memory_bytes() const
{
    return first_.capacity() * sizeof(uint32_t) + strips_.capacity() + parents_.capacity() * sizeof(Parent) +
           order_.capacity() * sizeof(uint32_t);
}

bool HorizonParents::meets_hull(int32_t dx, int32_t dy, int32_t px, int32_t py, bool inside) const
{
    const std::array<Point, 4> source = corners(0, 0, width_, height_);
    const std::array<Point, 4> target = corners(dx, dy, dx + 1, dy + 1);
    const std::array<Point, 4> cell = corners(px, py, px + 1, py + 1);
    std::array<Point, 8> hull_points{};
    std::copy(source.begin(), source.end(), hull_points.begin());
    std::copy(target.begin(), target.end(), hull_points.begin() + 4);
    // Separating axes of two convex sets: the cell's edge normals (x, y) and the hull's. The
    // hull's edges are the two rectangles' own (x, y again) and bridges between like corners
    // of the two (a supporting line touches each rectangle at the corner its normal's signs
    // pick): their normals are among the four like-corner segments' normals. Extra axes can
    // only find real gaps. The open cell meets the hull unless an axis separates them with
    // touching allowed (the hull has an inside, so it is the closure of it).
    std::array<std::pair<int64_t, int64_t>, 6> axes{{{1, 0}, {0, 1}}};
    for (size_t c = 0; c < 4; ++c)
        axes[2 + c] = {-(target[c].y - source[c].y), target[c].x - source[c].x};
    for (const auto& [ax, ay] : axes) {
        if (ax == 0 && ay == 0)
            continue;
        const auto [hull_lo, hull_hi] = project(hull_points, ax, ay);
        const auto [cell_lo, cell_hi] = project(cell, ax, ay);
        if (inside ? (cell_hi <= hull_lo || hull_hi <= cell_lo) : (cell_hi < hull_lo || hull_hi < cell_lo))
            return false;
    }
    return true;
}

} // namespace pvs
