#include "gen/kd_bsp.h"

#include <array>
#include <cstdlib>

namespace pvs::gen {

namespace {

struct Builder {
    const VoxelLevel& level;
    const GridAxes& axes;
    std::span<const uint32_t> labels;
    KdBsp out;
    std::array<std::vector<uint32_t>, 3> score; // per axis, per boundary: differing neighbour pairs
    std::array<std::vector<uint32_t>, 3> cuts;  // per axis, per boundary: pairs of one labelled box

    // Two cells inside the level that must not share a leaf.
    bool differ(int x0, int y0, int z0, int x1, int y1, int z1) const
    {
        if (level.at(x0, y0, z0) != level.at(x1, y1, z1))
            return true;
        return !labels.empty() && labels[level.index(x0, y0, z0)] != labels[level.index(x1, y1, z1)];
    }

    // Two cells of one labelled open box (a split between them would cut the box).
    bool same_box(int x0, int y0, int z0, int x1, int y1, int z1) const
    {
        if (labels.empty())
            return false;
        const uint32_t label = labels[level.index(x0, y0, z0)];
        return label != 0 && label == labels[level.index(x1, y1, z1)];
    }

    // The split with the most differing neighbour pairs across it; ties go to the middle.
    // With labels, splits that cut no labelled box come first (each box then ends as one leaf
    // wherever the layout allows a guillotine cut). Returns false when the box holds one
    // content (and label) only.
    bool choose_split(const glm::ivec3& lo, const glm::ivec3& hi, int& axis, int& position)
    {
        for (int a = 0; a < 3; ++a) {
            score[a].assign(size_t(hi[a] - lo[a] + 1), 0);
            cuts[a].assign(size_t(hi[a] - lo[a] + 1), 0);
        }
        const auto count = [&](int a, const glm::ivec3& c) {
            glm::ivec3 n = c;
            ++n[a];
            if (n[a] >= hi[a])
                return;
            const size_t boundary = size_t(n[a] - lo[a]);
            if (differ(c.x, c.y, c.z, n.x, n.y, n.z))
                ++score[a][boundary];
            else if (same_box(c.x, c.y, c.z, n.x, n.y, n.z))
                ++cuts[a][boundary];
        };
        for (int z = lo.z; z < hi.z; ++z)
            for (int y = lo.y; y < hi.y; ++y)
                for (int x = lo.x; x < hi.x; ++x)
                    for (int a = 0; a < 3; ++a)
                        count(a, {x, y, z});
        bool found = false;
        for (bool allow_cuts : {false, true}) {
            uint32_t best = 0;
            int best_offcentre = 0;
            for (int a = 0; a < 3; ++a)
                for (int p = lo[a] + 1; p < hi[a]; ++p) {
                    const size_t boundary = size_t(p - lo[a]);
                    if (!allow_cuts && cuts[a][boundary] > 0)
                        continue;
                    const uint32_t s = score[a][boundary];
                    const int offcentre = std::abs(2 * p - lo[a] - hi[a]);
                    if (s > best || (s == best && s > 0 && offcentre < best_offcentre)) {
                        best = s;
                        best_offcentre = offcentre;
                        axis = a;
                        position = p;
                        found = true;
                    }
                }
            if (found)
                return true;
        }
        return false;
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
        plane.dist = axes.lines[size_t(axis)][size_t(position)];
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

KdBsp build_kd_bsp(const VoxelLevel& level, const GridAxes& axes, std::span<const uint32_t> labels)
{
    Builder builder{level, axes, labels, {}, {}, {}};
    builder.out.tree.tie_rule = TieRule::OnPlaneGoesFront;
    builder.out.tree.root = builder.build(glm::ivec3(0), level.dims);
    return std::move(builder.out);
}

} // namespace pvs::gen
