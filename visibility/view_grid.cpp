#include "visibility/view_grid.h"

#include <algorithm>
#include <cmath>

namespace pvs {

int32_t ViewGrid::cell_at(const glm::vec3& zone_point) const
{
    const glm::vec3 p = to_grid_space(zone_point);
    uint32_t i[3];
    for (int a = 0; a < 3; ++a) {
        if (!(p[a] > min[a])) // also false for NaN
            return -1;
        const float cells = std::trunc((p[a] - min[a]) / cell_size);
        if (!(cells < float(counts[a])))
            return -1;
        i[a] = uint32_t(cells);
    }
    return int32_t(index(i[0], i[1], i[2]));
}

Aabb ViewGrid::cell_bounds(uint32_t cell) const
{
    const uint32_t z = cell % counts.z, y = (cell / counts.z) % counts.y, x = cell / (counts.z * counts.y);
    const glm::vec3 lo = (min + glm::vec3(float(x), float(y), float(z)) * cell_size) * grid_size;
    const glm::vec3 hi = lo + glm::vec3(cell_size * grid_size);
    // grid (x, y, z) is zone (x, -z, y)
    Aabb box;
    box.grow(glm::vec3(lo.x, -lo.z, lo.y));
    box.grow(glm::vec3(hi.x, -hi.z, hi.y));
    return box;
}

std::optional<ViewGrid> grid_over_points(std::span<const glm::vec3> zone_points, float cell_size, float grid_size)
{
    if (zone_points.empty() || !(cell_size > 0.0f) || !(grid_size > 0.0f))
        return std::nullopt;
    ViewGrid grid;
    grid.cell_size = cell_size;
    grid.grid_size = grid_size;
    Aabb space;
    for (const glm::vec3& p : zone_points)
        space.grow(grid.to_grid_space(p));
    grid.min = space.min;
    for (int a = 0; a < 3; ++a) {
        const float cells = std::max(1.0f, std::ceil((space.max[a] - space.min[a]) / cell_size));
        if (!(cells <= 65535.0f))
            return std::nullopt;
        grid.counts[a] = uint32_t(cells);
    }
    return grid;
}

} // namespace pvs
