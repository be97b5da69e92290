#include "visibility/culler.h"

#include "visibility/bit_row.h"
#include "visibility/math/frustum.h"

#include <algorithm>
#include <chrono>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace pvs {

namespace {
using Clock = std::chrono::steady_clock;
double micros_since(Clock::time_point start)
{
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}
} // namespace

const char* cull_mode_name(CullMode mode)
{
    switch (mode) {
    case CullMode::None: return "none";
    case CullMode::Frustum: return "frustum";
    case CullMode::Pvs: return "pvs";
    case CullMode::PvsFrustum: return "pvs+frustum";
    }
    return "?";
}

std::optional<CullMode> parse_cull_mode(const std::string& name)
{
    for (CullMode m : {CullMode::None, CullMode::Frustum, CullMode::Pvs, CullMode::PvsFrustum})
        if (name == cull_mode_name(m))
            return m;
    return std::nullopt;
}

Culler::Culler(const Zone& zone, const Pvs* pvs)
    : zone_(&zone), pvs_(pvs), locator_(zone.tree, zone.bounds()), zone_bounds_(zone.bounds()),
      face_stamp_(zone.mesh.faces.size(), 0)
{
    if (pvs_ && pvs_->region_count() == zone.region_count())
        cursor_.emplace(*pvs_);
    else
        pvs_ = nullptr; // a PVS of another zone is unusable: cull as if there were none
}

uint64_t Culler::count_triangles(const std::vector<uint32_t>& regions)
{
    if (++stamp_ == 0) { // wrapped: restart the stamps
        std::fill(face_stamp_.begin(), face_stamp_.end(), 0);
        stamp_ = 1;
    }
    uint64_t triangles = 0;
    for (uint32_t r : regions)
        for (uint32_t f : zone_->faces_of_region(r))
            if (face_stamp_[f] != stamp_) {
                face_stamp_[f] = stamp_;
                triangles += zone_->mesh.faces[f].triangle_count;
            }
    return triangles;
}

bool Culler::far_plane_reaches_everything(const Camera& camera) const
{
    // The farthest corner of the zone's box from the camera, against the far distance.
    const glm::vec3 d = glm::max(glm::abs(zone_bounds_.min - camera.position), glm::abs(zone_bounds_.max - camera.position));
    return glm::dot(d, d) < camera.far_distance * camera.far_distance;
}

CullStats Culler::cull(const Camera& camera, const CullOptions& options, std::vector<uint32_t>& visible)
{
    CullStats stats;
    const auto region_count = static_cast<uint32_t>(zone_->region_count());
    stats.regions_total = region_count;

    // Stage 1: where is the camera?
    auto start = Clock::now();
    const PointLocation at = locator_.locate(camera.position);
    stats.lookup_us = micros_since(start);
    stats.region = at.region >= 0 ? at.region : -1;
    stats.camera = at.region >= 0 ? CameraPlace::InRegion
                   : at.region == kLeafSolid ? CameraPlace::InSolid
                                             : CameraPlace::Outside;

    // Stage 2: the PVS row, or every region.
    start = Clock::now();
    candidates_.clear();
    const bool want_pvs = options.mode == CullMode::Pvs || options.mode == CullMode::PvsFrustum;
    stats.pvs_used = want_pvs && pvs_ && at.region >= 0;
    if (stats.pvs_used) {
        const std::span<const uint64_t> row = cursor_->row(uint32_t(at.region));
        bits::for_each_set(row, [&](size_t r) { candidates_.push_back(uint32_t(r)); });
        // The camera's own region is always drawn, even when a damaged row lacks its bit.
        if (!bits::test(row, uint32_t(at.region)))
            candidates_.insert(std::lower_bound(candidates_.begin(), candidates_.end(), uint32_t(at.region)),
                               uint32_t(at.region));
    } else {
        candidates_.resize(region_count);
        for (uint32_t r = 0; r < region_count; ++r)
            candidates_[r] = r;
    }
    stats.pvs_us = micros_since(start);
    stats.regions_after_pvs = static_cast<uint32_t>(candidates_.size());

    // Stage 3: the frustum.
    start = Clock::now();
    visible.clear();
    const bool want_frustum = options.mode == CullMode::Frustum || options.mode == CullMode::PvsFrustum;
    if (want_frustum) {
        const Frustum frustum = Frustum::from_view_projection(camera.view_projection());
        if (far_plane_reaches_everything(camera)) {
            for (uint32_t r : candidates_)
                if (frustum.intersects_sides(zone_->regions[r].bounds))
                    visible.push_back(r);
        } else {
            for (uint32_t r : candidates_)
                if (frustum.intersects(zone_->regions[r].bounds))
                    visible.push_back(r);
        }
    } else {
        visible = candidates_;
    }
    stats.frustum_us = micros_since(start);
    stats.regions_after_frustum = static_cast<uint32_t>(visible.size());

    if (options.count_triangles) {
        stats.triangles_total = zone_->mesh.triangle_count();
        stats.triangles_after_pvs = count_triangles(candidates_);
        stats.triangles_after_frustum = count_triangles(visible);
    }
    return stats;
}

} // namespace pvs
