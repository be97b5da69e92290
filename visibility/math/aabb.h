// Axis-aligned bounding box. An empty box has min > max on every axis, so that growing it by
// the first point gives that point.
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace pvs {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void grow(const glm::vec3& p)
    {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Aabb& b)
    {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::vec3 size() const { return max - min; }
    bool contains(const glm::vec3& p) const
    {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
    }
    bool overlaps(const Aabb& b) const
    {
        return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y &&
               min.z <= b.max.z && b.min.z <= max.z;
    }
};

} // namespace pvs
