// The view cells of a grid zone: an OBJ level whose PVS is a HateEngine .hepvs
// (../shared/formats/quake-doom-hepvs.md §5). Such a zone has no BSP tree; the camera's cell is
// found on a uniform grid of cubic cells, and each cell's PVS row lists regions, which in an OBJ
// zone are the file's objects (the drawable groups). So a grid zone's Pvs has one row per cell
// (Pvs::row_count() == cell_count()) over its regions, and BSP zones, which have no ViewGrid,
// pay nothing for it (docs/architecture.md, "Grid zones").
//
// Space. The grid lives where the baker put it: the OBJ file's coordinates (y up) divided by
// grid_size (16 by default, the engine's too). A zone is z up: the OBJ reader turns file point
// (x, y, z) into zone point (x, -z, y), the inverse of the map-editor export (x, z, -y) that made
// the E1M1 sample (§5.5) and that obj_writer.h writes. to_grid_space() undoes both.
//
// Lookup, exactly as the engine's (§5.5): the cell is used only when the point is strictly above
// `min` on all three axes; then i = trunc((p - min) / cell_size) per axis, each below its count;
// otherwise there is no cell (-1) and the engine draws everything. Cell order: x outermost, then
// y, then z: index = (x * ny + y) * nz + z.
#pragma once

#include "visibility/math/aabb.h"

#include <cstdint>
#include <optional>
#include <span>
#include <glm/ext/vector_uint3.hpp>
#include <glm/vec3.hpp>

namespace pvs {

struct ViewGrid {
    glm::vec3 min{0.0f};     // grid space
    float cell_size = 1.0f;  // grid space, > 0
    glm::uvec3 counts{0u};   // cells along x, y, z (grid space axes)
    float grid_size = 16.0f; // OBJ units per grid unit

    uint64_t cell_count() const { return uint64_t(counts.x) * counts.y * counts.z; }
    uint32_t index(uint32_t x, uint32_t y, uint32_t z) const { return (x * counts.y + y) * counts.z + z; }
    glm::vec3 to_grid_space(const glm::vec3& zone_point) const
    {
        return glm::vec3(zone_point.x, zone_point.z, -zone_point.y) / grid_size;
    }
    // The cell holding a zone-space point, or -1 (outside the grid: draw everything).
    int32_t cell_at(const glm::vec3& zone_point) const;
    // A cell's box in zone space.
    Aabb cell_bounds(uint32_t cell) const;
};

// The HateEngine baker's grid over points in zone space (a zone's vertices): min over the points
// in grid space, cells of cell_size grid units, counts rounded up (at least 1 each). Returns
// nullopt when there are no points, a size is not positive, or a side needs over 65535 cells.
std::optional<ViewGrid> grid_over_points(std::span<const glm::vec3> zone_points, float cell_size, float grid_size);

} // namespace pvs
