// PVS rows and columns as region lists, portal neighbours, and the difference of two rows: what
// the region and bake panels list. Not hot (a panel's lists, recomputed when the region changes).
#pragma once

#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <cstdint>
#include <vector>

namespace pvs::gui {

// Regions `region` sees (its row), ascending. A missing row lists every region. Empty for a
// region out of range.
std::vector<uint32_t> pvs_row_regions(const Pvs& pvs, uint32_t region);

// Regions that see `region` (its column: every r whose row has it), ascending, read a slice of
// rows at a time so a panel can spread it over frames: on an open zone it walks 33 k compressed
// rows (tens of ms), and the region a panel follows changes whenever the camera enters another.
// A region past the last lists nothing.
struct PvsColumnScan {
    uint32_t region = 0;
    uint32_t next_row = 0;         // rows below it are read
    std::vector<uint32_t> regions; // found so far, ascending

    void restart(uint32_t column);
    // Reads up to `max_rows` more rows of `pvs` (the same PVS every call since restart); true when
    // every row has been read.
    bool step(const Pvs& pvs, uint32_t max_rows);
};

// Regions sharing a portal with `region`, ascending, no duplicates.
std::vector<uint32_t> portal_neighbours(const PortalSet& portals, uint32_t region);

// Two ascending lists' differences: only_a = in a and not b, only_b = in b and not a.
struct RegionDiff {
    std::vector<uint32_t> only_a, only_b;
};
RegionDiff diff_regions(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b);

// Over every row of two PVSs of the same region count: how many (from, to) pairs only a has,
// and only b has. Both zero when the counts differ (nothing comparable).
struct PvsDiffCounts {
    uint64_t only_a = 0, only_b = 0;
};
PvsDiffCounts diff_pvs(const Pvs& a, const Pvs& b);

} // namespace pvs::gui
