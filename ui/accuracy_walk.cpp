#include "ui/accuracy_walk.h"

#include "ui/software_renderer.h"
#include "visibility/eval/ray_pick.h"

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <tuple>

namespace pvs::ui {

namespace {

std::vector<int32_t> face_ids_of(const Image& ids)
{
    std::vector<int32_t> out(size_t(ids.width) * ids.height);
    for (uint32_t y = 0; y < ids.height; ++y)
        for (uint32_t x = 0; x < ids.width; ++x) {
            const uint32_t face = face_at(ids, x, y);
            out[size_t(y) * ids.width + x] = face == kNoFace ? -1 : int32_t(face);
        }
    return out;
}

// The ray from the camera through the centre of pixel (x, y), rows top to bottom.
void pixel_ray(const Camera& camera, uint32_t x, uint32_t y, uint32_t width, uint32_t height, glm::vec3& origin,
               glm::vec3& direction)
{
    const glm::mat4 inverse = glm::inverse(camera.view_projection());
    const float nx = 2.0f * (float(x) + 0.5f) / float(width) - 1.0f;
    const float ny = 1.0f - 2.0f * (float(y) + 0.5f) / float(height);
    glm::vec4 near_point = inverse * glm::vec4(nx, ny, -1.0f, 1.0f);
    glm::vec4 far_point = inverse * glm::vec4(nx, ny, 1.0f, 1.0f);
    near_point /= near_point.w;
    far_point /= far_point.w;
    origin = camera.position;
    direction = glm::normalize(glm::vec3(far_point) - glm::vec3(near_point));
}

// Re-checks popping pixels with exact rays; returns (checked, confirmed).
std::pair<uint64_t, uint64_t> confirm_popping(const Zone& zone, const FaceRegions& face_regions, const Camera& camera,
                                              const Image& ids, const std::vector<uint8_t>& region_drawn,
                                              const ImageAccuracy& accuracy, uint32_t max_rays)
{
    if (accuracy.popping_pixels == 0 || max_rays == 0)
        return {0, 0};
    auto drawn = [&](uint32_t face) {
        for (uint32_t r : face_regions.of(face))
            if (region_drawn[r])
                return true;
        return false;
    };
    const uint64_t stride = std::max<uint64_t>(1, accuracy.popping_pixels / max_rays);
    uint64_t seen = 0, checked = 0, confirmed = 0;
    for (uint32_t y = 0; y < ids.height; ++y)
        for (uint32_t x = 0; x < ids.width; ++x) {
            const uint32_t face = face_at(ids, x, y);
            if (face == kNoFace || drawn(face) || seen++ % stride != 0 || checked == max_rays)
                continue;
            glm::vec3 origin, direction;
            pixel_ray(camera, x, y, ids.width, ids.height, origin, direction);
            const RayHit hit = first_face_hit(zone, origin, direction);
            ++checked;
            confirmed += hit.face >= 0 && !drawn(uint32_t(hit.face));
        }
    return {checked, confirmed};
}

} // namespace

std::vector<WalkRow> run_accuracy_walk(const Zone& zone, const Pvs* pvs, std::span<const Camera> cameras,
                                       const WalkOptions& options)
{
    SoftwareRenderer renderer(options.width, options.height);
    Culler culler(zone, pvs);
    const FaceRegions face_regions = build_face_regions(zone);
    std::vector<uint32_t> all_regions(zone.region_count());
    for (uint32_t r = 0; r < all_regions.size(); ++r)
        all_regions[r] = r;

    std::vector<WalkRow> rows;
    rows.reserve(cameras.size());
    std::vector<uint32_t> visible;
    std::vector<uint8_t> region_drawn(zone.region_count(), 0);
    for (size_t i = 0; i < cameras.size(); ++i) {
        WalkRow row;
        row.camera = cameras[i];
        row.camera.aspect = float(options.width) / float(options.height);
        row.cull = culler.cull(row.camera, {options.mode, true}, visible);
        const Image ids = renderer.render(zone, row.camera, all_regions, RenderMode::IdBuffer);
        row.accuracy = measure_image_accuracy(zone, face_regions, face_ids_of(ids), visible);
        std::fill(region_drawn.begin(), region_drawn.end(), 0);
        for (uint32_t r : visible)
            region_drawn[r] = 1;
        std::tie(row.popping_checked, row.popping_confirmed) = confirm_popping(
            zone, face_regions, row.camera, ids, region_drawn, row.accuracy, options.max_rays_per_camera);
        if (options.time_culled_render) {
            const auto start = std::chrono::steady_clock::now();
            renderer.render(zone, row.camera, visible, RenderMode::Textured);
            row.render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        }
        rows.push_back(std::move(row));
        if (options.progress && !options.progress(i + 1, cameras.size()))
            break;
    }
    return rows;
}

} // namespace pvs::ui
