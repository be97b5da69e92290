// A sight line from a view cell to an object of a grid zone (an OBJ level with a .hepvs grid):
// the mesh reference (mesh_reference.h) asked about one pair, as `pvscope why` needs it on
// levels with no BSP tree.
//
// Contract. find_grid_sight_line tries up to `budget` lines and returns the first that proves
// the pair by the mesh reference's rule: its eye is a point of the cell's box in open space
// (MeshTracer::in_open_space), and the ray from it toward a point of one of the object's
// triangles meets, first, a front face the object lists. The witness runs from the eye to that
// hit. Lines are aimed at the object (a point drawn on its triangles by area), so a pair whose
// object shows through a gap of a few pixels is found in a few thousand tries where the
// reference's undirected rays need many more. Deterministic in `seed`, cell and object.
// Returns nothing for a cell or object out of range, an object with no triangles, or a zone
// without a view grid.
#pragma once

#include "visibility/reference/mesh_tracer.h"
#include "visibility/reference/pair_witness.h"
#include "visibility/zone.h"

#include <cstdint>
#include <optional>

namespace pvs {

std::optional<SightWitness> find_grid_sight_line(const Zone& zone, const MeshTracer& tracer, uint32_t cell,
                                                 uint32_t object, uint64_t budget, uint64_t seed,
                                                 uint64_t* tries = nullptr);

} // namespace pvs
