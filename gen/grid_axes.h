// Where the boundaries of a voxel level's cells lie in the world, axis by axis. The procedural
// zones use a uniform grid (every cell `cell_size` wide); the stability cases (stability_cases.h)
// use uneven ones, so that a wall 0.1 units thick or a crack 0.01 wide is one column of cells.
//
// lines[a] holds dims[a] + 1 increasing coordinates: cell c spans [lines[a][c], lines[a][c + 1]).
#pragma once

#include <array>
#include <glm/ext/vector_float3.hpp>
#include <glm/ext/vector_int3.hpp>
#include <vector>

namespace pvs::gen {

struct GridAxes {
    std::array<std::vector<float>, 3> lines;

    // The world position of cell corner `c` (0 <= c[a] <= dims[a]).
    glm::vec3 corner(const glm::ivec3& c) const
    {
        return {lines[0][size_t(c.x)], lines[1][size_t(c.y)], lines[2][size_t(c.z)]};
    }
    glm::ivec3 dims() const
    {
        return {int(lines[0].size()) - 1, int(lines[1].size()) - 1, int(lines[2].size()) - 1};
    }
};

// dims[a] cells of `cell_size` from `origin` on every axis.
GridAxes uniform_grid_axes(const glm::ivec3& dims, float cell_size, const glm::vec3& origin);

} // namespace pvs::gen
