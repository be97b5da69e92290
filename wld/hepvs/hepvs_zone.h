// A .hepvs attached to its OBJ zone, and a grid zone's PVS written back as a .hepvs.
//
// attach_hepvs: the grid becomes the zone's ViewGrid (view_grid.h, grid_size OBJ units per grid
// unit: 16 unless the level was baked with another -g) and each cell's object names become a
// PVS row over the zone's regions (Pvs::build_rows, one row per cell). Names are matched to the
// regions' names (Zone::region_names, the OBJ's objects): a name listed twice in the OBJ means its
// first object, as the baker resolves it; a name the OBJ lacks is ignored, as the engine ignores
// it, and counted in the zone's notes. Throws FileError (the .hepvs path, offset 0) when the zone
// has no region names or no name of the file matches any object (the wrong OBJ).
//
// hepvs_from_zone: the zone's grid and PVS rows as a HepvsFile, names in region order and each
// cell's objects ascending. std::invalid_argument when the zone has no grid, no PVS of one row
// per cell, no names, or more than 65535 objects.
#pragma once

#include "visibility/zone.h"
#include "wld/hepvs/hepvs_file.h"

#include <string>

namespace pvs {

inline constexpr float kDefaultHepvsGridSize = 16.0f;

void attach_hepvs(Zone& zone, const HepvsFile& hepvs, const std::string& hepvs_path,
                  float grid_size = kDefaultHepvsGridSize);
HepvsFile hepvs_from_zone(const Zone& zone);

// A region PVS (a BSP zone's, one row per region) as a .hepvs over the zone written as an OBJ
// (obj_writer.h: one object per region, named as region_names or "region_<r>"): the baker's grid
// (min over every vertex in OBJ space / grid_size, cells of cell_size grid units, counts rounded
// up), and for each cell the union of the rows of every region whose bounds touch the cell: a
// camera in that cell is in one of them, so the row is conservative (it over-covers where a
// region's box is larger than its cell). std::invalid_argument when the zone has no region PVS.
HepvsFile hepvs_over_regions(const Zone& zone, float cell_size, float grid_size = kDefaultHepvsGridSize);

} // namespace pvs
