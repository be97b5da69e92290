// Camera geometry for the inspector's orbit and picking, free of any state: aiming a camera at a
// point, turning it about that point, and the ray through a pixel of its picture. Same
// conventions as pvs::Camera (z up, yaw counter-clockwise about +z from +x, pitch up).
#pragma once

#include "visibility/camera.h"
#include "visibility/zone.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>

namespace pvs::gui {

// Yaw and pitch (degrees) that make camera.forward() point along `direction`; pitch clamped to
// +-max_pitch. A zero direction keeps the camera's own.
void aim_along(Camera& camera, const glm::vec3& direction, float max_pitch);

// Turns `camera` about `target` by the given angles at its current distance: the new yaw and
// pitch are the old plus the deltas (pitch clamped to +-max_pitch), the camera then sits at
// target - forward * distance, looking at the target.
void orbit_about(Camera& camera, const glm::vec3& target, float yaw_degrees, float pitch_degrees, float max_pitch);

// The ray from the camera through the centre of pixel (x, y) of a width x height picture
// (rows top to bottom): origin on the near plane, unit direction.
struct Ray {
    glm::vec3 origin, direction;
};
Ray pixel_ray(const Camera& camera, uint32_t width, uint32_t height, uint32_t x, uint32_t y);

// Where that ray first hits a face of the zone (first_face_hit, exact), or nullopt.
std::optional<glm::vec3> pixel_point(const Zone& zone, const Camera& camera, uint32_t width, uint32_t height, uint32_t x,
                                     uint32_t y);

} // namespace pvs::gui
