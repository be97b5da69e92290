#include "visibility/raster/ray_cube.h"

#include <limits>

namespace pvs {

RayCube::RayCube(const MeshTracer& tracer, const CubeRasterOptions& options) : tracer_(tracer), options_(options)
{
    const size_t pixels = size_t(options.resolution) * options.resolution;
    directions_.resize(pixels);
    hits_.resize(pixels);
}

void RayCube::render(const glm::vec3& eye, std::vector<uint8_t>& seen)
{
    const uint32_t r = options_.resolution;
    const MeshTracer::FaceFilter* filter = options_.cull_back_faces ? &front_only_ : nullptr;
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
    }
}

} // namespace pvs
