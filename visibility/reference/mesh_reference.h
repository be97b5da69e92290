// The ground truth of a grid zone (an OBJ level with a view grid, no BSP tree), as the sampled
// reference (reference_vis.h) is for zones with a tree: a cell sees an object when a sight line
// from a point of the cell that is in open space meets the object's front first. Traced against
// the mesh with Embree in robust mode (mesh_tracer.h), so a line cannot slip between triangles.
//
// Per cell: points uniform in the cell's box, each kept only when it is in open space (six axis
// rays all meet front faces: a point in the rock or the void around the level is no camera's);
// from each kept point, rays in stratified directions (sample_sequence.h); each first hit on a
// front face adds the regions listing that face. A lower bound: the lines it traced. Cells with
// no point in open space get an empty row (no camera stands there). Deterministic for a seed,
// any thread count; progress(fraction) false cancels.
#pragma once

#include "visibility/pvs.h"
#include "visibility/view_grid.h"
#include "visibility/zone.h"

#include <cstdint>
#include <functional>

namespace pvs {

struct MeshReferenceParams {
    uint32_t points_per_cell = 16;
    uint32_t rays_per_point = 256;
    uint64_t seed = 1;
    unsigned threads = 0;
    std::function<bool(double fraction)> progress;
};

struct MeshReferenceReport {
    uint64_t cells = 0, points = 0, open_points = 0, rays = 0;
    uint64_t open_cells = 0; // cells with at least one point in open space
    unsigned threads = 0;
    double seconds = 0.0, mean_visible = 0.0;
    bool cancelled = false;
};

Pvs bake_mesh_reference_grid(const Zone& zone, const ViewGrid& grid, const MeshReferenceParams& params,
                             MeshReferenceReport* report = nullptr);

} // namespace pvs
