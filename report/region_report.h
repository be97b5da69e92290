// One row per region of a zone, for `pvscope stats --regions-csv`: its flags, bounds, faces and
// triangles, how many regions its PVS row holds and how many rows hold it, and its neighbours
// through portals.
//
// Visibility comes from the zone's baked PVS: `visible` is the region's row count (-1 without a
// square PVS: a grid zone's rows are cells), `visible_from` the number of rows holding the
// region (cells, in a grid zone; -1 without a PVS). `portal_neighbours` counts the distinct
// other regions the portals join it to: the zone's own portals when it carries them, else
// those built from its tree (none for a zone without a tree, -1 then).
#pragma once

#include "report/json_csv.h"
#include "visibility/zone.h"

#include <cstdint>
#include <vector>

namespace pvs {

struct RegionRow {
    uint32_t region = 0;
    uint32_t flags = 0;
    Aabb bounds;
    uint32_t faces = 0;
    uint64_t triangles = 0;
    int64_t visible = -1;
    int64_t visible_from = -1;
    int64_t portal_neighbours = -1;
};

std::vector<RegionRow> region_rows(const Zone& zone);

// The row as CSV fields: region, name (when the zone names its regions), flags ("water|lava"),
// min/max x y z, faces, triangles, visible, visible_from, portal_neighbours (empty for -1).
CsvFields region_fields(const Zone& zone, const RegionRow& row);

} // namespace pvs
