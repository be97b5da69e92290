#include "ui/gui/camera_math.h"

#include "visibility/eval/ray_pick.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

namespace pvs::gui {

void aim_along(Camera& camera, const glm::vec3& direction, float max_pitch)
{
    const float length = glm::length(direction);
    if (!(length > 0.0f) || !std::isfinite(length))
        return;
    const glm::vec3 d = direction / length;
    camera.yaw_degrees = glm::degrees(std::atan2(d.y, d.x));
    camera.pitch_degrees = std::clamp(glm::degrees(std::asin(std::clamp(d.z, -1.0f, 1.0f))), -max_pitch, max_pitch);
}

void orbit_about(Camera& camera, const glm::vec3& target, float yaw_degrees, float pitch_degrees, float max_pitch)
{
    const float distance = glm::length(camera.position - target);
    camera.yaw_degrees = std::remainder(camera.yaw_degrees + yaw_degrees, 360.0f);
    camera.pitch_degrees = std::clamp(camera.pitch_degrees + pitch_degrees, -max_pitch, max_pitch);
    camera.position = target - camera.forward() * distance;
}

Ray pixel_ray(const Camera& camera, uint32_t width, uint32_t height, uint32_t x, uint32_t y)
{
    const float ndc_x = (float(x) + 0.5f) / float(std::max(width, 1u)) * 2.0f - 1.0f;
    const float ndc_y = 1.0f - (float(y) + 0.5f) / float(std::max(height, 1u)) * 2.0f;
    const glm::mat4 inverse = glm::inverse(camera.view_projection());
    glm::vec4 near_point = inverse * glm::vec4(ndc_x, ndc_y, -1.0f, 1.0f);
    glm::vec4 far_point = inverse * glm::vec4(ndc_x, ndc_y, 1.0f, 1.0f);
    near_point /= near_point.w;
    far_point /= far_point.w;
    return {glm::vec3(near_point), glm::normalize(glm::vec3(far_point - near_point))};
}

std::optional<glm::vec3> pixel_point(const Zone& zone, const Camera& camera, uint32_t width, uint32_t height, uint32_t x,
                                     uint32_t y)
{
    const Ray ray = pixel_ray(camera, width, height, x, y);
    const RayHit hit = first_face_hit(zone, ray.origin, ray.direction);
    if (hit.face < 0)
        return std::nullopt;
    return ray.origin + ray.direction * hit.distance;
}

} // namespace pvs::gui
