#include "wld/eq/convex_face_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace pvs::eq {

namespace {

constexpr float kCosMaxAngle = 0.9999f; // about 0.8 degrees between a face's triangle normals
constexpr float kTurnTolerance = 1e-4f; // relative: corners straighter than that count as convex

glm::vec3 triangle_normal(std::span<const glm::vec3> p, const TriangleCorners& t)
{
    return glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
}

} // namespace

bool ConvexFaceBuilder::start(std::span<const glm::vec3> positions, const TriangleCorners& t)
{
    positions_ = positions;
    corner_count_ = 0;
    const glm::vec3 n = triangle_normal(positions, t);
    const float length = glm::length(n);
    if (!(length > 0.0f) || !std::isfinite(length))
        return false;
    normal_ = n / length;
    std::copy(t.begin(), t.end(), corners_.begin());
    corner_count_ = 3;
    return true;
}

// Turning before -> corner -> after seen from the normal's side: >= 0 (a left turn, or straight
// on) at every corner of a convex polygon wound counter-clockwise.
bool ConvexFaceBuilder::convex_corner(uint16_t before, uint16_t corner, uint16_t after) const
{
    const glm::vec3 a = positions_[corner] - positions_[before], b = positions_[after] - positions_[corner];
    return glm::dot(glm::cross(a, b), normal_) >= -kTurnTolerance * glm::length(a) * glm::length(b);
}

bool ConvexFaceBuilder::try_add(const TriangleCorners& t)
{
    if (corner_count_ < 3 || corner_count_ == kMaxCorners)
        return false;
    const glm::vec3 n = triangle_normal(positions_, t);
    const float length = glm::length(n);
    if (!(length > 0.0f) || !std::isfinite(length) || glm::dot(n, normal_) < kCosMaxAngle * length)
        return false;
    const auto begin = corners_.begin(), end = corners_.begin() + std::ptrdiff_t(corner_count_);
    for (size_t i = 0; i < corner_count_; ++i) {
        const size_t next = (i + 1) % corner_count_;
        const uint16_t u = corners_[i], v = corners_[next];
        // t walks the boundary edge u -> v as v -> u: at (k, k+1) = (v, u), third vertex t[k+2].
        for (int k = 0; k < 3; ++k) {
            if (t[k] != v || t[(k + 1) % 3] != u)
                continue;
            const uint16_t w = t[(k + 2) % 3];
            if (std::find(begin, end, w) != end)
                return false;
            const uint16_t before = corners_[(i + corner_count_ - 1) % corner_count_];
            const uint16_t after = corners_[(next + 1) % corner_count_];
            if (!convex_corner(before, u, w) || !convex_corner(u, w, v) || !convex_corner(w, v, after))
                return false;
            std::copy_backward(corners_.begin() + std::ptrdiff_t(i + 1), end, end + 1);
            corners_[i + 1] = w;
            ++corner_count_;
            return true;
        }
    }
    return false;
}

} // namespace pvs::eq
