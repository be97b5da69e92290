// A camera in the zone's frame (z up): position, yaw about +z (0 = looking along +x, 90 = +y),
// pitch up from the horizontal, vertical field of view, aspect, near and far distances.
// The view-projection matrix is OpenGL-style clip space, as Frustum::from_view_projection expects.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace pvs {

struct Camera {
    glm::vec3 position{0.0f};
    float yaw_degrees = 0.0f;
    float pitch_degrees = 0.0f;
    float fov_y_degrees = 70.0f;
    float aspect = 4.0f / 3.0f;
    float near_distance = 1.0f;
    float far_distance = 16384.0f;

    glm::vec3 forward() const;
    glm::mat4 view() const;
    glm::mat4 projection() const;
    glm::mat4 view_projection() const { return projection() * view(); }
};

} // namespace pvs
