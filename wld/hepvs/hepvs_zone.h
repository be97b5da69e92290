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

} // namespace pvs
