#include "visibility/eval/camera_set.h"

#include "visibility/region_lookup.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <random>

namespace pvs {

namespace {

// A camera point a player could occupy: in a region that is not sky (a sky volume is the
// inside of the sky brush, outside the playable space), with open space all around it out to
// beyond the near plane's corners, so the near plane never reaches through a wall.
bool good_viewpoint(const Zone& zone, const glm::vec3& p, float clearance)
{
    const PointLocation at = locate_point(zone.tree, p);
    if (!at.in_region() || (zone.regions[size_t(at.region)].flags & kRegionSky))
        return false;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                if (dx == 0 && dy == 0 && dz == 0)
                    continue;
                const glm::vec3 offset = glm::normalize(glm::vec3(dx, dy, dz)) * clearance;
                if (!locate_point(zone.tree, p + offset).in_region())
                    return false;
            }
    return true;
}

float clearance_for(const Camera& lens)
{
    const float half_h = lens.near_distance * std::tan(glm::radians(lens.fov_y_degrees) * 0.5f);
    const float half_w = half_h * std::max(lens.aspect, 1.0f);
    return 1.5f * std::sqrt(lens.near_distance * lens.near_distance + half_h * half_h + half_w * half_w);
}

Camera with_lens(const Camera& lens, const glm::vec3& position, float yaw, float pitch)
{
    Camera c = lens;
    c.position = position;
    c.yaw_degrees = yaw;
    c.pitch_degrees = pitch;
    return c;
}

} // namespace

std::vector<Camera> random_cameras_in_regions(const Zone& zone, size_t count, uint64_t seed, const Camera& lens)
{
    std::vector<Camera> cameras;
    const Aabb box = zone.bounds();
    if (box.empty() || zone.region_count() == 0)
        return cameras;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z),
        yaw(0.0f, 360.0f), pitch(-60.0f, 60.0f);
    const float clearance = clearance_for(lens);
    cameras.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        for (int attempt = 0; attempt < 10000; ++attempt) {
            const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
            if (good_viewpoint(zone, p, clearance)) {
                cameras.push_back(with_lens(lens, p, yaw(rng), pitch(rng)));
                break;
            }
        }
    }
    return cameras;
}

std::vector<Camera> cameras_visiting_every_region(const Zone& zone, uint64_t seed, const Camera& lens)
{
    std::vector<Camera> cameras;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), yaw(0.0f, 360.0f), pitch(-30.0f, 30.0f);
    const float clearance = clearance_for(lens);
    auto fits = [&](const glm::vec3& p, uint32_t r) {
        return locate_point(zone.tree, p).region == int32_t(r) && good_viewpoint(zone, p, clearance);
    };
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        const Aabb& b = zone.regions[r].bounds;
        if (b.empty() || (zone.regions[r].flags & kRegionSky))
            continue;
        // The centre first (most regions are convex boxes or close to it), then random points.
        glm::vec3 p = b.center();
        for (int attempt = 0; attempt < 200 && !fits(p, r); ++attempt)
            p = b.min + (b.max - b.min) * glm::vec3(unit(rng), unit(rng), unit(rng));
        if (fits(p, r))
            cameras.push_back(with_lens(lens, p, yaw(rng), pitch(rng)));
    }
    return cameras;
}

} // namespace pvs
