#include "visibility/raster/ray_cube.h"

#include <algorithm>
#include <limits>

namespace pvs {

RayCube::RayCube(const MeshTracer& tracer, const CubeRasterOptions& options, std::span<const uint8_t> translucent)
    : tracer_(tracer), options_(options), translucent_(translucent.begin(), translucent.end())
{
    const size_t pixels = size_t(options.resolution) * options.resolution;
    directions_.resize(pixels);
    hits_.resize(pixels);
    opaque_filter_.front_only = options.cull_back_faces;
    if (!translucent_.empty()) {
        opaque_.resize(translucent_.size());
        std::transform(translucent_.begin(), translucent_.end(), opaque_.begin(), [](uint8_t t) { return uint8_t(!t); });
        opaque_filter_.face_enabled = opaque_;
        translucent_filter_ = {translucent_, options.cull_back_faces};
        translucent_hits_.resize(pixels);
    }
}

void RayCube::render(const glm::vec3& eye, std::vector<uint8_t>& seen)
{
    const uint32_t r = options_.resolution;
    const bool filtered = options_.cull_back_faces || !translucent_.empty();
    const MeshTracer::FaceFilter* filter = filtered ? &opaque_filter_ : nullptr;
    for (int view = 0; view < 6; ++view) {
        // View `view` looks along +-axis; its picture spans the other two axes at distance 1.
        const int axis = view / 2;
        for (uint32_t y = 0; y < r; ++y)
            for (uint32_t x = 0; x < r; ++x) {
                glm::vec3& d = directions_[size_t(y) * r + x];
                d[axis] = view % 2 ? -1.0f : 1.0f;
                d[(axis + 1) % 3] = 2.0f * (float(x) + 0.5f) / float(r) - 1.0f;
                d[(axis + 2) % 3] = 2.0f * (float(y) + 0.5f) / float(r) - 1.0f;
            }
        tracer_.first_hits(eye, directions_, options_.near_distance, std::numeric_limits<float>::infinity(), hits_,
                           filter);
        for (const MeshTracer::Hit& hit : hits_)
            if (hit.hit && hit.face < seen.size())
                seen[hit.face] = 1;
        if (!translucent_.empty())
            see_translucent(eye, seen);
    }
}

// The translucent faces in front of each pixel's opaque hit (hits_), for the view in directions_:
// the first layer in packets, the layers behind it ray by ray (few pixels have any).
void RayCube::see_translucent(const glm::vec3& eye, std::vector<uint8_t>& seen)
{
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    tracer_.first_hits(eye, directions_, options_.near_distance, kInfinity, translucent_hits_, &translucent_filter_);
    for (size_t i = 0; i < directions_.size(); ++i) {
        const float wall = hits_[i].hit ? hits_[i].t : kInfinity;
        MeshTracer::Hit layer = translucent_hits_[i];
        float t = 0.0f; // where `layer`'s ray started, along directions_[i] from the eye
        for (int k = 0; k < kTranslucentLayers && layer.hit && t + layer.t < wall; ++k) {
            if (layer.face < seen.size())
                seen[layer.face] = 1;
            // Past this layer by a relative step: the same plane is not met again.
            t += layer.t + std::max(1e-4f, 1e-5f * (t + layer.t));
            layer = tracer_.first_hit(eye + directions_[i] * t, directions_[i], wall - t, translucent_filter_);
        }
    }
}

} // namespace pvs
