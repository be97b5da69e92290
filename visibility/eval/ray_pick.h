// The first face a ray hits, by exact ray-triangle tests (Möller & Trumbore, "Fast, Minimum
// Storage Ray/Triangle Intersection", 1997) over every triangle: the independent check of what
// a rasterised ID buffer shows. Only triangles facing the ray's origin count (counter-clockwise
// seen from the front), as in a renderer with back-face culling. Brute force: for checking a
// few pixels, not for rendering.
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>

namespace pvs {

struct RayHit {
    int32_t face = -1; // -1: nothing hit
    float distance = 0.0f;
};

RayHit first_face_hit(const Zone& zone, const glm::vec3& origin, const glm::vec3& direction);

} // namespace pvs
