#include "gen/grid_axes.h"

namespace pvs::gen {

GridAxes uniform_grid_axes(const glm::ivec3& dims, float cell_size, const glm::vec3& origin)
{
    GridAxes axes;
    for (int a = 0; a < 3; ++a) {
        axes.lines[size_t(a)].resize(size_t(dims[a]) + 1);
        for (int i = 0; i <= dims[a]; ++i)
            axes.lines[size_t(a)][size_t(i)] = origin[a] + float(i) * cell_size;
    }
    return axes;
}

} // namespace pvs::gen
