// Many boxes against one frustum, fast: the culler's frustum stage.
//
// Frustum::intersects picks each plane's "positive vertex" with a branch per axis and leaves
// at the first plane that rejects, so a frame of a few hundred boxes pays for unpredictable
// branches on every box. Here the planes are prepared once per frame, four to a group and
// split into their positive and negative normal parts (n+ = max(n, 0), n- = min(n, 0)), so the
// positive vertex's distance is a branch-free sum, max·n+ + min·n- - dist, over four planes at
// once (SSE2, part of every x86-64; a scalar loop elsewhere; AVX without FMA, when the CPU has it,
// for eight boxes against one plane). The products with the zero part
// are exact zeros, so every distance is bit for bit the one Frustum::intersects computes, and
// the answers are identical to it (tests/visibility/test_frustum_boxes.cpp checks that on
// random boxes and frustums, touching boxes included).
//
// The boxes are copied into 32-byte aligned records (min.xyz, pad, max.xyz, pad) at
// construction; the culler keeps one FrustumBoxes per zone, built from the regions' bounds.
#pragma once

#include "visibility/math/aabb.h"
#include "visibility/math/frustum.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

class FrustumBoxes {
public:
    // Which planes to test: all six, or the four side planes (Frustum::intersects_sides).
    enum class Planes : uint8_t { All, SidesOnly };

    // Planes prepared for the branch-free test: up to two groups of four. Unused lanes hold a
    // plane every point is in front of.
    struct alignas(16) PlaneGroups {
        float pos_x[2][4], pos_y[2][4], pos_z[2][4]; // n+ per lane
        float neg_x[2][4], neg_y[2][4], neg_z[2][4]; // n- per lane
        float dist[2][4];
        // Per plane: a bound on the float round-off of a distance to a box within the
        // coordinate scale given to prepare (classify's safety margin).
        float margin[2][4];
        // Per plane p < 8, the same values spread over four lanes (pos x, y, z, neg x, y, z,
        // dist): the four-boxes test loads them instead of shuffling each one for every four.
        float splat[8][7][4];
        int group_count = 1;
        int plane_count = 4; // 4 (sides) or 6
    };

    explicit FrustumBoxes(std::span<const Aabb> boxes);

    // `coordinate_scale`: the largest absolute coordinate of the boxes that will be classified
    // (sets PlaneGroups::margin; 0 when classify is not used).
    static PlaneGroups prepare(const Frustum& frustum, Planes planes, float coordinate_scale = 0.0f);
    // The same, into `out` (a frame's planes are 1.2 KB: the culler keeps one and refills it).
    static void prepare(const Frustum& frustum, Planes planes, float coordinate_scale, PlaneGroups& out);

    // Where box i lies for the prepared planes, decided so that every box inside it gets the
    // answer intersects() gives it: Outside (behind some plane by more than its round-off
    // margin: every box within is rejected), Inside (in front of every plane by more than the
    // margin: every box within is accepted), else Partial (ask each box). The culler's block
    // stage: one test for 64 regions.
    enum class Side : uint8_t { Outside, Inside, Partial };
    Side classify(uint32_t box, const PlaneGroups& planes) const;
    // The same, testing only the planes of `crossing` (bit p: plane p; a box within a box wholly in
    // front of a plane is wholly in front of it too, with the same margin) and leaving in it the
    // planes whose boundary crosses the box (none when Inside): the planes its boxes must test.
    Side classify(uint32_t box, const PlaneGroups& planes, unsigned& crossing) const;
    static unsigned all_planes(const PlaneGroups& planes) { return (1u << planes.plane_count) - 1u; }

    // Same answer as frustum.intersects(box i) (or intersects_sides) for the prepared planes.
    bool intersects(uint32_t box, const PlaneGroups& planes) const;

    // Every box, in order: writes the indices of the boxes that intersect to `out` (room for
    // size() entries), ascending, and returns their count. The same answers as intersects(),
    // four boxes at a time against one plane (the boxes are also kept plane-major, SoA, for
    // this): the path of a camera with no PVS row, where every region is tested.
    size_t collect_all(const PlaneGroups& planes, uint32_t* out) const;

    // Boxes [first, first + count) (count <= 64): bit i of the result set when box first + i
    // intersects, the same answers as intersects(), four boxes at a time (SoA; eight with AVX where the
    // CPU has it, checked once at start-up). With
    // `crossing` (classify's, for a box holding them all) only those planes are tested: the others
    // pass every box; and only the fours with a bit in `wanted` are tested (the others' bits are 0).
    uint64_t intersect_mask(uint32_t first, uint32_t count, const PlaneGroups& planes) const;
    uint64_t intersect_mask(uint32_t first, uint32_t count, const PlaneGroups& planes, unsigned crossing,
                            uint64_t wanted) const;

    // The squared distance from `p` to the nearest point of box i (0 inside it): the culler's
    // distance stage reads the same packed boxes as its frustum stage.
    float squared_distance(uint32_t box, const glm::vec3& p) const
    {
        const PackedBox& b = boxes_[box];
        float sum = 0.0f;
        for (int k = 0; k < 3; ++k) {
            const float d = std::max({b.min[k] - p[k], p[k] - b.max[k], 0.0f});
            sum += d * d;
        }
        return sum;
    }

    // Boxes [first, first + count) (count <= 64): bit i set when squared_distance(first + i, p) <=
    // limit, the same sums (SSE, four at a time, where there is SSE2).
    uint64_t near_mask(uint32_t first, uint32_t count, const glm::vec3& p, float limit) const;

    // The squared distance from `p` to the farthest point of box i.
    float squared_reach(uint32_t box, const glm::vec3& p) const
    {
        const PackedBox& b = boxes_[box];
        float sum = 0.0f;
        for (int k = 0; k < 3; ++k) {
            const float d = std::max(std::abs(p[k] - b.min[k]), std::abs(b.max[k] - p[k]));
            sum += d * d;
        }
        return sum;
    }

    size_t size() const { return boxes_.size(); }
    size_t memory_bytes() const { return boxes_.capacity() * sizeof(PackedBox) + 6 * min_x_.capacity() * sizeof(float); }

private:
#if defined(__SSE2__)
    // Bit i set when box at + i (i < 4) intersects: the SoA test collect_all and intersect_mask share.
    unsigned intersect_four(size_t at, const PlaneGroups& planes, unsigned crossing) const;
#endif
    struct alignas(32) PackedBox {
        float min[4];
        float max[4];
    };
    std::vector<PackedBox> boxes_;
    std::vector<float> min_x_, min_y_, min_z_, max_x_, max_y_, max_z_; // the same boxes, SoA
};

} // namespace pvs
