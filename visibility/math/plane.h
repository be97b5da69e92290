// A plane in the form dot(normal, p) == dist. The signed distance is positive on the front
// side (the side the normal points to). Loaders convert their file's convention to this one
// (EverQuest stores n·p + d = 0, i.e. dist = -d).
#pragma once

#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

namespace pvs {

struct Plane {
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float dist = 0.0f;

    float distance(const glm::vec3& p) const { return glm::dot(normal, p) - dist; }
    Plane flipped() const { return {-normal, -dist}; }
};

} // namespace pvs
