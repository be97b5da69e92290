#include "render/picture_occlusion.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>
#include <limits>

namespace pvs::ui {

namespace {
constexpr float kInfinity = std::numeric_limits<float>::infinity();
}

PictureOcclusion::PictureOcclusion(const Zone& zone) : tracer_(zone)
{
    filter_.front_only = true;
}

void PictureOcclusion::set_frame(const Zone& zone, const Camera& view, uint32_t width, uint32_t height,
                                 std::span<const uint32_t> drawn_regions)
{
    view_ = view;
    rays_ = 0;
    drawn_faces_.assign(zone.mesh.faces.size(), 0);
    for (uint32_t region : drawn_regions)
        if (region < zone.region_count())
            for (uint32_t face : zone.faces_of_region(region))
                if (face < drawn_faces_.size())
                    drawn_faces_[face] = 1;
    filter_.face_enabled = drawn_faces_;

    // The basis of glm::lookAt with z up (as frustum_corners), scaled so that pixel (u, v) looks
    // along forward + (2u/w - 1) side + (1 - 2v/h) up.
    forward_ = view.forward();
    const glm::vec3 s = glm::normalize(glm::cross(forward_, glm::vec3(0.0f, 0.0f, 1.0f)));
    const float tan_half = std::tan(glm::radians(view.fov_y_degrees) * 0.5f);
    side_ = s * (tan_half * view.aspect);
    up_ = glm::cross(s, forward_) * tan_half;
    view_projection_ = view.view_projection();
    width_ = width;
    height_ = height;
    corners_x_ = width / kDepthTile + 2;
    corners_y_ = height / kDepthTile + 2;
    corner_depths_.assign(size_t(corners_x_) * corners_y_, kInfinity);
    row_traced_.assign(corners_y_, 0);
    row_directions_.resize(corners_x_);
    row_hits_.resize(corners_x_);
}

void PictureOcclusion::trace_corner_row(uint32_t cy) const
{
    // One row of corners in packets of coherent rays (MeshTracer::first_hits): about 3x cheaper
    // a ray than one at a time, and a line that needs one corner of a row soon needs its others.
    const float v = float(cy * kDepthTile);
    for (uint32_t cx = 0; cx < corners_x_; ++cx) {
        const float u = float(cx * kDepthTile);
        row_directions_[cx] = forward_ + side_ * (2.0f * u / float(width_) - 1.0f) + up_ * (1.0f - 2.0f * v / float(height_));
    }
    tracer_.first_hits(view_.position, row_directions_, 0.0f, kInfinity, row_hits_, &filter_);
    rays_ += corners_x_;
    float* depths = corner_depths_.data() + size_t(cy) * corners_x_;
    for (uint32_t cx = 0; cx < corners_x_; ++cx) // the directions' forward part is 1: t is the view depth
        depths[cx] = row_hits_[cx].hit ? row_hits_[cx].t : kInfinity;
    row_traced_[cy] = 1;
}

float PictureOcclusion::corner_depth(uint32_t cx, uint32_t cy) const
{
    if (!row_traced_[cy])
        trace_corner_row(cy);
    return corner_depths_[size_t(cy) * corners_x_ + cx];
}

bool PictureOcclusion::exact_hidden(const glm::vec3& point) const
{
    const glm::vec3 to_point = point - view_.position;
    const float distance = glm::length(to_point);
    const float reach = distance * (1.0f - kDepthBias) - kDepthBiasUnits;
    if (!(reach > 0.0f))
        return false; // at the eye, or not finite
    ++rays_;
    return tracer_.occluded(view_.position, to_point / distance, reach, filter_);
}

bool PictureOcclusion::hidden(const glm::vec3& point) const
{
    const glm::vec4 clip = view_projection_ * glm::vec4(point, 1.0f);
    const float depth = glm::dot(point - view_.position, forward_);
    if (!(clip.w > 0.0f) || !(depth > 0.0f) || width_ == 0 || height_ == 0)
        return exact_hidden(point);
    const float u = (clip.x / clip.w * 0.5f + 0.5f) * float(width_);
    const float v = (0.5f - clip.y / clip.w * 0.5f) * float(height_);
    if (!(u >= 0.0f && v >= 0.0f && u < float(width_) && v < float(height_)))
        return exact_hidden(point);
    const uint32_t tx = uint32_t(u) / kDepthTile, ty = uint32_t(v) / kDepthTile;
    float nearest = kInfinity, farthest = 0.0f;
    for (uint32_t dy = 0; dy < 2; ++dy)
        for (uint32_t dx = 0; dx < 2; ++dx) {
            const float d = corner_depth(tx + dx, ty + dy);
            nearest = std::min(nearest, d);
            farthest = std::max(farthest, d);
        }
    if (depth < nearest)
        return false; // in front of every surface around it
    if (depth * (1.0f - kDepthBias) - kDepthBiasUnits > farthest)
        return true; // behind every surface around it
    return exact_hidden(point);
}

std::optional<PictureOcclusion::FaceHit> PictureOcclusion::face_under(const glm::vec3& direction) const
{
    const float length = glm::length(direction);
    if (!(length > 0.0f) || !std::isfinite(length))
        return std::nullopt;
    const MeshTracer::Hit hit = tracer_.first_hit(view_.position, direction / length, kInfinity, filter_);
    if (!hit.hit)
        return std::nullopt;
    return FaceHit{hit.face, hit.t};
}

} // namespace pvs::ui
