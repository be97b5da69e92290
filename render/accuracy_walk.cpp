#include "render/accuracy_walk.h"

#include "render/software_renderer.h"
#include "visibility/eval/sight_check.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <memory>

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

// The faces seen through translucent faces: at each pixel whose face (face_ids) is translucent,
// the face the picture without them shows there (-1 for none or the same face); -1 elsewhere.
std::vector<int32_t> faces_behind_translucent(const std::vector<int32_t>& face_ids, const Image& opaque_ids,
                                              const std::vector<uint8_t>& translucent)
{
    std::vector<int32_t> out(face_ids.size(), -1);
    for (uint32_t y = 0; y < opaque_ids.height; ++y)
        for (uint32_t x = 0; x < opaque_ids.width; ++x) {
            const size_t pixel = size_t(y) * opaque_ids.width + x;
            const int32_t front = face_ids[pixel];
            if (front < 0 || size_t(front) >= translucent.size() || !translucent[size_t(front)])
                continue;
            const uint32_t behind = face_at(opaque_ids, x, y);
            if (behind != kNoFace && int32_t(behind) != front)
                out[pixel] = int32_t(behind);
        }
    return out;
}

// The sight lines of one camera's pixels, traced on first demand and kept for the other PVSs:
// layer 0 to the face the pixel shows, layer 1 to the face seen through it (translucent faces).
class PixelSights {
public:
    PixelSights(const SightCheck& check, const Camera& camera, uint32_t width, uint32_t height)
        : check_(check), camera_(camera), width_(width), height_(height),
          inverse_(glm::inverse(glm::dmat4(camera.view_projection()))), cache_(2 * size_t(width) * height)
    {
    }
    const SightResult& at(uint32_t x, uint32_t y, uint32_t face, int layer)
    {
        Entry& entry = cache_[(size_t(layer) * height_ + y) * width_ + x];
        if (!entry.done) {
            entry.result = check_.face_along_ray(glm::dvec3(camera_.position), pixel_direction(x, y), face, scratch_);
            entry.done = true;
        }
        return entry.result;
    }

private:
    // The unit direction from the camera through the centre of pixel (x, y), rows top to bottom.
    glm::dvec3 pixel_direction(uint32_t x, uint32_t y) const
    {
        const double nx = 2.0 * (double(x) + 0.5) / double(width_) - 1.0;
        const double ny = 1.0 - 2.0 * (double(y) + 0.5) / double(height_);
        glm::dvec4 near_point = inverse_ * glm::dvec4(nx, ny, -1.0, 1.0);
        glm::dvec4 far_point = inverse_ * glm::dvec4(nx, ny, 1.0, 1.0);
        near_point /= near_point.w;
        far_point /= far_point.w;
        return glm::normalize(glm::dvec3(far_point) - glm::dvec3(near_point));
    }

    struct Entry {
        SightResult result;
        bool done = false;
    };
    const SightCheck& check_;
    Camera camera_;
    uint32_t width_, height_;
    glm::dmat4 inverse_;
    std::vector<Entry> cache_;
    TreeTracer::Scratch scratch_;
};

// Splits the raster popping pixels into confirmed, unlisted, grazing, unfaced, cracks and unknown. A
// pixel pops by the face it shows, else by the face seen through it (`behind`, may be empty).
void confirm_popping(const FaceRegions& face_regions, uint32_t width, const std::vector<int32_t>& face_ids,
                     const std::vector<int32_t>& behind, const std::vector<uint8_t>& region_drawn,
                     PixelSights& sights, WalkRow& row)
{
    if (row.accuracy.popping_pixels == 0)
        return;
    auto drawn = [&](uint32_t face) {
        for (uint32_t r : face_regions.of(face))
            if (region_drawn[r])
                return true;
        return false;
    };
    const size_t faces = face_regions.offsets.size() - 1;
    const auto popped = [&](int32_t face) { return face >= 0 && size_t(face) < faces && !drawn(uint32_t(face)); };
    for (size_t pixel = 0; pixel < face_ids.size(); ++pixel) {
        const uint32_t x = uint32_t(pixel % width), y = uint32_t(pixel / width);
        int layer = 0;
        int32_t face = face_ids[pixel];
        if (!popped(face)) {
            if (face < 0 || pixel >= behind.size() || !popped(behind[pixel]))
                continue;
            layer = 1;
            face = behind[pixel];
        }
        const SightResult& sight = sights.at(x, y, uint32_t(face), layer);
        if (sight.sight == Sight::Grazing) {
            ++row.popping_grazing;
            continue;
        }
        if (sight.sight == Sight::Unfaced) {
            ++row.popping_unfaced;
            continue;
        }
        if (sight.sight == Sight::Unknown) {
            ++row.popping_unknown;
            continue;
        }
        if (sight.sight != Sight::Open) {
            ++row.popping_cracks;
            continue;
        }
        if (sight.end_region >= 0 && size_t(sight.end_region) < region_drawn.size() &&
            region_drawn[size_t(sight.end_region)]) {
            ++row.popping_unlisted; // the line ends in a kept region: the face's list, not the PVS
            continue;
        }
        ++row.popping_confirmed;
        if (sight.end_region >= 0)
            row.confirmed_regions.push_back(uint32_t(sight.end_region));
    }
    std::sort(row.confirmed_regions.begin(), row.confirmed_regions.end());
    row.confirmed_regions.erase(std::unique(row.confirmed_regions.begin(), row.confirmed_regions.end()),
                                row.confirmed_regions.end());
}

} // namespace

