// Which columns a sight line from a footprint must cross before it reaches a column: the
// dependency table of the horizon sweep (terrain_vis.h).
//
// Cells are unit squares in column units; the source footprint R is the w x h rectangle of
// columns at the origin, and a column C is given by its offset (dx, dy) from R's first column.
// A strip is a column (or row) of cells strictly between R and C next to C: when C lies right of
// R with at least one column between, every segment from a point of R to a point of C crosses
// the strip x in [dx - 1, dx] over its whole width; likewise left, above and below. A segment
// crosses a strip through the inside of a strip cell, or (a horizontal segment, for a column
// strip) along the shared edge of two strip cells. So a strip's parents are:
//  - the strip cells whose inside meets the convex hull of R and C (a segment can cross them),
//  - the strip cells that only touch the hull beside a line parallel to the strip that both R and
//    C reach (a segment along the hull's edge can run along their side there): such a segment is
//    also on the side of the inside cell across that edge (the partner), so what lies before the
//    partner bounds it, and the touching cell adds only its height.
// C has up to two strips (a column one and a row one); each gives a lower bound of its own, and
// the sweep keeps the larger. A cell of a strip is nearer R in the sum of the column gaps along
// x and y than C is (one gap smaller, the other no larger), so sweeping columns by that sum
// (order()) computes every parent before its child. Hull tests are exact: separating axes on
// the integer corners.
//
// Tables depend only on the footprint's size and the grid's size, so one table serves every
// footprint of that size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pvs {

class HorizonParents {
public:
    struct Parent {
        uint32_t offset; // offset index of the strip cell
        uint8_t strip;   // 0 or 1: which of C's strips
        uint8_t inside;  // 1: its inside meets the hull; 0: it only touches it
        uint32_t partner; // inside == 0: the inside cell across the shared edge (offset index), or kNone
    };
    static constexpr uint32_t kNone = UINT32_MAX;

    // For footprints of `width` x `height` columns in a grid of columns_x x columns_y.
    HorizonParents(uint32_t width, uint32_t height, uint32_t columns_x, uint32_t columns_y);

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    // Offsets run over dx in [-(columns_x - 1), columns_x - 1], likewise dy.
    uint32_t offset_index(int32_t dx, int32_t dy) const
    {
        return uint32_t(dx + span_x_) + uint32_t(dy + span_y_) * stride_;
    }
    int32_t offset_dx(uint32_t index) const { return int32_t(index % stride_) - span_x_; }
    int32_t offset_dy(uint32_t index) const { return int32_t(index / stride_) - span_y_; }
    // Column gaps between R and the cell along x plus along y (0 for R's own cells).
    uint32_t gap(int32_t dx, int32_t dy) const;
    // Strips of the cell at this offset index (0, 1 or 2) and their parents, strip 0 first.
    uint32_t strip_count(uint32_t index) const { return strips_[index]; }
    const Parent* parents_begin(uint32_t index) const { return parents_.data() + first_[index]; }
    const Parent* parents_end(uint32_t index) const { return parents_.data() + first_[index + 1]; }
    // Every offset index, by gap (parents before children).
    const std::vector<uint32_t>& order() const { return order_; }
    size_t memory_bytes() const;

    // Whether the closed (inside = false) or open (inside = true) unit square at (px, py) meets
    // the convex hull of R and the unit square at (dx, dy). Exposed for tests.
    bool meets_hull(int32_t dx, int32_t dy, int32_t px, int32_t py, bool inside = false) const;

private:
    void add_strip(int32_t dx, int32_t dy, bool column_strip, int32_t at, uint8_t strip);

    uint32_t width_, height_;
    int32_t span_x_, span_y_;
    uint32_t stride_;
    std::vector<uint32_t> first_;  // per offset index, + 1
    std::vector<uint8_t> strips_;  // per offset index
    std::vector<Parent> parents_;
    std::vector<uint32_t> order_;
};

} // namespace pvs
