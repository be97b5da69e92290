#include "wld/gen/kd_bsp.h"

#include <array>
#include <cstdlib>

namespace pvs::gen {

namespace {

struct Builder {
    const VoxelLevel& level;
    float cell_size;
    glm::vec3 origin;
    KdBsp out;
    std::array<std::vector<uint32_t>, 3> score; // per axis, per boundary: differing neighbour pairs

    // The split with the most differing neighbour pairs across it; ties go to the middle.
    // Returns false when the box holds one content only.
    bool choose_split(const glm::ivec3& lo, const glm::ivec3& hi, int& axis, int& position)
    {
        for (int a = 0; a < 3; ++a)
            score[a].assign(size_t(hi[a] - lo[a] + 1), 0);
        for (int z = lo.z; z < hi.z; ++z)
            for (int y = lo.y; y < hi.y; ++y)
                for (int x = lo.x; x < hi.x; ++x) {
                    const Cell c = level.at(x, y, z);
                    if (x + 1 < hi.x && level.at(x + 1, y, z) != c)
                        ++score[0][size_t(x + 1 - lo.x)];
                    if (y + 1 < hi.y && level.at(x, y + 1, z) != c)
                        ++score[1][size_t(y + 1 - lo.y)];
                    if (z + 1 < hi.z && level.at(x, y, z + 1) != c)
                        ++score[2][size_t(z + 1 - lo.z)];
                }
        uint32_t best = 0;
        int best_offcentre = 0;
        for (int a = 0; a < 3; ++a)
            for (int p = lo[a] + 1; p < hi[a]; ++p) {
                const uint32_t s = score[a][size_t(p - lo[a])];
                const int offcentre = std::abs(2 * p - lo[a] - hi[a]);
                if (s > best || (s == best && s > 0 && offcentre < best_offcentre)) {
                    best = s;
                    best_offcentre = offcentre;
                    axis = a;
                    position = p;
                }
            }
        return best > 0;
    }

    int32_t make_leaf(const glm::ivec3& lo, const glm::ivec3& hi)
    {
        const Cell content = level.at(lo.x, lo.y, lo.z);
        const auto leaf = static_cast<int32_t>(out.leaves.size());
        out.leaves.push_back({lo, hi, content});
        if (content == Cell::Solid) {
            out.tree.leaf_region.push_back(kLeafOutside);
        } else {
            out.tree.leaf_region.push_back(static_cast<int32_t>(out.region_leaf.size()));
            out.region_leaf.push_back(uint32_t(leaf));
        }
        return ~leaf;
    }

    // Returns the child encoding of the subtree for box [lo, hi).
    int32_t build(const glm::ivec3& lo, const glm::ivec3& hi)
    {
        int axis = 0, position = 0;
        if (!choose_split(lo, hi, axis, position))
            return make_leaf(lo, hi);
        const auto node = static_cast<int32_t>(out.tree.nodes.size());
        BspNode plane{};
        plane.normal[axis] = 1.0f;
        plane.dist = origin[axis] + float(position) * cell_size;
        out.tree.nodes.push_back(plane);
        glm::ivec3 split_hi = hi, split_lo = lo;
        split_hi[axis] = position;
        split_lo[axis] = position;
        const int32_t front = build(split_lo, hi);
        const int32_t back = build(lo, split_hi);
        out.tree.nodes[size_t(node)].children[0] = front;
        out.tree.nodes[size_t(node)].children[1] = back;
        return node;
    }
};

} // namespace

KdBsp build_kd_bsp(const VoxelLevel& level, float cell_size, const glm::vec3& origin)
{
    Builder builder{level, cell_size, origin, {}, {}};
    builder.out.tree.tie_rule = TieRule::OnPlaneGoesFront;
    builder.out.tree.root = builder.build(glm::ivec3(0), level.dims);
    return std::move(builder.out);
}

} // namespace pvs::gen