std::vector<std::vector<WalkRow>> run_accuracy_walks(const Zone& zone, std::span<const Pvs* const> pvss,
                                                     std::span<const Camera> cameras, const WalkOptions& options)
{
    SoftwareRenderer renderer(options.width, options.height);
    std::vector<std::unique_ptr<Culler>> cullers;
    for (const Pvs* pvs : pvss)
        cullers.push_back(std::make_unique<Culler>(zone, pvs));
    const FaceRegions face_regions = build_face_regions(zone);
    const SightCheck sight_check(zone, options.sky);
    // Zones with translucent faces get a second ID picture without them: the faces seen through.
    const std::vector<uint8_t> translucent = translucent_face_mask(zone);
    const bool any_translucent = !translucent.empty(); // translucent_face_mask: empty when none is
    std::vector<uint32_t> all_regions(zone.region_count());
    for (uint32_t r = 0; r < all_regions.size(); ++r)
        all_regions[r] = r;

    std::vector<std::vector<WalkRow>> rows(pvss.size());
    for (auto& list : rows)
        list.reserve(cameras.size());
    std::vector<uint32_t> visible;
    std::vector<uint8_t> region_drawn(zone.region_count(), 0);
    for (size_t i = 0; i < cameras.size(); ++i) {
        Camera camera = cameras[i];
        camera.aspect = float(options.width) / float(options.height);
        const Image ids = renderer.render(zone, camera, all_regions, RenderMode::IdBuffer);
        const std::vector<int32_t> face_ids = face_ids_of(ids);
        const std::vector<int32_t> behind =
            any_translucent ? faces_behind_translucent(face_ids, renderer.render_ids_behind_translucent(zone, camera, all_regions),
                                                       translucent)
                            : std::vector<int32_t>{};
        PixelSights sights(sight_check, camera, options.width, options.height);
        for (size_t p = 0; p < pvss.size(); ++p) {
            WalkRow row;
            row.camera = camera;
            CullOptions cull_options{options.mode, true};
            cull_options.distance_stage = options.distance_stage;
            if (i < options.forced_regions.size())
                cull_options.forced_region = options.forced_regions[i];
            row.cull = cullers[p]->cull(camera, cull_options, visible);
            row.accuracy = measure_image_accuracy(zone, face_regions, face_ids, visible, behind);
            std::fill(region_drawn.begin(), region_drawn.end(), 0);
            for (uint32_t r : visible)
                region_drawn[r] = 1;
            confirm_popping(face_regions, options.width, face_ids, behind, region_drawn, sights, row);
            if (options.time_culled_render) {
                const auto start = std::chrono::steady_clock::now();
                renderer.render(zone, camera, visible, RenderMode::Textured);
                row.render_ms =
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            }
            rows[p].push_back(std::move(row));
        }
        if (options.progress && !options.progress(i + 1, cameras.size()))
            break;
    }
    return rows;
}

std::vector<WalkRow> run_accuracy_walk(const Zone& zone, const Pvs* pvs, std::span<const Camera> cameras,
                                       const WalkOptions& options)
{
    const Pvs* one[] = {pvs};
    return std::move(run_accuracy_walks(zone, one, cameras, options).front());
}

} // namespace pvs::ui
