#include "visibility/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace pvs {

glm::vec3 Camera::forward() const
{
    const float yaw = glm::radians(yaw_degrees);
    // Clamp short of straight up/down so the view matrix keeps a defined up direction.
    const float pitch = glm::radians(std::clamp(pitch_degrees, -89.9f, 89.9f));
    return {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
}

glm::mat4 Camera::view() const { return glm::lookAt(position, position + forward(), glm::vec3(0.0f, 0.0f, 1.0f)); }

glm::mat4 Camera::projection() const
{
    return glm::perspective(glm::radians(fov_y_degrees), aspect, near_distance, far_distance);
}

} // namespace pvs
